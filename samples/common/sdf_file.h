// Signed-distance grids from NumPy .npy files, for SDF obstacles in scene files (no GL here:
// the scene loader and its fuzzer use it; samples/common/sdf_texture.h makes the GL texture).
//
// The file: what numpy.save writes for a 3-D array, format version 1.0 or 2.0, dtype
// little-endian float32 ('<f4') or float16 ('<f2'), C order (fortran_order False), shape
// (nx, ny, nz) with 2..kMaxSdfSamples samples per axis. a[i, j, k] is the distance at the centre
// of cell (i, j, k) of an nx x ny x nz grid of equal cells tiling the obstacle's local box
// [-half_extents, half_extents]: local point
//     (-hx + (i + 0.5) 2 hx / nx,  -hy + (j + 0.5) 2 hy / ny,  -hz + (k + 0.5) 2 hz / nz),
// i along local x, j along y, k along z (numpy.meshgrid(xs, ys, zs, indexing="ij") gives this
// order), negative inside, in units of the obstacle's sdf_scale (metres per unit). Every value
// must be finite; nothing may follow the data.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace pfs {

/// Most samples a grid may have along one axis (a 256^3 float32 grid is 64 MiB).
constexpr uint32_t kMaxSdfSamples = 256;

struct SdfGrid {
    enum class Precision { float16, float32 };
    uint32_t size[3] = {0, 0, 0};      // samples along local x, y, z (the file's shape)
    Precision precision = Precision::float32;  // as stored in the file (the GL texture keeps it)
    std::vector<float> values;         // x fastest: values[i + nx * (j + ny * k)] = a[i, j, k]

    float at(uint32_t i, uint32_t j, uint32_t k) const { return values[i + size[0] * (j + size_t(size[1]) * k)]; }
};

/// Why an .npy file was refused (the reason only; callers add the file and the scene's path).
struct SdfFileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Parses the bytes of an .npy file as above; throws SdfFileError with the reason.
SdfGrid parse_npy_sdf(const std::string& bytes);

/// Reads and parses the .npy file at `path` (a regular file no larger than the biggest grid
/// allowed, checked before reading); throws SdfFileError with the reason.
SdfGrid load_npy_sdf(const std::string& path);

} // namespace pfs
