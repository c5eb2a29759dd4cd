// Separation for the CG family: p = max(p, 0) on FLUID cells, after an active-set update (the
// cells it made active hold p = 0 from now on) and at the end of the solve.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_SOLVER_X) buffer X { float x[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/state.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_dims.w || PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID || solve_singular()) return;
    x[c] = max(x[c], 0.0);
}
