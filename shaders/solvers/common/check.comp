// One workgroup: adds residual's partials into the relative residual |r| / |b|. Convergence
// check (PF_CHECK_FINAL 0): counts the iterations since the previous check and, once the
// tolerance is met, stops the solve (its later indirect dispatches become empty). Final
// report (PF_CHECK_FINAL 1): records the solve's iterations and final residual in the
// simulation's status buffer (the largest over the substeps of a step). A pair solve's report
// (PF_PAIR 1, residual.comp's sums of both problems) books the second problem in status_second.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#if PF_CHECK_FINAL
layout(std430, binding = PF_SLOT_SOLVER_STATUS) buffer Status { uint status[]; };
#endif
#if PF_CHECK_FINAL && PF_PAIR
layout(std430, binding = PF_SLOT_SOLVER_STATUS_SECOND) buffer StatusSecond { uint status_second[]; };
#endif
layout(location = PF_LOC_SOLVER_COUNT) uniform uint u_partials;
layout(location = PF_LOC_SOLVER_ITERATIONS) uniform uint u_iterations;
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"

#if PF_CHECK_FINAL
// The largest of v and a status word (the second problem's status buffer when `second`).
void book(bool second, uint word, uint v) {
#if PF_PAIR
    if (second) {
        atomicMax(status_second[word], v);
        return;
    }
#endif
    atomicMax(status[word], v);
}

// Block b's iterations and final residual (from r.r and b.b).
void report(uint b, float rr, float bb, bool second) {
    float rel = relative_residual(rr, bb);
    set_state_float(b + PF_SOLVER_RESIDUAL, rel);
    book(second, PF_STATUS_SOLVER_ITERATIONS, state[b + PF_SOLVER_ITERATIONS]);
    finish_round_in(b);
    book(second, PF_STATUS_SOLVER_FIRST_ROUND, state[b + PF_SOLVER_FIRST_ROUND]);
    book(second, PF_STATUS_SOLVER_LATER_ROUNDS, state[b + PF_SOLVER_LATER_ROUNDS]);
    book(second, PF_STATUS_SOLVER_RESIDUAL, floatBitsToUint(rel));  // rel >= 0: bits order like values
}
#endif

void main() {
#if !PF_CHECK_FINAL
    if (solve_converged()) return;  // uniform across the workgroup: no barrier is skipped by a few
#endif
    vec4 t = sum_partials(u_partials);
    if (gl_LocalInvocationIndex != 0u) return;
#if PF_CHECK_FINAL
    report(0u, t.x, t.y, false);
#if PF_PAIR
    report(PF_SOLVER_SECOND, t.z, t.w, true);
#endif
#else
    float rel = relative_residual(t.x, t.y);
    set_state_float(PF_SOLVER_RESIDUAL, rel);
    state[PF_SOLVER_ITERATIONS] += u_iterations;
    if (rel <= state_float(PF_SOLVER_TOLERANCE)) stop_solve_in(0u);
#endif
}
