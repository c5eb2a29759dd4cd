// Conjugate gradients with a stored preconditioned residual z (multigrid): the partial sums
// (r.r, r.z, sum z, sum r) over FLUID cells.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_SOLVER_R) readonly buffer R { float r[]; };
layout(std430, binding = PF_SLOT_SOLVER_Z) readonly buffer Z { float z[]; };
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"

vec4 cell_contribution(int c) {
    if (cell_type[c] != PF_CELL_FLUID) return vec4(0.0);
    float rc = r[c], zc = z[c];
    return vec4(rc * rc, rc * zc, zc, rc);
}
#include "solvers/common/orbit_main.glsl"
