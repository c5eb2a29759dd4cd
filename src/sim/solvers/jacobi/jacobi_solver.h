// Weighted Jacobi (the original's solver): sweeps ping-pong between the problem's pressure
// buffer and a scratch buffer, projected onto p >= 0 after every sweep when separation is on
// (projected Jacobi). Stops after params.pressure_iterations sweeps, or earlier at a residual
// check (every kCheckEvery sweeps) that meets params.pressure_tolerance (while recent solves ended within ten times of it).
#pragma once
#include "sim/solvers/common/solve_control.h"
#include "sim/solvers/pressure_solver.h"

namespace pf {

class JacobiSolver final : public PressureSolver {
public:
    static constexpr uint32_t kCheckEvery = 8;

    pf_result init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid, const Log& log,
                   const char* fn) override;
    void solve(PassRunner& runner, const PressureProblem& problem) override;

private:
    SolverGrid grid_{};
    SolveControl control_;
    gl::Buffer scratch_;
    StatId stat_ = 0;
};

}  // namespace pf
