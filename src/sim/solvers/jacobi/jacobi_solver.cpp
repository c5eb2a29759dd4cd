#include "sim/solvers/jacobi/jacobi_solver.h"

#include <string>

#include "solvers/jacobi/jacobi_locations.h"

namespace pf {

pf_result JacobiSolver::init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid, const Log& log,
                             const char* fn) {
    gl_ = &gl;
    grid_ = grid;
    scratch_ = gl::Buffer(gl, size_t(grid.cells) * 4, GL_DYNAMIC_COPY);
    if (std::string error = runner.prepare(gl::ProgramId::jacobi); !error.empty())
        return log.error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
    stat_ = runner.add_stat("jacobi", PF_PASS_PRESSURE_SOLVE);
    return PF_OK;
}

void JacobiSolver::solve(PassRunner& runner, const PressureProblem& problem) {
    const uint32_t sweeps = problem.params.pressure_iterations;
    gl_->ProgramUniform1f(runner.program(gl::ProgramId::jacobi), PF_LOC_JACOBI_OMEGA, problem.params.jacobi_omega);
    // Sweeps alternate direction; an odd count starts from a copy in the scratch buffer so the
    // last sweep always writes the problem's pressure buffer.
    const gl::Buffer* src = &problem.pressure;
    const gl::Buffer* dst = &scratch_;
    if (sweeps % 2 == 1) {
        gl_->BindBuffer(GL_COPY_READ_BUFFER, problem.pressure.id());
        gl_->BindBuffer(GL_COPY_WRITE_BUFFER, scratch_.id());
        gl_->CopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, GLsizeiptr(grid_.cells) * 4);
        std::swap(src, dst);
    }
    for (uint32_t k = 0; k < sweeps; ++k) {
        runner.run({gl::ProgramId::jacobi,
                    stat_,
                    grid_.cells,
                    {{PF_SLOT_CELL_TYPE, &problem.cell_type},
                     {PF_SLOT_RHS, &problem.rhs},
                     {PF_SLOT_PRESSURE, src},
                     {PF_SLOT_PRESSURE_OUT, dst}}});
        std::swap(src, dst);
    }
}

}  // namespace pf
