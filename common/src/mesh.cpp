// OBJ loading (tinyobjloader does the parsing; this file checks the input before and the
// result after), mesh checks and the generated meshes. Conventions: raster/mesh.h.
#include "raster/mesh.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <string_view>

namespace raster {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& source, const std::string& reason) {
    throw MeshError(source + ": " + reason);
}

[[noreturn]] void fail_line(const std::string& source, long long line, const std::string& reason) {
    throw MeshError(source + ":" + std::to_string(line) + ": " + reason);
}

std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

// A whole word as a real number, like the file's author meant it ("+1" allowed).
bool parse_real(std::string_view word, double& out) {
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    if (word.empty()) return false;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), out);
    return ec == std::errc() && end == word.data() + word.size();
}

// A whole word as an int; false for anything else, including values that do not fit.
bool parse_int(std::string_view word, int& out) {
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    if (word.empty()) return false;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), out);
    return ec == std::errc() && end == word.data() + word.size();
}

struct Counts {
    long long v = 0, vt = 0, vn = 0;
};

struct PendingIndex {
    long long line;
    const char* kind;  // "position", "texture coordinate", "normal"
    int index;         // as written, positive
};

// Checks what tinyobjloader would accept silently or read wrongly: unparsable or non-finite
// numbers (it reads them as 0), missing coordinates (truncated lines), indices that overflow
// an int (it wraps them), zero and out-of-range indices, faces with fewer than 3 corners
// (it drops them with a warning).
void precheck(const std::string& text, const std::string& source) {
    Counts counts;
    std::vector<PendingIndex> forward;  // positive indices, checked against the final counts
    long long line_no = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + pos, end - pos);
        pos = end + 1;
        ++line_no;
        if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.find('\0') != std::string_view::npos) {
            fail_line(source, line_no, "contains a NUL byte: not a text OBJ file");
        }
        const auto words = split_words(line);
        if (words.empty()) continue;
        const std::string_view key = words[0];
        if (key == "v" || key == "vn" || key == "vt") {
            const std::size_t need = key == "vt" ? 1 : 3;
            if (words.size() - 1 < need) {
                fail_line(source, line_no,
                          "`" + std::string(key) + "` needs " + std::to_string(need) +
                              " numbers, found " + std::to_string(words.size() - 1) +
                              " (truncated file?)");
            }
            for (std::size_t i = 1; i < words.size(); ++i) {
                double value = 0;
                if (!parse_real(words[i], value)) {
                    fail_line(source, line_no, "`" + std::string(words[i]) + "` is not a number");
                }
                if (!std::isfinite(value)) {
                    fail_line(source, line_no,
                              "coordinate `" + std::string(words[i]) + "` is not a finite number");
                }
            }
            if (key == "v") {
                if (++counts.v > kMaxMeshVertices) {
                    fail_line(source, line_no,
                              "more than " + std::to_string(kMaxMeshVertices) + " vertices");
                }
            } else if (key == "vn") {
                ++counts.vn;
            } else {
                ++counts.vt;
            }
        } else if (key == "f") {
            if (words.size() - 1 < 3) {
                fail_line(source, line_no,
                          "a face needs at least 3 vertices, found " +
                              std::to_string(words.size() - 1));
            }
            for (std::size_t i = 1; i < words.size(); ++i) {
                // v, v/vt, v//vn or v/vt/vn
                const std::string_view corner = words[i];
                std::string_view parts[3];
                int nparts = 0;
                std::size_t start = 0;
                while (true) {
                    const std::size_t slash = corner.find('/', start);
                    if (nparts == 3) fail_line(source, line_no, "bad face corner `" + std::string(corner) + "`");
                    parts[nparts++] = corner.substr(start, slash == std::string_view::npos ? slash : slash - start);
                    if (slash == std::string_view::npos) break;
                    start = slash + 1;
                }
                static const char* const kinds[3] = {"position", "texture coordinate", "normal"};
                const long long available[3] = {counts.v, counts.vt, counts.vn};
                for (int k = 0; k < nparts; ++k) {
                    if (k > 0 && parts[k].empty()) continue;  // v//vn, v/vt/
                    int index = 0;
                    if (!parse_int(parts[k], index)) {
                        fail_line(source, line_no,
                                  "face corner `" + std::string(corner) + "`: `" +
                                      std::string(parts[k]) + "` is not a " + kinds[k] +
                                      " index (or does not fit in an int)");
                    }
                    if (index == 0) {
                        fail_line(source, line_no,
                                  "face corner `" + std::string(corner) +
                                      "`: index 0 (OBJ indices start at 1)");
                    }
                    if (index < 0 && -static_cast<long long>(index) > available[k]) {
                        fail_line(source, line_no,
                                  "face corner `" + std::string(corner) + "`: relative " +
                                      kinds[k] + " index " + std::to_string(index) + " but only " +
                                      std::to_string(available[k]) + " defined so far");
                    }
                    if (index > 0) forward.push_back({line_no, kinds[k], index});
                }
            }
        }
    }
    for (const PendingIndex& p : forward) {
        const std::string kind = p.kind;
        const long long available =
            kind == "position" ? counts.v : kind == "normal" ? counts.vn : counts.vt;
        if (p.index > available) {
            fail_line(source, p.line,
                      kind + " index " + std::to_string(p.index) + " but the file has only " +
                          std::to_string(available) + " " + kind + "s");
        }
    }
}

