// Red-black Gauss-Seidel with over-relaxation (SOR, params.sor_omega): one iteration updates
// the cells with i+j+k even, then the odd ones, in place (each colour reads only the other).
// With separation on, every update is projected onto p >= 0 (projected SOR). Stops after
// params.pressure_iterations iterations or at a residual check (every kCheckEvery iterations)
// that meets params.pressure_tolerance (while recent solves ended within ten times of it).
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
    // One red and one black half-sweep; skipped (indirectly) once the solve has converged.
    void sweep(PassRunner& runner, const PressureProblem& problem);

    SolveControl control_;
    StatId stat_ = 0;
};

}  // namespace pf
