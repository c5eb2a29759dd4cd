// pf_ply_check — reads a particle PLY file back the way a DCC tool would, independently of the
// writer (samples/common/ply_write.cpp), and checks it: a standard header (ply, format
// binary_little_endian 1.0 or ascii 1.0, one vertex element with the float properties
// x y z vx vy vz in that order, end_header), the vertex count, exactly that much data, every
// value finite and every position inside the domain. pf_headless --export-ply's test runs it.
//
// usage: pf_ply_check FILE COUNT CELL NX NY NZ [OX OY OZ]
//   the domain is a grid of NX x NY x NZ cells of CELL metres from the corner O (default 0),
//   given as the scene file does.
// Exit status 0 when the file passes; otherwise 1 with the reason on stderr.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Header {
    bool binary = false;
    uint64_t vertices = 0;
    std::vector<std::string> properties; // names, in order
    std::string error;
};

Header read_header(std::istream& in) {
    Header h;
    std::string line;
    if (!std::getline(in, line) || line != "ply") {
        h.error = "first line is not 'ply'";
        return h;
    }
    bool have_format = false, in_vertex = false, have_vertex = false;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string key;
        words >> key;
        if (key == "end_header") {
            if (!have_format) h.error = "no format line";
            else if (!have_vertex) h.error = "no 'element vertex' line";
            return h;
        } else if (key == "format") {
            std::string fmt, version;
            words >> fmt >> version;
            if (version != "1.0") h.error = "format version '" + version + "', expected 1.0";
            else if (fmt == "binary_little_endian") h.binary = true;
            else if (fmt != "ascii") h.error = "format '" + fmt + "', expected binary_little_endian or ascii";
            have_format = true;
        } else if (key == "comment" || key == "obj_info") {
        } else if (key == "element") {
            std::string name;
            words >> name;
            if (name != "vertex" || have_vertex) {
                h.error = "unexpected element '" + name + "' (a particle file holds one vertex element)";
                return h;
            }
            if (!(words >> h.vertices)) h.error = "element vertex without a count";
            have_vertex = in_vertex = true;
        } else if (key == "property") {
            std::string type, name;
            words >> type >> name;
            if (!in_vertex) h.error = "property before the vertex element";
            else if (type != "float" && type != "float32") h.error = "property " + name + " has type " + type;
            h.properties.push_back(name);
        } else {
            h.error = "unknown header line '" + line + "'";
        }
        if (!h.error.empty()) return h;
    }
    h.error = "no end_header";
    return h;
}

float le_float(const unsigned char* b) {
    const uint32_t bits = uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
    float v;
    std::memcpy(&v, &bits, 4);
    return v;
}

int fail(const char* file, const std::string& why) {
    std::fprintf(stderr, "pf_ply_check: %s: %s\n", file, why.c_str());
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 7 && argc != 10) {
        std::fprintf(stderr, "usage: pf_ply_check FILE COUNT CELL NX NY NZ [OX OY OZ]\n");
        return 2;
    }
    const char* file = argv[1];
    const uint64_t count = std::strtoull(argv[2], nullptr, 10);
    const double cell = std::strtod(argv[3], nullptr);
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
        lo[k] = argc == 10 ? std::strtod(argv[7 + k], nullptr) : 0.0;
        // float rounding of the library's own bound may land a hair outside the double product
        hi[k] = lo[k] + cell * std::strtod(argv[4 + k], nullptr) + 1e-6;
        lo[k] -= 1e-6;
    }

    std::ifstream in(file, std::ios::binary);
    if (!in) return fail(file, "cannot open");
    const Header h = read_header(in);
    if (!h.error.empty()) return fail(file, h.error);
    const std::vector<std::string> want = {"x", "y", "z", "vx", "vy", "vz"};
    if (h.properties != want) return fail(file, "vertex properties are not exactly x y z vx vy vz");
    if (h.vertices != count)
        return fail(file, std::to_string(h.vertices) + " vertices, expected " + std::to_string(count));

    std::vector<float> values(6 * size_t(count));
    if (h.binary) {
        std::vector<unsigned char> bytes(values.size() * 4);
        in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
        if (size_t(in.gcount()) != bytes.size()) return fail(file, "binary data shorter than the header says");
        for (size_t i = 0; i < values.size(); ++i) values[i] = le_float(bytes.data() + 4 * i);
    } else {
        for (float& v : values) {
            std::string word;
            if (!(in >> word)) return fail(file, "ascii data shorter than the header says");
            char* end = nullptr;
            v = std::strtof(word.c_str(), &end);
            if (*end) return fail(file, "not a number: '" + word + "'");
        }
        in >> std::ws;
    }
    if (in.peek() != std::char_traits<char>::eof()) return fail(file, "data after the last vertex");

    for (uint64_t i = 0; i < count; ++i) {
        const float* v = &values[6 * size_t(i)];
        for (int k = 0; k < 6; ++k)
            if (!std::isfinite(v[k])) return fail(file, "vertex " + std::to_string(i) + " has a non-finite value");
        for (int k = 0; k < 3; ++k)
            if (v[k] < lo[k] || v[k] > hi[k])
                return fail(file, "vertex " + std::to_string(i) + " lies outside the domain (" + want[size_t(k)] +
                                      " = " + std::to_string(v[k]) + ")");
    }
    std::printf("pf_ply_check: %s: %s, %llu particles, finite, inside the domain\n", file,
                h.binary ? "binary" : "ascii", static_cast<unsigned long long>(count));
    return 0;
}
