// Conjugate gradients with a stored preconditioned residual z (multigrid): the partial sums
// (r.r, r.z, sum z, sum r) over FLUID cells, and CG's scalar step u_cg_step in the last
// workgroup (cg_scalar_step.glsl). Used by a multigrid whose fine grid is its coarsest level.
// A pair solve (PF_PAIR 1) sums each problem in a column of its own.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#if defined(PF_PAIR) && PF_PAIR
#define PF_SUMS 2
#endif
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_REDUCTION_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_SOLVER_R) readonly buffer R { value_t r[]; };
layout(std430, binding = PF_SLOT_SOLVER_Z) readonly buffer Z { value_t z[]; };
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) coherent buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
layout(location = PF_LOC_SOLVER_CG_STEP) uniform uint u_cg_step;  // run by the last workgroup
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"
#include "solvers/cg/cg_scalar_step.glsl"

sums_t cell_contribution(int c, ivec3 ijk) {
    if (PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID) return sums_t(0.0);
    value_t rc = r[c], zc = z[c];
#if PF_PAIR
    return mat2x4(vec4(rc.x * rc.x, rc.x * zc.x, zc.x, rc.x), vec4(rc.y * rc.y, rc.y * zc.y, zc.y, rc.y));
#else
    return vec4(rc * rc, rc * zc, zc, rc);
#endif
}
void last_group_step(sums_t t) { cg_scalar_step(u_cg_step, t); }
#define PF_LAST_GROUP 1
#include "solvers/common/orbit_main.glsl"
