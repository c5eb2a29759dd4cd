// Conjugate gradients (without a stored z: PF_PRECOND 0 none, 1 Jacobi): x += alpha p, r -= alpha q
// on FLUID cells, z = M^-1 r, the partial sums (r.r, r.z, sum z, sum r) of the new residual, and
// in the last workgroup the beta step (cg_scalar_step.glsl). With Jacobi, z is also written out
// for the next direction (cg_matvec.comp). With a stored z, cg_update_stored.comp.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_REDUCTION_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_SOLVER_X) buffer X { float x[]; };
layout(std430, binding = PF_SLOT_SOLVER_R) buffer R { float r[]; };
layout(std430, binding = PF_SLOT_SOLVER_P) readonly buffer P { float p[]; };
layout(std430, binding = PF_SLOT_SOLVER_Q) readonly buffer Q { float q[]; };
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) coherent buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#if PF_PRECOND == 1
layout(std430, binding = PF_SLOT_SOLVER_Z) writeonly buffer Z { float z_out[]; };
#endif
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"
#include "solvers/cg/cg_precondition.glsl"
#include "solvers/cg/cg_scalar_step.glsl"

vec4 cell_contribution(int c, ivec3 ijk) {
    float rn = 0.0, z = 0.0;
    if (PF_CELL_KIND(cell_type[c]) == PF_CELL_FLUID) {
        float alpha = state_float(PF_SOLVER_ALPHA);
        x[c] += alpha * p[c];
        rn = r[c] - alpha * q[c];
        r[c] = rn;
        z = precondition(rn, poisson_stencil_at(c, ijk));
    }
#if PF_PRECOND == PF_PRECOND_JACOBI
    z_out[c] = z;
#endif
    return vec4(rn * rn, rn * z, z, rn);
}
void last_group_step(vec4 t) { cg_scalar_step(PF_CG_STEP_BETA, t); }
#define PF_LAST_GROUP 1
#include "solvers/common/orbit_main.glsl"
