// Weighted Jacobi (the original's solver): params.pressure_iterations sweeps, ping-ponging
// between the problem's pressure buffer and a scratch buffer; projected onto p >= 0 after
// every sweep when params.separation is on (projected Jacobi).
#pragma once
#include "sim/solvers/pressure_solver.h"

namespace pf {

class JacobiSolver final : public PressureSolver {
public:
    pf_result init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid, const Log& log,
                   const char* fn) override;
    void solve(PassRunner& runner, const PressureProblem& problem) override;

private:
    const gl::Api* gl_ = nullptr;
    SolverGrid grid_{};
    gl::Buffer scratch_;
    StatId stat_ = 0;
};

}  // namespace pf