std::vector<std::array<int, 3>> fan(const std::vector<std::vector<int>>& faces) {
    std::vector<std::array<int, 3>> tris;
    for (const auto& f : faces) {
        for (std::size_t i = 1; i + 1 < f.size(); ++i) tris.push_back({f[0], f[i], f[i + 1]});
    }
    return tris;
}

Mesh parse(const std::string& text, const std::string& source) {
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) fail(source, "empty file");
    precheck(text, source);

    tinyobj::ObjReaderConfig config;
    config.triangulate = false;  // the fan is ours, after the indices are checked
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, "", config)) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == '.')) why.pop_back();
        fail(source, "tinyobjloader: " + (why.empty() ? std::string("cannot parse") : why));
    }
    if (reader.Warning().find("Degenerated face") != std::string::npos) {
        fail(source, "a face with fewer than 3 vertices");
    }

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    Mesh mesh;
    const std::size_t nv = attrib.vertices.size() / 3;
    mesh.positions.reserve(nv);
    for (std::size_t i = 0; i < nv; ++i) {
        mesh.positions.push_back({static_cast<double>(attrib.vertices[3 * i]),
                                  static_cast<double>(attrib.vertices[3 * i + 1]),
                                  static_cast<double>(attrib.vertices[3 * i + 2])});
    }
    const std::size_t nn = attrib.normals.size() / 3;

    bool every_corner_has_normal = true;
    std::vector<std::set<int>> corner_normals(nv);
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& fv = shape.mesh.num_face_vertices;
        const auto& idx = shape.mesh.indices;
        std::size_t offset = 0;
        for (const auto count : fv) {
            if (offset + count > idx.size()) fail(source, "tinyobjloader returned a short index list");
            std::vector<int> face;
            face.reserve(count);
            for (std::size_t k = 0; k < count; ++k) {
                const tinyobj::index_t& c = idx[offset + k];
                if (c.vertex_index < 0 || static_cast<std::size_t>(c.vertex_index) >= nv) {
                    fail(source, "position index " + std::to_string(c.vertex_index + 1) +
                                     " out of range 1.." + std::to_string(nv));
                }
                if (c.normal_index < 0) {
                    every_corner_has_normal = false;
                } else if (static_cast<std::size_t>(c.normal_index) >= nn) {
                    fail(source, "normal index " + std::to_string(c.normal_index + 1) +
                                     " out of range 1.." + std::to_string(nn));
                } else {
                    corner_normals[static_cast<std::size_t>(c.vertex_index)].insert(c.normal_index);
                }
                face.push_back(c.vertex_index);
            }
            offset += count;
            mesh.faces.push_back(std::move(face));
        }
    }
    if (mesh.faces.empty()) fail(source, "no faces (an OBJ mesh needs `f` lines)");

    if (every_corner_has_normal && nn > 0) {
        mesh.normals.assign(nv, Vec3{});
        for (std::size_t i = 0; i < nv; ++i) {
            Vec3 sum{};
            for (int n : corner_normals[i]) {
                const auto j = static_cast<std::size_t>(n);
                sum = sum + Vec3{static_cast<double>(attrib.normals[3 * j]),
                                 static_cast<double>(attrib.normals[3 * j + 1]),
                                 static_cast<double>(attrib.normals[3 * j + 2])};
            }
            mesh.normals[i] = normalize(sum);
        }
    }
    mesh.triangles = fan(mesh.faces);
    try {
        check_mesh(mesh);
    } catch (const MeshError& e) {
        fail(source, e.what());
    }
    return mesh;
}

