// Conjugate gradients: the search direction p = (z - m) + beta p on FLUID cells (0 elsewhere),
// where m is the mean of z removed when the system is singular (keeps p out of the null space)
// and beta = 0 starts afresh (p is not read then, so stale values cannot leak in).
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
#if PF_PRECOND == 2
layout(std430, binding = PF_SLOT_SOLVER_Z) readonly buffer Z { float z_in[]; };
#else
layout(std430, binding = PF_SLOT_SOLVER_R) readonly buffer R { float r[]; };
#endif
layout(std430, binding = PF_SLOT_SOLVER_P) buffer P { float p[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/state.glsl"
#include "solvers/cg/cg_precondition.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_dims.w) return;
    if (cell_type[c] != PF_CELL_FLUID) {
        p[c] = 0.0;
        return;
    }
#if PF_PRECOND == PF_PRECOND_STORED
    float z = z_in[c];
#else
    float z = precondition(r[c], poisson_stencil(c));
#endif
    float beta = state_float(PF_SOLVER_BETA);
    float d = z - state_float(PF_SOLVER_Z_MEAN);
    p[c] = beta == 0.0 ? d : d + beta * p[c];
}
