// Reading a render program's artifacts as hostile input (see read_artifacts in checkpoint.h).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <sstream>
#include <vector>

#include "harness/checkpoint.h"
#include "raster/io.h"

namespace cp {

namespace {

class Fd {
public:
    explicit Fd(int fd) : fd_(fd) {}
    ~Fd() {
        if (fd_ >= 0) ::close(fd_);
    }
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

// The bytes of `name` inside the directory `dir_fd`, or nothing when there is no such entry.
std::optional<std::vector<unsigned char>> read_plain_file(int dir_fd, const std::string& name, std::size_t cap) {
    // O_NOFOLLOW: a symbolic link fails with ELOOP; O_NONBLOCK: opening a FIFO does not wait for
    // a writer (it is then refused as not a plain file).
    const Fd fd(::openat(dir_fd, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
    if (fd.get() < 0) {
        if (errno == ENOENT) return std::nullopt;
        if (errno == ELOOP) throw ArtifactError(name + " is a symbolic link");
        throw ArtifactError(name + " cannot be opened: " + std::strerror(errno));
    }
    struct stat st {};
    if (::fstat(fd.get(), &st) != 0) throw ArtifactError(name + " cannot be examined: " + std::strerror(errno));
    if (!S_ISREG(st.st_mode)) throw ArtifactError(name + " is not a plain file");
    if (static_cast<std::size_t>(st.st_size) > cap) {
        throw ArtifactError(name + " is " + std::to_string(st.st_size) + " bytes, more than the " +
                            std::to_string(cap) + " allowed");
    }
    std::vector<unsigned char> bytes;
    bytes.reserve(static_cast<std::size_t>(st.st_size));
    unsigned char buf[1 << 16];
    while (true) {
        const ssize_t n = ::read(fd.get(), buf, sizeof buf);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw ArtifactError(name + " cannot be read: " + std::strerror(errno));
        }
        if (n == 0) break;
        if (bytes.size() + static_cast<std::size_t>(n) > cap) throw ArtifactError(name + " grew past its size cap");
        bytes.insert(bytes.end(), buf, buf + n);
    }
    return bytes;
}

long long to_count(const std::string& word) {
    char* end = nullptr;
    const long long v = std::strtoll(word.c_str(), &end, 10);
    return end == word.c_str() ? 0 : v;
}

}  // namespace

Artifacts read_artifacts(const std::string& dir, const ArtifactRules& rules) {
    const Fd dir_fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
    if (dir_fd.get() < 0) throw ArtifactError("the artifacts folder cannot be opened: " + std::string(std::strerror(errno)));
    Artifacts a;
    const auto values = read_plain_file(dir_fd.get(), "values.txt", std::min<std::size_t>(rules.max_file_bytes, 4u << 20));
    if (!values) throw ArtifactError("the render wrote no values.txt (it did not finish)");
    // Line by line, numbers through strtod: a student's code may well produce NaN or
    // infinity, which operator>> refuses (and would end the reading there).
    std::istringstream in(std::string(values->begin(), values->end()));
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string key, name, number;
        words >> key;
        if (key == "trace") {
            std::string calls, writes, strays;
            words >> name >> calls >> writes >> strays;
            if (name.empty()) continue;
            a.trace[name] = FunctionTrace{to_count(calls), to_count(writes), to_count(strays)};
            continue;
        }
        if (key == "stopped") {
            StoppedCall& s = a.stopped_call;
            std::string call, writes, strays;
            words >> s.function >> call >> writes >> strays >> number;
            if (s.function == "-") s.function.clear();
            s.call = to_count(call);
            s.writes = to_count(writes);
            s.stray_writes = to_count(strays);
            s.seconds = std::strtod(number.c_str(), nullptr);
            a.stopped = true;
            continue;
        }
        if (key == "value") words >> name;
        words >> number;
        const double v = std::strtod(number.c_str(), nullptr);
        if (key == "seconds") {
            a.seconds = v;
        } else if (key == "stray_writes") {
            a.stray_writes = to_count(number);
        } else if (key == "value" && !name.empty()) {
            a.values[name] = v;
        }
    }
    for (const auto& [name, size] : rules.images) {
        const std::string file = name + ".png";
        const auto bytes = read_plain_file(dir_fd.get(), file, rules.max_file_bytes);
        if (!bytes) continue;
        try {
            a.images[name] = raster::decode_png(bytes->data(), bytes->size(), file, size.first, size.second);
        } catch (const raster::ImageIoError& e) {
            throw ArtifactError(e.what());
        }
    }
    return a;
}

ArtifactRules rules_from_reference(const Artifacts& reference) {
    ArtifactRules r;
    for (const auto& [name, img] : reference.images) r.images[name] = {img.width(), img.height()};
    const auto main = reference.images.find("main");
    if (main != reference.images.end()) r.images["stopped"] = {main->second.width(), main->second.height()};
    return r;
}

}  // namespace cp
