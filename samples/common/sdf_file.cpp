// A strict reader of the .npy format (numpy/lib/format.py documents it) for 3-D float grids. No
// C++ library for it is packaged in Debian (cnpy and libnpy are not), and the format is small:
// a magic string, a version, a header length, a Python dict literal and the raw array.
#include "sdf_file.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace pfs {

namespace {

constexpr char kMagic[] = "\x93NUMPY";
constexpr size_t kMagicSize = 6;
// numpy itself refuses headers longer than this by default (max_header_size, numpy >= 1.24);
// ours are about 70 bytes.
constexpr size_t kMaxHeader = 10000;
constexpr size_t kMaxPrefix = kMagicSize + 2 + 4;  // magic, version, v2 header length
constexpr uint64_t kMaxValues = uint64_t(kMaxSdfSamples) * kMaxSdfSamples * kMaxSdfSamples;

[[noreturn]] void refuse(const std::string& why) { throw SdfFileError(why); }

uint32_t little_endian(const unsigned char* p, int bytes) {
    uint32_t v = 0;
    for (int b = bytes - 1; b >= 0; --b) v = (v << 8) | p[b];
    return v;
}

float half_to_float(uint16_t h) {
    const int exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
    float magnitude;
    if (exponent == 0) magnitude = std::ldexp(float(mantissa), -24);                  // zero, subnormal
    else if (exponent == 31) magnitude = mantissa ? NAN : INFINITY;                   // refused later
    else magnitude = std::ldexp(float(mantissa + 1024), exponent - 25);
    return (h & 0x8000) ? -magnitude : magnitude;
}

// The header's dict literal, as numpy writes it with repr():
//     {'descr': '<f4', 'fortran_order': False, 'shape': (32, 20, 32), }
// Exactly these three keys, each once; strings in single or double quotes (no escapes: no valid
// value needs one); the shape a tuple of non-negative integers.
class HeaderReader {
public:
    explicit HeaderReader(const std::string& text) : s_(text) {}

    void read(std::string& descr, bool& fortran_order, std::vector<uint64_t>& shape) {
        bool seen_descr = false, seen_order = false, seen_shape = false;
        expect('{');
        while (!take('}')) {
            const std::string key = string_literal();
            expect(':');
            if (key == "descr") {
                once(seen_descr, key);
                descr = string_literal();
            } else if (key == "fortran_order") {
                once(seen_order, key);
                fortran_order = boolean();
            } else if (key == "shape") {
                once(seen_shape, key);
                shape = tuple();
            } else {
                refuse("header has an unknown key '" + key + "' (an .npy header has descr, fortran_order, shape)");
            }
            if (!take(',')) {
                expect('}');
                break;
            }
        }
        if (!seen_descr || !seen_order || !seen_shape)
            refuse(std::string("header lacks '") + (!seen_descr ? "descr" : !seen_order ? "fortran_order" : "shape") + "'");
        skip_space();
        if (i_ != s_.size()) refuse("header has text after its dictionary");
    }

private:
    void skip_space() {
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) ++i_;
    }
    bool take(char c) {
        skip_space();
        if (i_ < s_.size() && s_[i_] == c) {
            ++i_;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!take(c)) refuse(std::string("header is not an .npy dictionary (expected '") + c + "' at byte " +
                             std::to_string(i_) + ")");
    }
    static void once(bool& seen, const std::string& key) {
        if (seen) refuse("header has '" + key + "' twice");
        seen = true;
    }
    std::string string_literal() {
        skip_space();
        if (i_ >= s_.size() || (s_[i_] != '\'' && s_[i_] != '"'))
            refuse("header is not an .npy dictionary (expected a quoted string at byte " + std::to_string(i_) + ")");
        const char quote = s_[i_++];
        const size_t end = s_.find(quote, i_);
        if (end == std::string::npos || end - i_ > 64) refuse("header has an unterminated or overlong string");
        std::string v = s_.substr(i_, end - i_);
        i_ = end + 1;
        return v;
    }
    bool boolean() {
        skip_space();
        for (const char* word : {"True", "False"}) {
            const size_t n = std::strlen(word);
            if (s_.compare(i_, n, word) == 0) {
                i_ += n;
                return word[0] == 'T';
            }
        }
        refuse("header's fortran_order is not True or False");
    }
    std::vector<uint64_t> tuple() {
        expect('(');
        std::vector<uint64_t> v;
        while (!take(')')) {
            skip_space();
            if (i_ >= s_.size() || s_[i_] < '0' || s_[i_] > '9') refuse("header's shape is not a tuple of integers");
            uint64_t n = 0;
            while (i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9') {
                n = n * 10 + uint64_t(s_[i_++] - '0');
                if (n > (uint64_t(1) << 40)) refuse("header's shape has a size beyond any grid");
            }
            if (v.size() >= 32) refuse("header's shape has more than 32 dimensions");
            v.push_back(n);
            if (!take(',')) {
                expect(')');
                break;
            }
        }
        return v;
    }

    const std::string& s_;
    size_t i_ = 0;
};

std::string shape_text(const std::vector<uint64_t>& shape) {
    std::ostringstream s;
    s << '(';
    for (size_t a = 0; a < shape.size(); ++a) s << (a ? ", " : "") << shape[a];
    s << (shape.size() == 1 ? ",)" : ")");
    return s.str();
}

} // namespace

