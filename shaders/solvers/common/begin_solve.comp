// One workgroup, start of every solve: adds rhs_stats' partials, decides whether the system is
// singular, stores b.b and the mean of b to remove, resets the iteration scalars (the iteration
// count only for a new solve, not for a further round of the same one) and restores
// every indirect-dispatch record to its full size (an earlier solve may have zeroed them).
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
layout(location = PF_LOC_SOLVER_COUNT) uniform uint u_partials;
layout(location = PF_LOC_SOLVER_TOLERANCE) uniform float u_tolerance;
layout(location = PF_LOC_SOLVER_ITERATIONS) uniform uint u_keep_iterations;  // 1: a further round of one solve
layout(location = PF_LOC_SOLVER_NONNEGATIVE) uniform uint u_nonnegative;
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"

void main() {
    vec4 t = sum_partials(u_partials);
    uint lid = gl_LocalInvocationIndex;
    uint records = state[PF_SOLVER_RECORDS];
    for (uint w = lid; w < 4u * records; w += uint(PF_WORKGROUP_SIZE))
        state[PF_SOLVER_SCALARS + w] = state[PF_SOLVER_SCALARS + 4u * PF_SOLVER_MAX_RECORDS + w];
    if (lid != 0u) return;
    float fluid = t.z;
    bool singular = t.w == 0.0 && fluid > 0.0;
    float mean = singular ? t.x / fluid : 0.0;
    // sum (b - mean)^2 = sum b^2 - n mean^2 (sum b = n mean)
    set_state_float(PF_SOLVER_BB, max(t.y - fluid * mean * mean, 0.0));
    set_state_float(PF_SOLVER_B_MEAN, mean);
    state[PF_SOLVER_SINGULAR] = singular ? 1u : 0u;
    state[PF_SOLVER_FLUID_CELLS] = uint(fluid);
    set_state_float(PF_SOLVER_RZ, 0.0);
    set_state_float(PF_SOLVER_ALPHA, 0.0);
    set_state_float(PF_SOLVER_BETA, 0.0);
    set_state_float(PF_SOLVER_Z_MEAN, 0.0);
    if (u_keep_iterations == 0u) {
        state[PF_SOLVER_ITERATIONS] = 0u;
        state[PF_SOLVER_ROUND] = 0u;
        state[PF_SOLVER_FIRST_ROUND] = 0u;
        state[PF_SOLVER_LATER_ROUNDS] = 0u;
    } else {
        finish_round();
        state[PF_SOLVER_ROUND] += 1u;
    }
    state[PF_SOLVER_ROUND_START] = state[PF_SOLVER_ITERATIONS];
    state[PF_SOLVER_CONVERGED] = 0u;
    set_state_float(PF_SOLVER_RESIDUAL, 1.0);
    set_state_float(PF_SOLVER_TOLERANCE, u_tolerance);
    state[PF_SOLVER_NONNEGATIVE] = u_nonnegative;
}
