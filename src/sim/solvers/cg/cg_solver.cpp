#include "sim/solvers/cg/cg_solver.h"

#include <string>

#include "solvers/common/solver_state.h"

namespace pf {

using gl::ProgramId;

ConjugateGradientSolver::ConjugateGradientSolver(Preconditioner kind, const char* name,
                                                 std::unique_ptr<StoredPreconditioner> stored)
    : kind_(kind), name_(name), stored_(std::move(stored)) {}

ProgramId ConjugateGradientSolver::init_program() const {
    switch (kind_) {
        case Preconditioner::none: return ProgramId::cg_init_none;
        case Preconditioner::jacobi: return ProgramId::cg_init_jacobi;
        default: return ProgramId::cg_init_stored;
    }
}

ProgramId ConjugateGradientSolver::update_program() const {
    switch (kind_) {
        case Preconditioner::none: return ProgramId::cg_update_none;
        case Preconditioner::jacobi: return ProgramId::cg_update_jacobi;
        default: return ProgramId::cg_update_stored;
    }
}

ProgramId ConjugateGradientSolver::direction_program() const {
    switch (kind_) {
        case Preconditioner::none: return ProgramId::cg_direction_none;
        case Preconditioner::jacobi: return ProgramId::cg_direction_jacobi;
        default: return ProgramId::cg_direction_stored;
    }
}

pf_result ConjugateGradientSolver::init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid,
                                        const Log& log, const char* fn) {
    grid_ = grid;
    const size_t bytes = size_t(grid.cells) * 4;
    r_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "cg_r");
    p_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "cg_p");
    q_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "cg_q");
    working_type_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "cg_working_type");
    if (kind_ == Preconditioner::stored) z_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "cg_z");
    std::string error = control_.init(gl, runner, grid);
    const ProgramId programs[] = {init_program(),      update_program(),    direction_program(),
                                  ProgramId::cg_matvec, ProgramId::cg_start, ProgramId::cg_alpha,
                                  ProgramId::cg_beta,   ProgramId::cg_zstats, ProgramId::separation_active_set,
                                  ProgramId::separation_clamp};
    for (ProgramId id : programs) {
        if (!error.empty()) break;
        error = runner.prepare(id);
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
    runner.copy(problem.cell_type, working_type_, size_t(grid_.cells) * 4);
    const PressureProblem working{working_type_,  problem.rhs,    problem.pressure,
                                  problem.status, problem.params, problem.recent_iterations,
                                  problem.recent_later_iterations, problem.recent_converged,
                                  problem.recent_residual};
    const Pass clamp{ProgramId::separation_clamp,
                     stat_,
                     grid_.cells,
                     {{PF_SLOT_CELL_TYPE, &problem.cell_type},
                      {PF_SLOT_SOLVER_X, &problem.pressure},
                      {PF_SLOT_SOLVER_STATE, &control_.state()}},
                     {},
                     {control_.dims_uniform()}};
    krylov(runner, working, false);
    for (uint32_t round = 0; round < kActiveSetRounds; ++round) {
        runner.run({ProgramId::separation_active_set,
                    stat_,
                    grid_.cells,
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

void ConjugateGradientSolver::krylov(PassRunner& runner, const PressureProblem& problem, bool another_round) {
    const gl::Buffer& type = problem.cell_type;
    const gl::Buffer& x = problem.pressure;
    const gl::Buffer& state = control_.state();
    const gl::Buffer& partials = control_.partials();
    const Indirect cells = control_.record(0), orbits = control_.orbit_record();
    const Uniform dims = control_.dims_uniform();
    auto scalars = [&](ProgramId id) {
        runner.run({id, stat_, PF_WORKGROUP_SIZE, {{PF_SLOT_SOLVER_PARTIALS, &partials}, {PF_SLOT_SOLVER_STATE, &state}},
                    {}, {Uniform::uint1(PF_LOC_SOLVER_COUNT, control_.partial_count())}});
    };
    auto precondition = [&] {
        stored_->apply(runner, precondition_stat_, type, r_, z_);
        runner.run({ProgramId::cg_zstats, stat_, 0,
                    {{PF_SLOT_CELL_TYPE, &type}, {PF_SLOT_SOLVER_R, &r_}, {PF_SLOT_SOLVER_Z, &z_},
                     {PF_SLOT_SOLVER_PARTIALS, &partials}},
                    orbits, {dims}});
    };
    auto direction = [&] {
        const Bind source = stored_ ? Bind{PF_SLOT_SOLVER_Z, &z_} : Bind{PF_SLOT_SOLVER_R, &r_};
        runner.run({direction_program(), stat_, 0,
                    {{PF_SLOT_CELL_TYPE, &type}, source, {PF_SLOT_SOLVER_P, &p_}, {PF_SLOT_SOLVER_STATE, &state}},
                    cells, {dims}});
    };

    control_.begin(runner, stat_, problem, another_round);
    if (stored_) stored_->begin(runner, precondition_stat_, type);
    runner.run({init_program(), stat_, control_.orbit_count(),
                {{PF_SLOT_CELL_TYPE, &type}, {PF_SLOT_RHS, &problem.rhs}, {PF_SLOT_SOLVER_X, &x},
                 {PF_SLOT_SOLVER_R, &r_}, {PF_SLOT_SOLVER_PARTIALS, &partials}, {PF_SLOT_SOLVER_STATE, &state}},
                {}, {dims}});
    if (stored_) precondition();
    scalars(ProgramId::cg_start);
    direction();
    const uint32_t issued = issued_iterations(problem);
    for (uint32_t k = 0; k < issued; ++k) {
        runner.run({ProgramId::cg_matvec, stat_, 0,
                    {{PF_SLOT_CELL_TYPE, &type}, {PF_SLOT_SOLVER_P, &p_}, {PF_SLOT_SOLVER_Q, &q_},
                     {PF_SLOT_SOLVER_PARTIALS, &partials}},
                    orbits, {dims}});
        scalars(ProgramId::cg_alpha);
        runner.run({update_program(), stat_, 0,
                    {{PF_SLOT_CELL_TYPE, &type}, {PF_SLOT_SOLVER_X, &x}, {PF_SLOT_SOLVER_R, &r_},
                     {PF_SLOT_SOLVER_P, &p_}, {PF_SLOT_SOLVER_Q, &q_}, {PF_SLOT_SOLVER_PARTIALS, &partials},
                     {PF_SLOT_SOLVER_STATE, &state}},
                    orbits, {dims}});
        if (stored_) precondition();
        scalars(ProgramId::cg_beta);
        if (k + 1 < issued) direction();
    }
}

}  // namespace pf
