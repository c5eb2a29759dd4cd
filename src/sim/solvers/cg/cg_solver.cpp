#include "sim/solvers/cg/cg_solver.h"

#include <algorithm>
#include <string>

#include "solvers/common/solver_state.h"

namespace pf {

using gl::ProgramId;

ConjugateGradientSolver::ConjugateGradientSolver(Preconditioner kind, const char* name,
                                                 std::unique_ptr<StoredPreconditioner> stored, bool pairs)
    : kind_(kind), name_(name), stored_(std::move(stored)), pairs_(pairs && stored_) {}

ProgramId ConjugateGradientSolver::init_program(bool pair) const {
    switch (kind_) {
        case Preconditioner::none: return control_.reduction(ProgramId::cg_init_none);
        case Preconditioner::jacobi: return control_.reduction(ProgramId::cg_init_jacobi);
        default: return control_.program(ProgramId::cg_init_stored, pair);
    }
}

ProgramId ConjugateGradientSolver::update_program(bool pair) const {
    switch (kind_) {
        case Preconditioner::none: return control_.reduction(ProgramId::cg_update_none);
        case Preconditioner::jacobi: return control_.reduction(ProgramId::cg_update_jacobi);
        default: return control_.program(ProgramId::cg_update_stored, pair);
    }
}

ProgramId ConjugateGradientSolver::matvec_program(bool pair) const {
    switch (kind_) {
        case Preconditioner::none: return control_.reduction(ProgramId::cg_matvec_none);
        case Preconditioner::jacobi: return control_.reduction(ProgramId::cg_matvec_jacobi);
        default: return control_.program(ProgramId::cg_matvec_stored, pair);
    }
}

pf_result ConjugateGradientSolver::init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid,
                                        const Log& log, const char* fn) {
    grid_ = grid;
    const size_t bytes = size_t(grid.layout.cells()) * (pairs_ ? 8 : 4);  // a pair solve's vectors hold two values a cell
    r_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "cg_r");
    p_[0] = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "cg_p");
    p_[1] = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "cg_p");
    q_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "cg_q");
    working_type_ = gl::Buffer(gl, size_t(grid.layout.cells()) * 4, GL_DYNAMIC_COPY, "cg_working_type");
    if (kind_ != Preconditioner::none) z_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "cg_z");
    std::string error = control_.init(gl, runner, grid, pairs_);
    const ProgramId programs[] = {init_program(), update_program(), matvec_program(), ProgramId::separation_active_set,
                                  ProgramId::separation_clamp};
    for (ProgramId id : programs) {
        if (!error.empty()) break;
        error = runner.prepare(id);
    }
    if (pairs_) {
        for (ProgramId id : {init_program(true), update_program(true), matvec_program(true)}) {
            if (!error.empty()) break;
            error = runner.prepare(id);
        }
    }
    if (error.empty() && stored_) error = stored_->init(gl, runner, control_);
    if (!error.empty()) return log.error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
    stat_ = runner.add_stat(name_, PF_PASS_PRESSURE_SOLVE);
    if (stored_) precondition_stat_ = runner.add_stat(std::string(name_) + "/precondition", PF_PASS_PRESSURE_SOLVE);
    return PF_OK;
}

void ConjugateGradientSolver::solve(PassRunner& runner, const PressureProblem& problem) {
    if (!problem.params.separation) {
        krylov(runner, problem, false);
        control_.finish(runner, stat_, problem);
        return;
    }
    // Active-set rounds on a working copy of the cell types; the report measures the
    // complementarity residual with the real ones.
    runner.copy(problem.cell_type, working_type_, size_t(grid_.layout.cells()) * 4);
    const PressureProblem working{working_type_,  problem.rhs,    problem.pressure,
                                  problem.status, problem.params, problem.recent_iterations,
                                  problem.recent_later_iterations, problem.recent_converged,
                                  problem.recent_residual};
    const Pass clamp{ProgramId::separation_clamp,
                     stat_,
                     grid_.layout.cells(),
                     {{PF_SLOT_CELL_TYPE, &problem.cell_type},
                      {PF_SLOT_SOLVER_X, &problem.pressure},
                      {PF_SLOT_SOLVER_STATE, &control_.state()}},
                     {},
                     {control_.dims_uniform()}};
    krylov(runner, working, false);
    for (uint32_t round = 0; round < kActiveSetRounds; ++round) {
        runner.run({ProgramId::separation_active_set,
                    stat_,
                    grid_.layout.cells(),
                    {{PF_SLOT_CELL_TYPE, &problem.cell_type},
                     {PF_SLOT_RHS, &problem.rhs},
                     {PF_SLOT_SOLVER_X, &problem.pressure},
                     {PF_SLOT_SOLVER_WORKING_TYPE, &working_type_},
                     {PF_SLOT_SOLVER_STATE, &control_.state()}},
                    {},
                    {control_.dims_uniform()}});
        runner.run(clamp);
        krylov(runner, working, true);
    }
    runner.run(clamp);
    control_.finish(runner, stat_, problem);
}

void ConjugateGradientSolver::solve_pair(PassRunner& runner, const PressureProblem& first,
                                         const PressureProblem& second) {
    if (!pairs_) return;
    krylov(runner, first, false, &second);
    control_.finish(runner, stat_, first, &second);
}

