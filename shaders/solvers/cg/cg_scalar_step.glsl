// Conjugate gradients' scalar steps between the cell-wide kernels, decided on the GPU so the
// CPU never waits. Each runs in the last workgroup of the reduction pass that made its partial
// sums (orbit_main.glsl, PF_LAST_GROUP), with the partials added up in a fixed order: a pass of
// its own (one workgroup) cost as much as a cell-wide pass on the H100.
// PF_CG_STEP_START (after the first r and z) and PF_CG_STEP_BETA (after an update) take the sums (r.r,
// r.z, sum z, sum r), remove the null-space mean m of z when the system is singular
// (r.(z - m) = r.z - m sum r), test |r| / |b| against the tolerance and the iteration cap
// (stopping the problem there) and form beta; PF_CG_STEP_ALPHA takes p.A p and forms alpha =
// r.z / p.A p, stopping the problem if p.A p is not positive (no further progress is possible in
// float). A pair solve (PF_PAIR 1) runs the step for each problem on its own block of scalars
// (state.glsl); its records empty once both have stopped.
// Requires `state` (solvers/common/state.glsl).
void cg_scalar_step_in(uint b, uint step, vec4 t) {
    if (solve_converged_in(b)) return;
    if (step == PF_CG_STEP_ALPHA) {
        float rz = state_float(b + PF_SOLVER_RZ);
        if (!(t.x > 0.0) || !(rz > 0.0)) {
            stop_solve_in(b);
            return;
        }
        set_state_float(b + PF_SOLVER_ALPHA, rz / t.x);
        return;
    }
    float fluid = float(state[b + PF_SOLVER_FLUID_CELLS]);
    float m = state[b + PF_SOLVER_SINGULAR] != 0u && fluid > 0.0 ? t.z / fluid : 0.0;
    float rz = t.y - m * t.w;
    float rel = relative_residual(t.x, state_float(b + PF_SOLVER_BB));
    set_state_float(b + PF_SOLVER_RESIDUAL, rel);
    if (step == PF_CG_STEP_BETA) state[b + PF_SOLVER_ITERATIONS] += 1u;
    if (rel <= state_float(b + PF_SOLVER_TOLERANCE) || !(rz > 0.0) ||
        state[b + PF_SOLVER_ITERATIONS] >= state[b + PF_SOLVER_ITERATION_CAP]) {
        stop_solve_in(b);
        return;
    }
    set_state_float(b + PF_SOLVER_BETA, step == PF_CG_STEP_BETA ? rz / state_float(b + PF_SOLVER_RZ) : 0.0);
    set_state_float(b + PF_SOLVER_RZ, rz);
    set_state_float(b + PF_SOLVER_Z_MEAN, m);
}

#if PF_PAIR
// PF_CG_STEP_ALPHA: t = (p.A p of the first problem, of the second, 0, 0).
void cg_scalar_step(uint step, vec4 t) {
    cg_scalar_step_in(0u, step, vec4(t.x, 0.0, 0.0, 0.0));
    cg_scalar_step_in(PF_SOLVER_SECOND, step, vec4(t.y, 0.0, 0.0, 0.0));
}
// The other steps: a column of sums per problem.
void cg_scalar_step(uint step, mat2x4 t) {
    cg_scalar_step_in(0u, step, t[0]);
    cg_scalar_step_in(PF_SOLVER_SECOND, step, t[1]);
}
#else
void cg_scalar_step(uint step, vec4 t) { cg_scalar_step_in(0u, step, t); }
#endif
