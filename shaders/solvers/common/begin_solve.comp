// One workgroup, start of every solve: adds rhs_stats' partials, decides whether the system is
// singular, stores b.b and the mean of b to remove, resets the iteration scalars (the iteration
// count only for a new solve, not for a further round of the same one) and restores
// every indirect-dispatch record to its full size (an earlier solve may have zeroed them).
// A pair solve (PF_PAIR 1) starts each problem's block of scalars (state.glsl) from its own column
// of sums, with its own tolerance and iteration cap.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
layout(location = PF_LOC_SOLVER_COUNT) uniform uint u_partials;
layout(location = PF_LOC_SOLVER_TOLERANCE) uniform float u_tolerance;
layout(location = PF_LOC_SOLVER_ITERATIONS) uniform uint u_keep_iterations;  // 1: a further round of one solve
#if PF_PAIR
// A pair never imposes p >= 0 (the correction's potential has either sign).
layout(location = PF_LOC_SOLVER_TOLERANCE_SECOND) uniform float u_tolerance_second;
layout(location = PF_LOC_SOLVER_CAP) uniform uint u_cap;
layout(location = PF_LOC_SOLVER_CAP_SECOND) uniform uint u_cap_second;
const uint u_nonnegative = 0u;
#else
layout(location = PF_LOC_SOLVER_NONNEGATIVE) uniform uint u_nonnegative;
#endif
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"

// Block b's scalars from its sums t = (sum b, b.b, FLUID cells, AIR cells).
void begin_block(uint b, vec4 t, float tolerance, uint cap) {
    float fluid = t.z;
    bool singular = t.w == 0.0 && fluid > 0.0;
    float mean = singular ? t.x / fluid : 0.0;
    // sum (b - mean)^2 = sum b^2 - n mean^2 (sum b = n mean)
    set_state_float(b + PF_SOLVER_BB, max(t.y - fluid * mean * mean, 0.0));
    set_state_float(b + PF_SOLVER_B_MEAN, mean);
    state[b + PF_SOLVER_SINGULAR] = singular ? 1u : 0u;
    state[b + PF_SOLVER_FLUID_CELLS] = uint(fluid);
    set_state_float(b + PF_SOLVER_RZ, 0.0);
    set_state_float(b + PF_SOLVER_ALPHA, 0.0);
    set_state_float(b + PF_SOLVER_BETA, 0.0);
    set_state_float(b + PF_SOLVER_Z_MEAN, 0.0);
    if (u_keep_iterations == 0u) {
        state[b + PF_SOLVER_ITERATIONS] = 0u;
        state[b + PF_SOLVER_ROUND] = 0u;
        state[b + PF_SOLVER_FIRST_ROUND] = 0u;
        state[b + PF_SOLVER_LATER_ROUNDS] = 0u;
    } else {
        finish_round_in(b);
        state[b + PF_SOLVER_ROUND] += 1u;
    }
    state[b + PF_SOLVER_ROUND_START] = state[b + PF_SOLVER_ITERATIONS];
    state[b + PF_SOLVER_CONVERGED] = 0u;
    set_state_float(b + PF_SOLVER_RESIDUAL, 1.0);
    set_state_float(b + PF_SOLVER_TOLERANCE, tolerance);
    state[b + PF_SOLVER_NONNEGATIVE] = u_nonnegative;
    state[b + PF_SOLVER_ITERATION_CAP] = cap;
}

void main() {
    vec4 t = sum_partials(u_partials);
#if PF_PAIR
    vec4 t_second = sum_partials_at(u_partials, u_partials);
#endif
    uint lid = gl_LocalInvocationIndex;
    uint records = state[PF_SOLVER_RECORDS];
    for (uint w = lid; w < 4u * records; w += uint(PF_WORKGROUP_SIZE))
        state[PF_SOLVER_SCALARS + w] = state[PF_SOLVER_SCALARS + 4u * PF_SOLVER_MAX_RECORDS + w];
    if (lid != 0u) return;
#if PF_PAIR
    begin_block(0u, t, u_tolerance, u_cap);
    begin_block(PF_SOLVER_SECOND, t_second, u_tolerance_second, u_cap_second);
#else
    begin_block(0u, t, u_tolerance, 0xffffffffu);
#endif
}
