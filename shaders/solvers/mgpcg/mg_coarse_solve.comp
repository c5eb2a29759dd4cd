// Multigrid, the coarsest level in one workgroup: e = 0, then PF_MG_COARSE_SWEEPS symmetric
// red-black Gauss-Seidel pairs (red, black, black, red: the same operator forwards and
// backwards keeps the V-cycle symmetric) in shared memory, then e is written out. Skipped once
// the solve has converged (the CG scalars live in the state buffer).
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

void half_sweep(uint color) {
    for (int c = int(gl_LocalInvocationIndex); c < u_dims.w; c += PF_WORKGROUP_SIZE) {
        if (cell_color(c) != color || cell_type[c] != PF_CELL_FLUID) continue;
        PoissonStencil s = poisson_stencil(c);
        vec3 pair_sum = vec3(0.0);
        for (int n = 0; n < 6; ++n) {
            if (s.nb[n] >= 0) pair_sum[n / 2] += s_e[s.nb[n]];
        }
        s_e[c] = s.diag > 0.0 ? (r[c] + pair_total(pair_sum)) / s.diag : 0.0;
    }
    barrier();
}

void main() {
    if (solve_converged()) return;  // uniform across the workgroup
    for (int c = int(gl_LocalInvocationIndex); c < u_dims.w; c += PF_WORKGROUP_SIZE) s_e[c] = 0.0;
    barrier();
    for (int k = 0; k < PF_MG_COARSE_SWEEPS; ++k) {
        half_sweep(0u);
        half_sweep(1u);
        half_sweep(1u);
        half_sweep(0u);
    }
    for (int c = int(gl_LocalInvocationIndex); c < u_dims.w; c += PF_WORKGROUP_SIZE) e[c] = s_e[c];
}
