// Multigrid, the coarsest level in one workgroup: e = 0, then red-black Gauss-Seidel half-sweeps
// in the palindromic order red, (black, red) x PF_MG_COARSE_SWEEPS — the same operator forwards
// and backwards, which keeps the V-cycle symmetric — then e is written out. One workgroup runs this, so
// every global-memory read would be a latency it waits for alone: the level's right-hand side
// and each cell's stencil (a mask of FLUID neighbours and the diagonal) are loaded into shared
// memory once, and the sweeps touch shared memory only. Skipped once the solve has converged.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/mgpcg/multigrid_limits.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_R) readonly buffer R { float r[]; };
layout(std430, binding = PF_SLOT_MG_E) writeonly buffer E { float e[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/state.glsl"

shared float s_e[PF_MG_COARSE_CELLS];
shared float s_r[PF_MG_COARSE_CELLS];
shared uint s_stencil[PF_MG_COARSE_CELLS];  // bits 0-5: FLUID neighbour n; bits 8-11: diag; bit 16: FLUID

void half_sweep(uint color) {
    const int step[6] = int[6](-1, 1, -u_dims.x, u_dims.x, -u_dims.x * u_dims.y, u_dims.x * u_dims.y);
    for (int c = int(gl_LocalInvocationIndex); c < u_dims.w; c += PF_WORKGROUP_SIZE) {
        uint st = s_stencil[c];
        if (cell_color(c) != color || (st & 0x10000u) == 0u) continue;
        vec3 pair_sum = vec3(0.0);
        for (int n = 0; n < 6; ++n) {
            if ((st & (1u << n)) != 0u) pair_sum[n / 2] += s_e[c + step[n]];
        }
        float diag = float((st >> 8) & 0xfu);
        s_e[c] = diag > 0.0 ? (s_r[c] + pair_total(pair_sum)) / diag : 0.0;
    }
    barrier();
}

void main() {
    if (solve_converged()) return;  // uniform across the workgroup
    for (int c = int(gl_LocalInvocationIndex); c < u_dims.w; c += PF_WORKGROUP_SIZE) {
        uint st = 0u;
        if (cell_type[c] == PF_CELL_FLUID) {
            PoissonStencil s = poisson_stencil(c);
            for (int n = 0; n < 6; ++n) st |= s.nb[n] >= 0 ? 1u << n : 0u;
            st |= uint(s.diag) << 8;
            st |= 0x10000u;
        }
        s_stencil[c] = st;
        s_r[c] = r[c];
        s_e[c] = 0.0;
    }
    barrier();
    half_sweep(0u);
    for (int k = 0; k < PF_MG_COARSE_SWEEPS; ++k) {
        half_sweep(1u);
        half_sweep(0u);
    }
    for (int c = int(gl_LocalInvocationIndex); c < u_dims.w; c += PF_WORKGROUP_SIZE) e[c] = s_e[c];
}
