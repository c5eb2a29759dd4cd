// Conjugate gradients with a stored z (the multigrid V-cycle), start, per cell: r = (b - mean)
// - A x from the warm-started pressure x (x = 0 outside FLUID cells, r = 0 there). The
// preconditioner makes z and its sums afterwards, and runs the start step (cg_scalar_step.glsl).
// A pair solve (PF_PAIR 1) does both problems: r holds a vec2 a cell.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_RHS) readonly buffer Rhs { float rhs[]; };
layout(std430, binding = PF_SLOT_SOLVER_X) buffer X { float x[]; };
#if PF_PAIR
layout(std430, binding = PF_SLOT_SOLVER_RHS_SECOND) readonly buffer RhsSecond { float rhs_second[]; };
layout(std430, binding = PF_SLOT_SOLVER_X_SECOND) buffer XSecond { float x_second[]; };
#endif
layout(std430, binding = PF_SLOT_SOLVER_R) writeonly buffer R { value_t r_out[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/state.glsl"
#include "solvers/cg/cg_start_residual.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_dims.w) return;
    value_t r = value_t(0.0);
    if (PF_CELL_KIND(cell_type[c]) == PF_CELL_FLUID) {
        r = start_residual(c, poisson_stencil(c));
    } else {
        x[c] = 0.0;  // never read by a neighbour's stencil: no race
#if PF_PAIR
        x_second[c] = 0.0;
#endif
    }
    r_out[c] = r;
}
