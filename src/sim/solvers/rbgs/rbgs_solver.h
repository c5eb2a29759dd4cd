// Red-black Gauss-Seidel with over-relaxation (SOR, params.sor_omega): one iteration updates
// the cells with i+j+k even, then the odd ones, in place (each colour reads only the other).
// With separation on, every update is projected onto p >= 0 (projected SOR). Stops after
// params.pressure_iterations iterations or at a residual check (every kCheckEvery iterations)
// that meets params.pressure_tolerance.
#pragma once
#include "sim/solvers/common/solve_control.h"
#include "sim/solvers/pressure_solver.h"

namespace pf {

class RedBlackSolver final : public PressureSolver {
public:
    static constexpr uint32_t kCheckEvery = 4;

    pf_result init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid, const Log& log,
                   const char* fn) override;
    void solve(PassRunner& runner, const PressureProblem& problem) override;

private:
    const gl::Api* gl_ = nullptr;
    SolverGrid grid_{};
    SolveControl control_;
    StatId stat_ = 0;
};

// One red and one black sweep of projected (when separation is on) SOR over the fine grid,
// dispatched through `indirect` (or directly when it has no buffer). Shared by the red-black
// solver and the Krylov solvers' separation step.
void red_black_sweep(PassRunner& runner, const gl::Api& gl, StatId stat, const PressureProblem& problem,
                     const SolveControl& control, float omega, Indirect indirect);

}  // namespace pf
