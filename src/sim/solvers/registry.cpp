// The one place that maps pf_pressure_solver values to solver classes.
#include "sim/solvers/cg/cg_solver.h"
#include "sim/solvers/jacobi/jacobi_solver.h"
#include "sim/solvers/mgpcg/multigrid.h"
#include "sim/solvers/pressure_solver.h"
#include "sim/solvers/rbgs/rbgs_solver.h"

namespace pf {

std::unique_ptr<PressureSolver> make_pressure_solver(pf_pressure_solver kind, bool pairs) {
    switch (kind) {
        case PF_PRESSURE_SOLVER_JACOBI: return std::make_unique<JacobiSolver>();
        case PF_PRESSURE_SOLVER_RBGS: return std::make_unique<RedBlackSolver>();
        case PF_PRESSURE_SOLVER_CG:
            return std::make_unique<ConjugateGradientSolver>(ConjugateGradientSolver::Preconditioner::none, "cg");
        case PF_PRESSURE_SOLVER_PCG:
            return std::make_unique<ConjugateGradientSolver>(ConjugateGradientSolver::Preconditioner::jacobi, "pcg");
        case PF_PRESSURE_SOLVER_MGPCG:
            return std::make_unique<ConjugateGradientSolver>(ConjugateGradientSolver::Preconditioner::stored, "mgpcg",
                                                             std::make_unique<Multigrid>(Multigrid::Coarse::geometric), pairs);
        case PF_PRESSURE_SOLVER_MGPCG_GALERKIN:
            return std::make_unique<ConjugateGradientSolver>(ConjugateGradientSolver::Preconditioner::stored, "mgpcg_galerkin",
                                                             std::make_unique<Multigrid>(Multigrid::Coarse::galerkin), pairs);
        default: return nullptr;
    }
}

}  // namespace pf
