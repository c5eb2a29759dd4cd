// One colour of a red-black (over-relaxed) Gauss-Seidel sweep, in place: cells of colour
// u_color (i+j+k even or odd) take p = (1-w) p + w (b + sum of FLUID neighbours) / diag; the
// 6 neighbours of a cell all have the other colour, so a colour updates without races.
// Permutations: the pressure solve (PF_GS_MULTIGRID 0: b has the singular mean removed and
// p >= 0 is imposed with separation — projected Gauss-Seidel) and the multigrid smoother
// (PF_GS_MULTIGRID 1: a correction equation on any level, linear, no projection), whose first
// sweep may start from zero (PF_GS_FROM_ZERO 1: neighbours read as 0, the other colour is set to 0).
// A pair solve (PF_PAIR 1, solver_value.glsl; the multigrid permutations only) does both
// problems: vec2 values.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_RHS) readonly buffer Rhs { value_t rhs[]; };
layout(std430, binding = PF_SLOT_SOLVER_X) buffer X { value_t x[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
layout(location = PF_LOC_SOLVER_COLOR) uniform uint u_color;
layout(location = PF_LOC_SOLVER_OMEGA) uniform float u_omega;
#include "solvers/common/poisson.glsl"
#include "solvers/common/state.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_dims.w) return;
    ivec3 ijk = level_coord(c);
    bool mine = cell_color_at(ijk) == u_color;
#if PF_GS_FROM_ZERO
    if (!mine || PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID) {
        x[c] = value_t(0.0);
        return;
    }
#else
    if (!mine || PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID) return;
#endif
    PoissonStencil s = poisson_stencil_at(c, ijk);
    pairs_t pair_sum = pairs_t(0.0);
#if !PF_GS_FROM_ZERO
    for (int n = 0; n < 6; ++n) {
        if (s.nb[n] >= 0) pair_sum[n / 2] += x[s.nb[n]];
    }
#endif
#if PF_GS_MULTIGRID
    value_t b = rhs[c];
#else
    value_t b = rhs[c] - rhs_mean();
#endif
    value_t gs = s.diag > 0.0 ? (b + pair_total(pair_sum)) / s.diag : value_t(0.0);
#if PF_GS_FROM_ZERO
    value_t p = u_omega * gs;
#else
    value_t p = (1.0 - u_omega) * x[c] + u_omega * gs;
#endif
#if !PF_GS_MULTIGRID
    if (project_nonnegative()) p = max(p, 0.0);
#endif
    x[c] = p;
}