void ConjugateGradientSolver::krylov(PassRunner& runner, const PressureProblem& problem, bool another_round,
                                     const PressureProblem* second) {
    const gl::Buffer& type = problem.cell_type;
    const gl::Buffer& x = problem.pressure;
    const gl::Buffer& state = control_.state();
    const gl::Buffer& partials = control_.partials();
    const Indirect orbits = control_.orbit_record();
    const Uniform dims = control_.dims_uniform();
    const bool pair = second != nullptr;
    // The preconditioner's last pass sums z and runs the scalar step `step` (cg_scalar_step.glsl).
    auto precondition = [&](bool first_sweep_done, uint32_t step) {
        stored_->apply(runner, precondition_stat_, type, r_, z_, first_sweep_done, step, pair);
    };
    // z: r itself without a preconditioner, else the z buffer (Jacobi's is written by init and
    // update; plain CG's kernels leave z_out's slot unused).
    const Bind z = kind_ == Preconditioner::none ? Bind{PF_SLOT_SOLVER_R, &r_} : Bind{PF_SLOT_SOLVER_Z, &z_};
    const gl::Buffer& z_out = kind_ == Preconditioner::none ? r_ : z_;
    // Iterations issued: a pair issues what either problem asks, and each stops at its own count.
    uint32_t issued = issued_iterations(problem);
    if (pair) {
        const uint32_t caps[2] = {issued, issued_iterations(*second)};
        issued = std::max(caps[0], caps[1]);
        control_.begin_pair(runner, stat_, problem, *second, caps);
    } else {
        control_.begin(runner, stat_, problem, another_round);
    }
    if (stored_) stored_->begin(runner, precondition_stat_, type);
    if (stored_) {
        // r per cell; the preconditioner sums z and runs the start step.
        Bindings binds{{PF_SLOT_CELL_TYPE, &type}, {PF_SLOT_RHS, &problem.rhs}, {PF_SLOT_SOLVER_X, &x},
                       {PF_SLOT_SOLVER_R, &r_}, {PF_SLOT_SOLVER_STATE, &state}};
        if (pair) {
            binds.add({PF_SLOT_SOLVER_RHS_SECOND, &second->rhs});
            binds.add({PF_SLOT_SOLVER_X_SECOND, &second->pressure});
        }
        runner.run({init_program(pair), stat_, grid_.layout.cells(), binds, {}, {dims}});
        precondition(false, PF_CG_STEP_START);
    } else {
        // r, z and their sums per orbit; the last workgroup runs the start step.
        runner.run({init_program(), stat_, control_.orbit_count(),
                    {{PF_SLOT_CELL_TYPE, &type}, {PF_SLOT_RHS, &problem.rhs}, {PF_SLOT_SOLVER_X, &x},
                     {PF_SLOT_SOLVER_R, &r_}, {PF_SLOT_SOLVER_PARTIALS, &partials}, {PF_SLOT_SOLVER_STATE, &state},
                     {PF_SLOT_SOLVER_Z_INIT, &z_out}},
                    {}, {dims}});
    }
    for (uint32_t k = 0; k < issued; ++k) {
        // The direction from z and the previous one (alternating buffers), q = A p, p.q; the
        // last workgroup forms alpha.
        const gl::Buffer& p_old = p_[k % 2];
        const gl::Buffer& p = p_[(k + 1) % 2];
        runner.run({matvec_program(pair), stat_, 0,
                    {{PF_SLOT_CELL_TYPE, &type}, z, {PF_SLOT_SOLVER_P, &p_old}, {PF_SLOT_SOLVER_P_NEXT, &p},
                     {PF_SLOT_SOLVER_Q, &q_}, {PF_SLOT_SOLVER_PARTIALS, &partials}, {PF_SLOT_SOLVER_STATE, &state}},
                    orbits, {dims}});
        if (stored_) {
            // x, r per cell and the V-cycle's first half-sweep; the V-cycle's last pass forms beta.
            Bindings binds{{PF_SLOT_CELL_TYPE, &type}, {PF_SLOT_SOLVER_X, &x},
                           {PF_SLOT_SOLVER_R, &r_},       {PF_SLOT_SOLVER_P, &p},
                           {PF_SLOT_SOLVER_Q, &q_},       {PF_SLOT_SOLVER_STATE, &state},
                           {PF_SLOT_SOLVER_MG_START, &stored_->first_sweep()}};
            if (pair) binds.add({PF_SLOT_SOLVER_UPDATE_X_SECOND, &second->pressure});
            runner.run({update_program(pair), stat_, 0, binds, control_.record(0), {dims}});
            precondition(true, PF_CG_STEP_BETA);
        } else {
            // x, r, z and their sums per orbit; the last workgroup forms beta.
            runner.run({update_program(), stat_, 0,
                        {{PF_SLOT_CELL_TYPE, &type}, {PF_SLOT_SOLVER_X, &x}, {PF_SLOT_SOLVER_R, &r_},
                         {PF_SLOT_SOLVER_P, &p}, {PF_SLOT_SOLVER_Q, &q_}, {PF_SLOT_SOLVER_PARTIALS, &partials},
                         {PF_SLOT_SOLVER_STATE, &state}, {PF_SLOT_SOLVER_Z, &z_out}},
                        orbits, {dims}});
        }
    }
}

}  // namespace pf
