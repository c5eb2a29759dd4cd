// Residual of the current pressure, per workgroup (r.r, b.b, 0, 0) with r = (b - mean) - A p on
// FLUID cells. With p >= 0 imposed (separation), the problem is the complementarity problem
// p >= 0, A p - b >= 0, p (A p - b) = 0, and a cell at p = 0 only counts the part of r that
// violates it: max(r, 0). Every solver measures its convergence and its final residual here,
// relative to |b - mean| over the same cells (a solver may have solved on other cell types).
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_REDUCTION_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_RHS) readonly buffer Rhs { float rhs[]; };
layout(std430, binding = PF_SLOT_SOLVER_X) readonly buffer X { float x[]; };
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"

vec4 cell_contribution(int c, ivec3 ijk) {
    float r = 0.0, b = 0.0;
    if (PF_CELL_KIND(cell_type[c]) == PF_CELL_FLUID) {
        PoissonStencil s = poisson_stencil_at(c, ijk);
        vec3 pair_sum = vec3(0.0);
        for (int n = 0; n < 6; ++n) {
            if (s.nb[n] >= 0) pair_sum[n / 2] += x[s.nb[n]];
        }
        b = rhs[c] - rhs_mean();
        r = b - (s.diag * x[c] - pair_total(pair_sum));
        if (project_nonnegative() && x[c] <= 0.0) r = max(r, 0.0);
    }
    return vec4(r * r, b * b, 0.0, 0.0);
}
#include "solvers/common/orbit_main.glsl"
