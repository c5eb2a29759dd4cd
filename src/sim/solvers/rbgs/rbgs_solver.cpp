#include "sim/solvers/rbgs/rbgs_solver.h"

#include <string>

#include "solvers/common/solver_state.h"

namespace pf {

void red_black_sweep(PassRunner& runner, const gl::Api& gl, StatId stat, const PressureProblem& problem,
                     const SolveControl& control, float omega, Indirect indirect) {
    const GLuint program = runner.program(gl::ProgramId::gauss_seidel);
    const SolverGrid grid{control.dims(), uint32_t(control.dims().x * control.dims().y * control.dims().z)};
    gl.ProgramUniform1f(program, PF_LOC_SOLVER_OMEGA, omega);
    for (uint32_t color = 0; color < 2; ++color) {
        gl.ProgramUniform1ui(program, PF_LOC_SOLVER_COLOR, color);
        runner.run({gl::ProgramId::gauss_seidel,
                    stat,
                    grid.cells,
                    {{PF_SLOT_CELL_TYPE, &problem.cell_type},
                     {PF_SLOT_RHS, &problem.rhs},
                     {PF_SLOT_SOLVER_X, &problem.pressure},
                     {PF_SLOT_SOLVER_STATE, &control.state()}},
                    indirect});
    }
}

pf_result RedBlackSolver::init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid, const Log& log,
                               const char* fn) {
    gl_ = &gl;
    grid_ = grid;
    std::string error = control_.init(gl, runner, grid);
    if (error.empty()) error = runner.prepare(gl::ProgramId::gauss_seidel);
    if (!error.empty()) return log.error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
    control_.set_dims(runner.program(gl::ProgramId::gauss_seidel), grid.size);
    stat_ = runner.add_stat("rbgs", PF_PASS_PRESSURE_SOLVE);
    return PF_OK;
}

void RedBlackSolver::solve(PassRunner& runner, const PressureProblem& problem) {
    const uint32_t iterations = problem.params.pressure_iterations;
    control_.begin(runner, stat_, problem);
    uint32_t checked = 0;
    for (uint32_t k = 1; k <= iterations; ++k) {
        red_black_sweep(runner, *gl_, stat_, problem, control_, problem.params.sor_omega, control_.record(0));
        if (k < iterations && k % kCheckEvery == 0) {
            control_.check(runner, stat_, problem, k - checked);
            checked = k;
        }
    }
    control_.check(runner, stat_, problem, iterations - checked);
    control_.finish(runner, stat_, problem);
}

}  // namespace pf
