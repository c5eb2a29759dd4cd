// Access to a solver's state buffer (solvers/common/solver_state.h): scalars and the
// indirect-dispatch records that convergence switches off. A pair solve (PF_PAIR 1,
// solver_value.glsl) has a block of scalars per problem: the `_in(b, ...)` forms take the block's
// first word (0, or PF_SOLVER_SECOND), the others read the first block; the `_value` forms give
// both as a value_t.
// Requires the kernel to declare `state` (uint[]) before including this file.
#ifndef PF_PAIR
#define PF_PAIR 0
#endif
float state_float(uint word) { return uintBitsToFloat(state[word]); }
void set_state_float(uint word, float v) { state[word] = floatBitsToUint(v); }

bool solve_singular() { return state[PF_SOLVER_SINGULAR] != 0u; }
bool solve_converged_in(uint b) { return state[b + PF_SOLVER_CONVERGED] != 0u; }
// The whole solve (both problems of a pair) has converged: its records are empty.
bool solve_converged() {
#if PF_PAIR
    return solve_converged_in(0u) && solve_converged_in(PF_SOLVER_SECOND);
#else
    return solve_converged_in(0u);
#endif
}

// Mean of b removed from the right-hand side (non-zero only for a singular system).
float rhs_mean() { return state_float(PF_SOLVER_B_MEAN); }

#ifdef PF_VALUE_TYPES
// Scalar `word` of each problem.
value_t state_value(uint word) {
#if PF_PAIR
    return vec2(state_float(word), state_float(PF_SOLVER_SECOND + word));
#else
    return state_float(word);
#endif
}
// The same, 0 for a problem of a pair that has converged (its CG steps no longer move it: alpha
// and beta read 0 there).
value_t live_state_value(uint word) {
#if PF_PAIR
    return vec2(solve_converged_in(0u) ? 0.0 : state_float(word),
                solve_converged_in(PF_SOLVER_SECOND) ? 0.0 : state_float(PF_SOLVER_SECOND + word));
#else
    return state_float(word);
#endif
}
#endif

// p >= 0 is imposed when the problem asks for it (the pressure with separation on; never the
// volume correction's potential), except in a singular system: with no AIR cell there is
// nothing to separate into, and the pressure is only defined up to a constant.
bool project_nonnegative() { return state[PF_SOLVER_NONNEGATIVE] != 0u && !solve_singular(); }

// Marks block b's problem converged; once the whole solve has, every later indirect dispatch of
// it becomes empty.
void stop_solve_in(uint b) {
    state[b + PF_SOLVER_CONVERGED] = 1u;
    if (!solve_converged()) return;
    uint records = state[PF_SOLVER_RECORDS];
    for (uint k = 0u; k < records; ++k) state[PF_SOLVER_SCALARS + 4u * k] = 0u;
}

// Books the iterations of the round that just ended (round 0 apart from the later ones: a later
// round starts from a nearly converged pressure and needs far fewer).
void finish_round_in(uint b) {
    uint done = state[b + PF_SOLVER_ITERATIONS] - state[b + PF_SOLVER_ROUND_START];
    if (state[b + PF_SOLVER_ROUND] == 0u)
        state[b + PF_SOLVER_FIRST_ROUND] = done;
    else
        state[b + PF_SOLVER_LATER_ROUNDS] = max(state[b + PF_SOLVER_LATER_ROUNDS], done);
}
void finish_round() { finish_round_in(0u); }

// Relative residual from r.r and b.b (0 when both are 0; 1 for a residual with b = 0).
float relative_residual(float rr, float bb) {
    if (bb > 0.0) return sqrt(max(rr, 0.0) / bb);
    return rr > 0.0 ? 1.0 : 0.0;
}