SdfGrid parse_npy_sdf(const std::string& bytes) {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    if (bytes.size() < kMagicSize + 2 || bytes.compare(0, kMagicSize, kMagic, kMagicSize) != 0)
        refuse("is not a NumPy .npy file (no \\x93NUMPY magic at its start)");
    const int major = data[kMagicSize], minor = data[kMagicSize + 1];
    if ((major != 1 && major != 2) || minor != 0)
        refuse("has .npy format version " + std::to_string(major) + "." + std::to_string(minor) +
               "; supported are 1.0 and 2.0 (what numpy.save writes for float arrays)");
    const size_t length_bytes = major == 1 ? 2 : 4, prefix = kMagicSize + 2 + length_bytes;
    if (bytes.size() < prefix) refuse("is truncated inside its header length");
    const size_t header_length = little_endian(data + kMagicSize + 2, int(length_bytes));
    if (header_length > kMaxHeader)
        refuse("has a header of " + std::to_string(header_length) + " bytes (at most " + std::to_string(kMaxHeader) + ")");
    if (bytes.size() < prefix + header_length) refuse("is truncated inside its header");
    const std::string header = bytes.substr(prefix, header_length);
    if (header.empty() || header.back() != '\n') refuse("has a header that does not end in a newline");

    std::string descr;
    bool fortran_order = false;
    std::vector<uint64_t> shape;
    HeaderReader(header).read(descr, fortran_order, shape);

    SdfGrid g;
    size_t item = 4;
    if (descr == "<f4") {
        g.precision = SdfGrid::Precision::float32;
    } else if (descr == "<f2") {
        g.precision = SdfGrid::Precision::float16;
        item = 2;
    } else if (descr == ">f4" || descr == ">f2") {
        refuse("has big-endian values (dtype '" + descr + "'); save little-endian ('<f4' or '<f2')");
    } else {
        refuse("has dtype '" + descr + "'; supported are float32 ('<f4') and float16 ('<f2')");
    }
    if (fortran_order) refuse("is in Fortran order; save a C-order array (numpy.ascontiguousarray)");
    if (shape.size() != 3) refuse("has shape " + shape_text(shape) + "; an SDF grid is a 3-D array (nx, ny, nz)");
    for (int a = 0; a < 3; ++a) {
        if (shape[a] < 2 || shape[a] > kMaxSdfSamples)
            refuse("has shape " + shape_text(shape) + "; each size must be in [2, " + std::to_string(kMaxSdfSamples) +
                   "] (linear filtering needs 2 samples an axis)");
        g.size[a] = uint32_t(shape[a]);
    }
    const uint64_t count = shape[0] * shape[1] * shape[2];
    static_assert(kMaxValues * 4 < (uint64_t(1) << 40), "sizes fit easily");
    const size_t expected = prefix + header_length + size_t(count) * item;
    if (bytes.size() < expected)
        refuse("is truncated: shape " + shape_text(shape) + " needs " + std::to_string(expected) + " bytes, the file has " +
               std::to_string(bytes.size()));
    if (bytes.size() > expected)
        refuse("has " + std::to_string(bytes.size() - expected) + " bytes after the array's data");

    // C order: the last index (k, z) varies fastest in the file; the grid keeps x fastest, the
    // order of a GL 3D texture's texels.
    const unsigned char* in = data + prefix + header_length;
    const size_t nx = g.size[0], ny = g.size[1], nz = g.size[2];
    g.values.resize(size_t(count));
    for (size_t i = 0; i < nx; ++i)
        for (size_t j = 0; j < ny; ++j)
            for (size_t k = 0; k < nz; ++k, in += item) {
                float v;
                if (item == 2) {
                    v = half_to_float(uint16_t(little_endian(in, 2)));
                } else {
                    const uint32_t w = little_endian(in, 4);
                    std::memcpy(&v, &w, 4);
                }
                if (!std::isfinite(v))
                    refuse("has a non-finite value at [" + std::to_string(i) + ", " + std::to_string(j) + ", " +
                           std::to_string(k) + "]");
                g.values[i + nx * (j + ny * k)] = v;
            }
    return g;
}

SdfGrid load_npy_sdf(const std::string& path) {
    // Only regular files, their size known before reading: a scene naming a device, a FIFO or
    // a huge file is refused without blocking or allocating.
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found) refuse("does not exist");
    if (ec) refuse("cannot be read: " + ec.message());
    if (!std::filesystem::is_regular_file(status)) refuse("is not a regular file");
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) refuse("cannot be read: " + ec.message());
    if (size > kMaxPrefix + kMaxHeader + kMaxValues * 4)
        refuse("has " + std::to_string(size) + " bytes, more than the largest grid allowed (" +
               std::to_string(kMaxSdfSamples) + "^3 float32)");
    std::ifstream f(path, std::ios::binary);
    if (!f) refuse("cannot be opened");
    std::string bytes(size_t(size), '\0');
    f.read(bytes.data(), std::streamsize(size));
    if (size_t(f.gcount()) != size) refuse("could not be read whole (it changed while being read?)");
    return parse_npy_sdf(bytes);
}

} // namespace pfs