std::string format_real(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v == 0 ? 0.0 : v);  // no "-0"
    return buf;
}

void require(bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument(what);
}

}  // namespace

Mesh load_obj(const std::string& path) {
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec || !fs::exists(st)) fail(path, "no such file");
    if (fs::is_directory(st)) fail(path, "is a directory, not an OBJ file");
    if (!fs::is_regular_file(st)) fail(path, "not a regular file (a device or pipe?)");
    const auto size = fs::file_size(path, ec);
    if (ec) fail(path, "cannot read its size: " + ec.message());
    if (size > static_cast<std::uintmax_t>(kMaxObjBytes)) {
        fail(path, "larger than " + std::to_string(kMaxObjBytes) + " bytes");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot open for reading");
    std::string text(static_cast<std::size_t>(size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    if (static_cast<std::uintmax_t>(in.gcount()) != size) fail(path, "read error");
    return parse(text, path);
}

Mesh load_obj_string(const std::string& text) {
    if (text.size() > static_cast<std::size_t>(kMaxObjBytes)) {
        fail("<OBJ text>", "larger than " + std::to_string(kMaxObjBytes) + " bytes");
    }
    return parse(text, "<OBJ text>");
}

std::string to_obj(const Mesh& mesh, const std::string& comment) {
    std::ostringstream out;
    if (!comment.empty()) {
        std::istringstream lines(comment);
        std::string line;
        while (std::getline(lines, line)) out << (line.empty() ? "#" : "# " + line) << '\n';
    }
    for (const Vec3& p : mesh.positions) {
        out << "v " << format_real(p.x) << ' ' << format_real(p.y) << ' ' << format_real(p.z) << '\n';
    }
    const bool with_normals = !mesh.normals.empty();
    for (const Vec3& n : mesh.normals) {
        out << "vn " << format_real(n.x) << ' ' << format_real(n.y) << ' ' << format_real(n.z) << '\n';
    }
    for (const auto& f : mesh.faces) {
        out << 'f';
        for (int i : f) {
            out << ' ' << i + 1;
            if (with_normals) out << "//" << i + 1;
        }
        out << '\n';
    }
    return out.str();
}

void write_obj(const std::string& path, const Mesh& mesh, const std::string& comment) {
    const std::string text = to_obj(mesh, comment);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) fail(path, "cannot open for writing");
    out << text;
    out.close();
    if (!out) fail(path, "write error");
}

void check_mesh(const Mesh& mesh) {
    if (mesh.positions.size() > static_cast<std::size_t>(kMaxMeshVertices)) {
        throw MeshError("more than " + std::to_string(kMaxMeshVertices) + " positions");
    }
    const auto n = static_cast<long long>(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        if (!is_finite(mesh.positions[i])) {
            throw MeshError("position " + std::to_string(i) + " is not finite");
        }
    }
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
        if (face.size() < 3) {
            throw MeshError("face " + std::to_string(f) + " has " + std::to_string(face.size()) +
                            " vertices; a face needs at least 3");
        }
        for (int i : face) {
            if (i < 0 || i >= n) {
                throw MeshError("face " + std::to_string(f) + " uses vertex " + std::to_string(i) +
                                ", outside 0.." + std::to_string(n - 1));
            }
        }
        std::vector<int> sorted = face;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
            throw MeshError("face " + std::to_string(f) + " uses a vertex twice");
        }
    }
    if (mesh.triangles != fan(mesh.faces)) {
        throw MeshError("triangles are not the fan triangulation of the faces");
    }
    if (!mesh.normals.empty()) {
        if (mesh.normals.size() != mesh.positions.size()) {
            throw MeshError("normals: " + std::to_string(mesh.normals.size()) + " for " +
                            std::to_string(n) + " positions");
        }
        for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
            if (!is_finite(mesh.normals[i])) {
                throw MeshError("normal " + std::to_string(i) + " is not finite");
            }
        }
    }
}

