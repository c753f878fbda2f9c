#include "harness/record.h"

#include "harness/checkpoint.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>

namespace fs = std::filesystem;

namespace cp {

namespace {

// Text values never contain tabs or newlines (ids, titles, concept tags, findings and hints
// are the checkpoints' own words), so a "key<TAB>value" line format is enough and keeps the
// files readable by eye.
void put_metrics(std::ostream& out, const std::string& prefix, const raster::ImageMetrics& m) {
    out << prefix << "differing_pixels\t" << m.differing_pixels << "\n"
        << prefix << "differing_share\t" << m.differing_share << "\n"
        << prefix << "max_channel_diff\t" << m.max_channel_diff << "\n"
        << prefix << "mean_abs_error\t" << m.mean_abs_error << "\n"
        << prefix << "psnr_db\t" << m.psnr_db << "\n";
}

void get_metric(raster::ImageMetrics& m, const std::string& key, const std::string& v) {
    if (key == "differing_pixels") m.differing_pixels = std::stoll(v);
    if (key == "differing_share") m.differing_share = std::stod(v);
    if (key == "max_channel_diff") m.max_channel_diff = std::stoi(v);
    if (key == "mean_abs_error") m.mean_abs_error = std::stod(v);
    if (key == "psnr_db") {
        m.psnr_db = v == "inf" ? std::numeric_limits<double>::infinity() : std::stod(v);
    }
}

}  // namespace

void write_record(const Record& r) {
    const fs::path dir = env_or("RASTER_RESULTS_DIR", "checkpoint_results");
    fs::create_directories(dir);
    std::ofstream out(dir / (r.id + ".txt"));
    out << std::setprecision(10);
    out << "id\t" << r.id << "\nmilestone\t" << r.milestone << "\norder\t" << r.order << "\ntitle\t" << r.title
        << "\nstatus\t" << r.status << "\nconcepts\t" << r.concepts << "\nhas_metrics\t"
        << r.has_metrics << "\nnumbers_only\t" << r.numbers_only << "\nstudent_ms\t" << r.student_ms << "\nreference_ms\t"
        << r.reference_ms << "\noutput_dir\t" << r.output_dir << "\n";
    put_metrics(out, "student.", r.student);
    put_metrics(out, "reference.", r.reference);
    for (const auto& [name, v] : r.measures) out << "measure." << name << "\t" << v << "\n";
    for (const std::string& f : r.findings) out << "finding\t" << f << "\n";
    if (!r.hint.empty()) out << "hint\t" << r.hint << "\n";
    if (!r.diagnosis.empty()) out << "diagnosis\t" << r.diagnosis << "\n";
    if (!r.todos.empty()) out << "todos\t" << r.todos << "\n";
    if (r.counts_only) out << "counts_only\t1\n";
    if (r.tolerated > 0) out << "tolerated\t" << r.tolerated << "\ntolerated_why\t" << r.tolerated_why << "\n";
}

std::vector<Record> read_records(const std::string& dir) {
    std::vector<Record> records;
    if (!fs::is_directory(dir)) return records;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".txt") continue;
        std::ifstream in(entry.path());
        Record r;
        std::string line;
        while (std::getline(in, line)) {
            const auto tab = line.find('\t');
            if (tab == std::string::npos) continue;
            const std::string key = line.substr(0, tab), v = line.substr(tab + 1);
            if (key == "id") r.id = v;
            else if (key == "milestone") r.milestone = v;
            else if (key == "order") r.order = std::stoi(v);
            else if (key == "title") r.title = v;
            else if (key == "status") r.status = v;
            else if (key == "concepts") r.concepts = v;
            else if (key == "has_metrics") r.has_metrics = v == "1";
            else if (key == "numbers_only") r.numbers_only = v == "1";
            else if (key == "student_ms") r.student_ms = std::stod(v);
            else if (key == "reference_ms") r.reference_ms = std::stod(v);
            else if (key == "output_dir") r.output_dir = v;
            else if (key.rfind("student.", 0) == 0) get_metric(r.student, key.substr(8), v);
            else if (key.rfind("reference.", 0) == 0) get_metric(r.reference, key.substr(10), v);
            else if (key.rfind("measure.", 0) == 0) r.measures[key.substr(8)] = std::stod(v);
            else if (key == "finding") r.findings.push_back(v);
            else if (key == "hint") r.hint = v;
            else if (key == "diagnosis") r.diagnosis = v;
            else if (key == "todos") r.todos = v;
            else if (key == "counts_only") r.counts_only = v == "1";
            else if (key == "tolerated") r.tolerated = std::stoll(v);
            else if (key == "tolerated_why") r.tolerated_why = v;
        }
        if (!r.id.empty()) records.push_back(r);
    }
    std::sort(records.begin(), records.end(), [](const Record& a, const Record& b) {
        return a.milestone != b.milestone ? a.milestone < b.milestone : a.order < b.order;
    });
    return records;
}

}  // namespace cp
