// Residual of the current pressure, per workgroup (r.r, b.b, 0, 0) with r = (b - mean) - A p on
// FLUID cells. With p >= 0 imposed (separation), the problem is the complementarity problem
// p >= 0, A p - b >= 0, p (A p - b) = 0, and a cell at p = 0 only counts the part of r that
// violates it: max(r, 0). Every solver measures its convergence and its final residual here,
// relative to |b - mean| over the same cells (a solver may have solved on other cell types).
// A pair solve (PF_PAIR 1, never with p >= 0) sums (r.r, b.b) of both problems:
// (r.r, b.b, r'.r', b'.b'), the second's b and p in rhs_second and x_second.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_REDUCTION_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_RHS) readonly buffer Rhs { float rhs[]; };
layout(std430, binding = PF_SLOT_SOLVER_X) readonly buffer X { float x[]; };
#if PF_PAIR
layout(std430, binding = PF_SLOT_SOLVER_RHS_SECOND) readonly buffer RhsSecond { float rhs_second[]; };
layout(std430, binding = PF_SLOT_SOLVER_X_SECOND) readonly buffer XSecond { float x_second[]; };
#endif
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"

#include "solvers/common/problem_values.glsl"

vec4 cell_contribution(int c, ivec3 ijk) {
    value_t r = value_t(0.0), b = value_t(0.0);
    if (PF_CELL_KIND(cell_type[c]) == PF_CELL_FLUID) {
        PoissonStencil s = poisson_stencil_at(c, ijk);
        pairs_t pair_sum = pairs_t(0.0);
        for (int n = 0; n < 6; ++n) {
            if (s.nb[n] >= 0) pair_sum[n / 2] += x_at(s.nb[n]);
        }
        b = b_at(c);
        r = b - (s.diag * x_at(c) - pair_total(pair_sum));
#if !PF_PAIR
        if (project_nonnegative() && x[c] <= 0.0) r = max(r, 0.0);
#endif
    }
#if PF_PAIR
    return vec4(r.x * r.x, b.x * b.x, r.y * r.y, b.y * b.y);
#else
    return vec4(r * r, b * b, 0.0, 0.0);
#endif
}
#include "solvers/common/orbit_main.glsl"
