// The one place that maps pf_pressure_solver values to solver classes.
#include "sim/solvers/jacobi/jacobi_solver.h"
#include "sim/solvers/pressure_solver.h"

namespace pf {

std::unique_ptr<PressureSolver> make_pressure_solver(pf_pressure_solver kind) {
    switch (kind) {
        case PF_PRESSURE_SOLVER_JACOBI: return std::make_unique<JacobiSolver>();
        default: return nullptr;
    }
}

}  // namespace pf
