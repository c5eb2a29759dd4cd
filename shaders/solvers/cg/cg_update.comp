// Conjugate gradients: x += alpha p, r -= alpha q on FLUID cells; unless z is stored
// (PF_PRECOND 2), also the partial sums (r.r, r.z, sum z, sum r) of the new residual.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_SOLVER_X) buffer X { float x[]; };
layout(std430, binding = PF_SLOT_SOLVER_R) buffer R { float r[]; };
layout(std430, binding = PF_SLOT_SOLVER_P) readonly buffer P { float p[]; };
layout(std430, binding = PF_SLOT_SOLVER_Q) readonly buffer Q { float q[]; };
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"
#include "solvers/cg/cg_precondition.glsl"

vec4 cell_contribution(int c) {
    float rn = 0.0, z = 0.0;
    if (cell_type[c] == PF_CELL_FLUID) {
        float alpha = state_float(PF_SOLVER_ALPHA);
        x[c] += alpha * p[c];
        rn = r[c] - alpha * q[c];
        r[c] = rn;
#if PF_PRECOND != PF_PRECOND_STORED
        z = precondition(rn, poisson_stencil(c));
#endif
    }
    return vec4(rn * rn, rn * z, z, rn);  // unused with a stored z (cg_zstats sums then)
}
#include "solvers/common/orbit_main.glsl"
