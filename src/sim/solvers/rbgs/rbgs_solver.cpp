#include "sim/solvers/rbgs/rbgs_solver.h"

#include <string>

#include "solvers/common/solver_state.h"

namespace pf {

pf_result RedBlackSolver::init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid, const Log& log,
                               const char* fn) {
    std::string error = control_.init(gl, runner, grid);
    if (error.empty()) error = runner.prepare(gl::ProgramId::gauss_seidel);
    if (!error.empty()) return log.error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
    stat_ = runner.add_stat("rbgs", PF_PASS_PRESSURE_SOLVE);
    return PF_OK;
}

void RedBlackSolver::sweep(PassRunner& runner, const PressureProblem& problem) {
    for (uint32_t color = 0; color < 2; ++color) {
        runner.run({gl::ProgramId::gauss_seidel,
                    stat_,
                    0,
                    {{PF_SLOT_CELL_TYPE, &problem.cell_type},
                     {PF_SLOT_RHS, &problem.rhs},
                     {PF_SLOT_SOLVER_X, &problem.pressure},
                     {PF_SLOT_SOLVER_STATE, &control_.state()}},
                    control_.record(0),
                    {control_.dims_uniform(), Uniform::uint1(PF_LOC_SOLVER_COLOR, color),
                     Uniform::float1(PF_LOC_SOLVER_OMEGA, problem.params.sor_omega)}});
    }
}

void RedBlackSolver::solve(PassRunner& runner, const PressureProblem& problem) {
    const uint32_t iterations = issued_iterations(problem);
    control_.begin(runner, stat_, problem);
    uint32_t checked = 0;
    const bool early_checks = early_checks_worthwhile(problem);
    for (uint32_t k = 1; k <= iterations; ++k) {
        sweep(runner, problem);
        if (early_checks && k < iterations && k % kCheckEvery == 0) {
            control_.check(runner, stat_, problem, k - checked);
            checked = k;
        }
    }
    control_.check(runner, stat_, problem, iterations - checked);
    control_.finish(runner, stat_, problem);
}

}  // namespace pf
