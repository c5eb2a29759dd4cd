// Conjugate gradients, start (without a stored z: PF_PRECOND 0 none, 1 Jacobi): r = (b - mean)
// - A x from the warm-started pressure x (x = 0 outside FLUID cells), z = M^-1 r, the partial
// sums (r.r, r.z, sum z, sum r), and in the last workgroup the start step (cg_scalar_step.glsl).
// With Jacobi, z is also written out for the next direction (cg_matvec.comp).
// With a stored z, cg_init_stored.comp.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_REDUCTION_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_RHS) readonly buffer Rhs { float rhs[]; };
layout(std430, binding = PF_SLOT_SOLVER_X) buffer X { float x[]; };
layout(std430, binding = PF_SLOT_SOLVER_R) writeonly buffer R { float r_out[]; };
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) coherent buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#if PF_PRECOND == 1
layout(std430, binding = PF_SLOT_SOLVER_Z_INIT) writeonly buffer Z { float z_out[]; };
#endif
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"
#include "solvers/cg/cg_precondition.glsl"
#include "solvers/cg/cg_scalar_step.glsl"
#include "solvers/cg/cg_start_residual.glsl"

vec4 cell_contribution(int c, ivec3 ijk) {
    float r = 0.0, z = 0.0;
    if (PF_CELL_KIND(cell_type[c]) == PF_CELL_FLUID) {
        PoissonStencil s = poisson_stencil_at(c, ijk);
        r = start_residual(c, s);
        z = precondition(r, s);
    } else {
        x[c] = 0.0;  // never read by a neighbour's stencil: no race
    }
    r_out[c] = r;
#if PF_PRECOND == PF_PRECOND_JACOBI
    z_out[c] = z;
#endif
    return vec4(r * r, r * z, z, r);
}
void last_group_step(vec4 t) { cg_scalar_step(PF_CG_STEP_START, t); }
#define PF_LAST_GROUP 1
#include "solvers/common/orbit_main.glsl"
