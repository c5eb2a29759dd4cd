// One workgroup: adds residual's partials into the relative residual |r| / |b|. Convergence
// check (PF_CHECK_FINAL 0): counts the iterations since the previous check and, once the
// tolerance is met, stops the solve (its later indirect dispatches become empty). Final
// report (PF_CHECK_FINAL 1): records the solve's iterations and final residual in the
// simulation's status buffer (the largest over the substeps of a step).
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#if PF_CHECK_FINAL
layout(std430, binding = PF_SLOT_SOLVER_STATUS) buffer Status { uint status[]; };
#endif
layout(location = PF_LOC_SOLVER_COUNT) uniform uint u_partials;
layout(location = PF_LOC_SOLVER_ITERATIONS) uniform uint u_iterations;
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"

void main() {
#if !PF_CHECK_FINAL
    if (solve_converged()) return;  // uniform across the workgroup: no barrier is skipped by a few
#endif
    vec4 t = sum_partials(u_partials);
    if (gl_LocalInvocationIndex != 0u) return;
    float rel = relative_residual(t.x, t.y);
    set_state_float(PF_SOLVER_RESIDUAL, rel);
#if PF_CHECK_FINAL
    atomicMax(status[PF_STATUS_SOLVER_ITERATIONS], state[PF_SOLVER_ITERATIONS]);
    finish_round();
    atomicMax(status[PF_STATUS_SOLVER_FIRST_ROUND], state[PF_SOLVER_FIRST_ROUND]);
    atomicMax(status[PF_STATUS_SOLVER_LATER_ROUNDS], state[PF_SOLVER_LATER_ROUNDS]);
    atomicMax(status[PF_STATUS_SOLVER_RESIDUAL], floatBitsToUint(rel));  // rel >= 0: bits order like values
#else
    state[PF_SOLVER_ITERATIONS] += u_iterations;
    if (rel <= state_float(PF_SOLVER_TOLERANCE)) stop_solve();
#endif
}
