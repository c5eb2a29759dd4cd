// Access to a solver's state buffer (solvers/common/solver_state.h): scalars and the
// indirect-dispatch records that convergence switches off.
// Requires the kernel to declare `state` (uint[]) before including this file.
float state_float(uint word) { return uintBitsToFloat(state[word]); }
void set_state_float(uint word, float v) { state[word] = floatBitsToUint(v); }

// Mean of b removed from the right-hand side (non-zero only for a singular system).
float rhs_mean() { return state_float(PF_SOLVER_B_MEAN); }
bool solve_singular() { return state[PF_SOLVER_SINGULAR] != 0u; }
bool solve_converged() { return state[PF_SOLVER_CONVERGED] != 0u; }

// p >= 0 is imposed when the problem asks for it (the pressure with separation on; never the
// volume correction's potential), except in a singular system: with no AIR cell there is
// nothing to separate into, and the pressure is only defined up to a constant.
bool project_nonnegative() { return state[PF_SOLVER_NONNEGATIVE] != 0u && !solve_singular(); }

// Marks the solve converged and makes every later indirect dispatch of it empty.
void stop_solve() {
    state[PF_SOLVER_CONVERGED] = 1u;
    uint records = state[PF_SOLVER_RECORDS];
    for (uint k = 0u; k < records; ++k) state[PF_SOLVER_SCALARS + 4u * k] = 0u;
}

// Books the iterations of the round that just ended (round 0 apart from the later ones: a later
// round starts from a nearly converged pressure and needs far fewer).
void finish_round() {
    uint done = state[PF_SOLVER_ITERATIONS] - state[PF_SOLVER_ROUND_START];
    if (state[PF_SOLVER_ROUND] == 0u)
        state[PF_SOLVER_FIRST_ROUND] = done;
    else
        state[PF_SOLVER_LATER_ROUNDS] = max(state[PF_SOLVER_LATER_ROUNDS], done);
}

// Relative residual from r.r and b.b (0 when both are 0; 1 for a residual with b = 0).
float relative_residual(float rr, float bb) {
    if (bb > 0.0) return sqrt(max(rr, 0.0) / bb);
    return rr > 0.0 ? 1.0 : 0.0;
}
