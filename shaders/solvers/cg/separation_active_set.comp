// Separation (p >= 0) for the CG family: one primal-dual active-set update between solves.
// The solve runs on a working copy of the cell types in which "active" FLUID cells are held at
// p = 0 (marked AIR). A FLUID cell whose pressure came out negative becomes active; an active
// cell whose residual r = b - A p is positive (the liquid there is being compressed, so it
// wants pressure) is released. Repeating solve + update converges to the complementarity
// solution (p >= 0, A p - b >= 0, p (A p - b) = 0) in a few rounds. Nothing changes in a
// singular system (no AIR: nothing to separate into). The pressure of newly active cells is
// zeroed by separation_clamp.comp afterwards (here neighbours still read it).
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_RHS) readonly buffer Rhs { float rhs[]; };
layout(std430, binding = PF_SLOT_SOLVER_X) readonly buffer X { float x[]; };
layout(std430, binding = PF_SLOT_SOLVER_WORKING_TYPE) buffer Working { uint working_type[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/state.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_dims.w || PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID || solve_singular()) return;
    if (PF_CELL_KIND(working_type[c]) == PF_CELL_FLUID) {
        if (x[c] < 0.0) working_type[c] = PF_CELL_AIR;
        return;
    }
    // Active: A p - b with the real operator (active neighbours hold p = 0 already).
    PoissonStencil s = poisson_stencil(c);
    vec3 pair_sum = vec3(0.0);
    for (int n = 0; n < 6; ++n) {
        if (s.nb[n] >= 0) pair_sum[n / 2] += max(x[s.nb[n]], 0.0);
    }
    float r = rhs[c] - (s.diag * max(x[c], 0.0) - pair_total(pair_sum));
    if (r > 0.0) working_type[c] = cell_type[c];  // the cell's own FLUID word back
}
