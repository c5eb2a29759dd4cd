#include "sim/solvers/jacobi/jacobi_solver.h"

#include <string>

#include "solvers/jacobi/jacobi_locations.h"

namespace pf {

pf_result JacobiSolver::init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid, const Log& log,
                             const char* fn) {
    grid_ = grid;
    scratch_ = gl::Buffer(gl, size_t(grid.layout.cells()) * 4, GL_DYNAMIC_COPY, "jacobi_scratch");
    std::string error = control_.init(gl, runner, grid);
    if (error.empty()) error = runner.prepare(gl::ProgramId::jacobi);
    if (!error.empty()) return log.error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
    stat_ = runner.add_stat("jacobi", PF_PASS_PRESSURE_SOLVE);
    return PF_OK;
}

void JacobiSolver::solve(PassRunner& runner, const PressureProblem& problem) {
    const uint32_t sweeps = issued_iterations(problem);
    control_.begin(runner, stat_, problem);
    // Sweeps alternate direction; an odd count starts from a copy in the scratch buffer, so
    // every sweep with the parity of the last one writes the problem's pressure buffer. Checks
    // (which read that buffer) come after such sweeps only.
    const gl::Buffer* src = &problem.pressure;
    const gl::Buffer* dst = &scratch_;
    if (sweeps % 2 == 1) {
        runner.copy(problem.pressure, scratch_, size_t(grid_.layout.cells()) * 4);
        std::swap(src, dst);
    }
    uint32_t checked = 0;
    const bool early_checks = early_checks_worthwhile(problem);
    for (uint32_t k = 1; k <= sweeps; ++k) {
        runner.run({gl::ProgramId::jacobi,
                    stat_,
                    0,
                    {{PF_SLOT_CELL_TYPE, &problem.cell_type},
                     {PF_SLOT_RHS, &problem.rhs},
                     {PF_SLOT_PRESSURE, src},
                     {PF_SLOT_PRESSURE_OUT, dst},
                     {PF_SLOT_SOLVER_STATE, &control_.state()}},
                    control_.record(0),
                    {control_.dims_uniform(), Uniform::float1(PF_LOC_JACOBI_OMEGA, problem.params.jacobi_omega)}});
        std::swap(src, dst);
        if (early_checks && k < sweeps && k % kCheckEvery == sweeps % kCheckEvery) {
            control_.check(runner, stat_, problem, k - checked);
            checked = k;
        }
    }
    control_.check(runner, stat_, problem, sweeps - checked);
    control_.finish(runner, stat_, problem);
}

}  // namespace pf