std::vector<std::array<int, 2>> unique_edges(const Mesh& mesh) {
    std::vector<std::array<int, 2>> edges;
    for (const auto& f : mesh.faces) {
        for (std::size_t i = 0; i < f.size(); ++i) {
            const int a = f[i], b = f[(i + 1) % f.size()];
            if (a != b) edges.push_back({std::min(a, b), std::max(a, b)});
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

double signed_volume(const Mesh& mesh) {
    double six_v = 0;
    for (const auto& t : mesh.triangles) {
        const Vec3 a = mesh.positions[static_cast<std::size_t>(t[0])];
        const Vec3 b = mesh.positions[static_cast<std::size_t>(t[1])];
        const Vec3 c = mesh.positions[static_cast<std::size_t>(t[2])];
        six_v += dot(a, cross(b, c));
    }
    return six_v / 6;
}

Vec3 face_normal(const Mesh& mesh, int face) {
    const auto& f = mesh.faces.at(static_cast<std::size_t>(face));
    Vec3 n{};
    for (std::size_t i = 0; i < f.size(); ++i) {
        const Vec3 a = mesh.positions.at(static_cast<std::size_t>(f[i]));
        const Vec3 b = mesh.positions.at(static_cast<std::size_t>(f[(i + 1) % f.size()]));
        n = n + Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    }
    return normalize(n);
}

std::string model_path(const std::string& name) {
    if (name.empty() || name.size() > 64 ||
        !std::all_of(name.begin(), name.end(), [](char c) {
            return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                   c == '_';
        })) {
        throw MeshError("model name `" + name + "`: use letters, digits and '_' only");
    }
    const char* env = std::getenv("RASTER_MODELS_DIR");
    const fs::path dir = env != nullptr && *env != '\0' ? fs::path(env) : fs::path(RASTER_MODELS_DIR);
    return fs::absolute(dir / (name + ".obj")).lexically_normal().string();
}

std::vector<std::string> model_names() { return {"cube", "octahedron", "pyramid", "soccer_ball"}; }

Mesh make_uv_sphere(int stacks, int slices, double radius) {
    require(stacks >= 2 && slices >= 3, "make_uv_sphere: needs stacks >= 2 and slices >= 3");
    require(static_cast<long long>(stacks) * slices <= 1'000'000,
            "make_uv_sphere: stacks * slices > 1,000,000");
    require(std::isfinite(radius) && radius > 0, "make_uv_sphere: radius must be finite and > 0");
    const double pi = std::numbers::pi;
    Mesh m;
    // Azimuth phi turns counter-clockwise seen from +y: (cos phi, -sin phi) in (x, z).
    auto add = [&](Vec3 unit) {
        m.positions.push_back(unit * radius);
        m.normals.push_back(unit);
    };
    add({0, 1, 0});
    for (int i = 1; i < stacks; ++i) {
        const double theta = pi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2 * pi * j / slices;
            add({std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)});
        }
    }
    add({0, -1, 0});
    const int south = static_cast<int>(m.positions.size()) - 1;
    auto ring = [&](int i, int j) { return 1 + (i - 1) * slices + (j % slices); };  // i in 1..stacks-1
    for (int j = 0; j < slices; ++j) m.faces.push_back({0, ring(1, j), ring(1, j + 1)});
    for (int i = 1; i + 1 < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            m.faces.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
    }
    for (int j = 0; j < slices; ++j) m.faces.push_back({ring(stacks - 1, j), south, ring(stacks - 1, j + 1)});
    m.triangles = fan(m.faces);
    check_mesh(m);
    return m;
}

Mesh make_torus(double major, double minor, int rings, int sides) {
    require(rings >= 3 && sides >= 3, "make_torus: needs rings >= 3 and sides >= 3");
    require(static_cast<long long>(rings) * sides <= 1'000'000, "make_torus: rings * sides > 1,000,000");
    require(std::isfinite(major) && std::isfinite(minor) && minor > 0 && minor < major,
            "make_torus: needs finite 0 < minor < major");
    const double pi = std::numbers::pi;
    Mesh m;
    for (int i = 0; i < rings; ++i) {
        const double u = 2 * pi * i / rings;
        const Vec3 radial{std::cos(u), 0, -std::sin(u)};
        for (int j = 0; j < sides; ++j) {
            const double v = 2 * pi * j / sides;
            const Vec3 normal = radial * std::cos(v) + Vec3{0, 1, 0} * std::sin(v);
            m.positions.push_back(radial * major + normal * minor);
            m.normals.push_back(normal);
        }
    }
    auto at = [&](int i, int j) { return (i % rings) * sides + (j % sides); };
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < sides; ++j) {
            m.faces.push_back({at(i, j + 1), at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        }
    }
    m.triangles = fan(m.faces);
    check_mesh(m);
    return m;
}

Mesh make_convex_polyhedron(const std::vector<Vec3>& points) {
    require(points.size() >= 4 && points.size() <= 1000,
            "make_convex_polyhedron: needs 4 to 1000 points");
    double scale = 0;
    for (const Vec3& p : points) {
        require(is_finite(p), "make_convex_polyhedron: points must be finite");
        scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    require(scale > 0, "make_convex_polyhedron: all points at the origin");
    const double eps = 1e-9 * scale;
    const int n = static_cast<int>(points.size());
    std::set<std::vector<int>> seen;
    std::vector<std::vector<int>> faces;
    for (int i = 0; i < n; ++i) {
        for (int j = i + 1; j < n; ++j) {
            for (int k = j + 1; k < n; ++k) {
                const Vec3 a = points[static_cast<std::size_t>(i)];
                Vec3 normal = cross(points[static_cast<std::size_t>(j)] - a,
                                    points[static_cast<std::size_t>(k)] - a);
                if (length(normal) <= eps * scale) continue;  // (nearly) collinear
                normal = normalize(normal);
                const double d = dot(normal, a);
                bool above = false, below = false;
                std::vector<int> on_plane;
                for (int q = 0; q < n; ++q) {
                    const double s = dot(normal, points[static_cast<std::size_t>(q)]) - d;
                    if (s > eps) above = true;
                    else if (s < -eps) below = true;
                    else on_plane.push_back(q);
                    if (above && below) break;
                }
                if (above && below) continue;
                if (!above && !below) {
                    throw std::invalid_argument("make_convex_polyhedron: all points are coplanar");
                }
                if (!seen.insert(on_plane).second) continue;
                if (above) normal = -normal;  // outward: every point is behind the plane
                Vec3 center{};
                for (int q : on_plane) center = center + points[static_cast<std::size_t>(q)];
                center = center / static_cast<double>(on_plane.size());
                const Vec3 u = normalize(points[static_cast<std::size_t>(on_plane[0])] - center);
                const Vec3 w = cross(normal, u);  // (u, w, normal) is right-handed
                std::vector<std::pair<double, int>> by_angle;
                for (int q : on_plane) {
                    const Vec3 r = points[static_cast<std::size_t>(q)] - center;
                    by_angle.push_back({std::atan2(dot(r, w), dot(r, u)), q});
                }
                std::sort(by_angle.begin(), by_angle.end());
                std::vector<int> face;
                for (const auto& [angle, q] : by_angle) face.push_back(q);
                std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
                faces.push_back(std::move(face));
            }
        }
    }
    std::sort(faces.begin(), faces.end());
    Mesh m;
    m.positions = points;
    m.faces = std::move(faces);
    m.triangles = fan(m.faces);
    check_mesh(m);
    return m;
}

Mesh make_cube() {
    return make_convex_polyhedron({{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}});
}

Mesh make_octahedron() {
    return make_convex_polyhedron({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}});
}

Mesh make_square_pyramid() {
    return make_convex_polyhedron({{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}, {0, 1, 0}});
}

Mesh make_truncated_icosahedron() {
    // Cyclic permutations of (0, +-1, +-3 phi), (+-1, +-(2 + phi), +-2 phi) and
    // (+-phi, +-2, +-(2 phi + 1)): edge length 2, circumradius sqrt(9 phi + 10).
    const double phi = std::numbers::phi;
    const double scale = 1 / std::sqrt(9 * phi + 10);
    const Vec3 bases[3] = {{0, 1, 3 * phi}, {1, 2 + phi, 2 * phi}, {phi, 2, 2 * phi + 1}};
    std::vector<Vec3> points;
    for (const Vec3& base : bases) {
        for (int rot = 0; rot < 3; ++rot) {
            for (int signs = 0; signs < 8; ++signs) {
                Vec3 p{signs & 1 ? -base.x : base.x, signs & 2 ? -base.y : base.y,
                       signs & 4 ? -base.z : base.z};
                if ((base.x == 0 && (signs & 1)) || (base.y == 0 && (signs & 2)) ||
                    (base.z == 0 && (signs & 4))) {
                    continue;  // -0 is the same point as 0
                }
                for (int r = 0; r < rot; ++r) p = {p.z, p.x, p.y};
                points.push_back(p * scale);
            }
        }
    }
    return make_convex_polyhedron(points);
}

}  // namespace raster
