// Host mirror of the SimUniforms std140 block in shaders/common/sim.glsl. Only 16-byte
// vectors, so std140 offsets equal C++ offsets; tests/test_gpu_layout.cpp checks each
// member's offset against the one the GL reports.
#pragma once
#include <cstdint>

namespace pf {

struct SimUniforms {
    int32_t grid[4];         // nx, ny, nz, cell count
    int32_t face_count[4];   // NU, NV, NW, total
    float origin_dx[4];      // origin xyz, cell size
    float gravity_dt[4];     // gravity xyz, substep dt
    float fixed_scale[4];    // S_m, S_w, 1/S_m, 1/S_w
    float solve[4];          // density, jacobi omega, flip ratio, max speed
    uint32_t counts[4];      // particle count, separation (0/1), -, -
};
static_assert(sizeof(SimUniforms) == 7 * 16, "SimUniforms must match the std140 block");

}  // namespace pf
