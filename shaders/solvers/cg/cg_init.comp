// Conjugate gradients, start: r = (b - mean) - A x from the warm-started pressure x (x = 0
// outside FLUID cells). Unless z is stored (PF_PRECOND 2, computed by the preconditioner
// afterwards), also the partial sums (r.r, r.z, sum z, sum r) for cg_scalars' start step.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_RHS) readonly buffer Rhs { float rhs[]; };
layout(std430, binding = PF_SLOT_SOLVER_X) buffer X { float x[]; };
layout(std430, binding = PF_SLOT_SOLVER_R) writeonly buffer R { float r_out[]; };
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"
#include "solvers/cg/cg_precondition.glsl"

vec4 cell_contribution(int c) {
    float r = 0.0, z = 0.0;
    if (cell_type[c] == PF_CELL_FLUID) {
        PoissonStencil s = poisson_stencil(c);
        vec3 pair_sum = vec3(0.0);
        for (int n = 0; n < 6; ++n) {
            if (s.nb[n] >= 0) pair_sum[n / 2] += x[s.nb[n]];
        }
        r = (rhs[c] - rhs_mean()) - (s.diag * x[c] - pair_total(pair_sum));
        z = precondition(r, s);
    } else {
        x[c] = 0.0;  // never read by a neighbour's stencil: no race
    }
    r_out[c] = r;
    // With a stored z (PF_PRECOND 2) the sums come later (cg_zstats) and these are unused.
    return vec4(r * r, r * z, z, r);
}
#include "solvers/common/orbit_main.glsl"
