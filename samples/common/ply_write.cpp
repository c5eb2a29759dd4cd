#include "ply_write.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

namespace pfs {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

bool host_is_little_endian() {
    const uint32_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

// The 4 bytes of v in little-endian order, whatever the host's order.
void put_le(float v, unsigned char* out) {
    uint32_t bits = 0;
    std::memcpy(&bits, &v, 4);
    for (int i = 0; i < 4; ++i) out[i] = static_cast<unsigned char>(bits >> (8 * i));
}

} // namespace

bool write_ply_particles(const std::string& path, const float* xyz, const float* vel, uint32_t n,
                         PlyFormat format, const std::string& comment) {
    std::unique_ptr<std::FILE, FileCloser> f(std::fopen(path.c_str(), "wb"));
    if (!f) return false;
    const bool binary = format == PlyFormat::binary_little_endian;
    // Header lines end in "\n" only: some readers reject "\r\n".
    std::string header = "ply\n";
    header += binary ? "format binary_little_endian 1.0\n" : "format ascii 1.0\n";
    if (!comment.empty()) header += "comment " + comment + "\n";
    header += "element vertex " + std::to_string(n) + "\n";
    for (const char* p : {"x", "y", "z", "vx", "vy", "vz"}) header += std::string("property float ") + p + "\n";
    header += "end_header\n";
    if (std::fwrite(header.data(), 1, header.size(), f.get()) != header.size()) return false;

    const float zero[3] = {0, 0, 0};
    if (binary) {
        // One particle is 24 bytes; write in blocks of 4096 to keep the calls few.
        const bool le = host_is_little_endian();
        std::vector<unsigned char> block;
        block.reserve(4096 * 24);
        for (uint32_t i = 0; i < n; ++i) {
            const float* v = vel ? vel + 3 * size_t(i) : zero;
            const float values[6] = {xyz[3 * size_t(i)], xyz[3 * size_t(i) + 1], xyz[3 * size_t(i) + 2],
                                     v[0], v[1], v[2]};
            unsigned char bytes[24];
            if (le) std::memcpy(bytes, values, 24);
            else
                for (int k = 0; k < 6; ++k) put_le(values[k], bytes + 4 * k);
            block.insert(block.end(), bytes, bytes + 24);
            if (block.size() == block.capacity() || i + 1 == n) {
                if (std::fwrite(block.data(), 1, block.size(), f.get()) != block.size()) return false;
                block.clear();
            }
        }
    } else {
        for (uint32_t i = 0; i < n; ++i) {
            const float* p = xyz + 3 * size_t(i);
            const float* v = vel ? vel + 3 * size_t(i) : zero;
            if (std::fprintf(f.get(), "%.9g %.9g %.9g %.9g %.9g %.9g\n", double(p[0]), double(p[1]), double(p[2]),
                             double(v[0]), double(v[1]), double(v[2])) < 0)
                return false;
        }
    }
    // fclose flushes: its failure (a full disk) is a failed write.
    return std::fclose(f.release()) == 0;
}

} // namespace pfs
