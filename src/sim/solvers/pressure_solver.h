// The interface every pressure solver implements, and the one factory that maps
// pf_pressure_solver to an implementation. A solver owns its buffers, programs and statistics
// entries; it receives the Poisson problem of one substep and leaves the solution in
// `pressure`. Adding a solver: a folder src/sim/solvers/<name>/ (the class), its kernels in
// shaders/solvers/<name>/ (+ lines in shaders/permutations.inc), a pf_pressure_solver value,
// and one case in make_pressure_solver (docs/design.md, "Adding a pressure solver").
#pragma once
#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

#include "api/log.h"
#include "gl/buffer.h"
#include "gl/gl.h"
#include "pf/pf.h"
#include "sim/grid_layout.h"
#include "sim/pass_runner.h"

namespace pf {

// The grid a solver works on (fixed for the simulation's lifetime).
struct SolverGrid {
    GridLayout layout{};
    // The reduction kernels run one invocation a cell instead of one a mirror orbit, the same sums
    // bit for bit (shaders/solvers/common/orbit_main.glsl; Simulation::kOneCellReductionOrbits).
    bool one_cell_an_invocation = false;
};

// One substep's problem: A p = rhs on FLUID cells (cell_type), p = 0 in AIR; `pressure` holds
// the previous substep's solution (a warm start) and receives the new one. `status` is the
// simulation's status buffer (solvers report iterations and residual into it).
// `recent_iterations` is what this solver needed in the first round of a solve in a recent step,
// and `recent_later_iterations` in one later round (active-set rounds start nearly converged),
// read back a few steps late (kUnknownIterations: not known yet). Every issued iteration costs dispatches even after the GPU
// has found convergence and emptied them, so solvers issue only a margin above it
// (issued_iterations); a solve that needs more stops early, reports its residual, and the
// next steps issue more.
constexpr uint32_t kUnknownIterations = 0xffffffffu;

struct PressureProblem {
    const gl::Buffer& cell_type;
    const gl::Buffer& rhs;
    const gl::Buffer& pressure;
    const gl::Buffer& status;
    const pf_sim_params& params;
    uint32_t recent_iterations = kUnknownIterations;
    uint32_t recent_later_iterations = kUnknownIterations;
    bool recent_converged = false;  // that step's final residual met the tolerance
    float recent_residual = -1.0f;  // that step's final relative residual (< 0: not known)
};

// Whether a stationary solver should check convergence before its last iteration: not while
// recent solves ended more than ten times above the tolerance (their checks could not stop
// anything; each costs two passes), and always until a residual is known.
inline bool early_checks_worthwhile(const PressureProblem& problem) {
    return problem.recent_residual < 0.0f || problem.recent_residual <= 10.0f * problem.params.pressure_tolerance;
}

// Iterations to issue for one solve round: all of params.pressure_iterations until the solver's
// needs are known; then the recent need of any round plus a quarter (at least 2) while recent
// solves met the tolerance, plus a half and 4 when they did not (they may have been cut short),
// within the cap. (Issuing later active-set rounds by their own, smaller, recent need was
// measured on the H100: it saved 5% of the time and cut those rounds short — the residual grew
// fifteenfold.)
// The same rule for any iterative solve (the viscosity's too): `recent` iterations needed
// lately (kUnknownIterations: not known), whether those solves met their tolerance, the cap.
inline uint32_t issued_iterations(uint32_t cap, uint32_t recent, bool recent_converged) {
    if (recent == kUnknownIterations) return cap;
    const uint64_t margin = recent_converged ? recent + (recent / 4 > 2 ? recent / 4 : 2) : recent + recent / 2 + 4;
    return uint32_t(margin < cap ? margin : cap);
}
inline uint32_t issued_iterations(const PressureProblem& problem) {
    uint32_t recent = problem.recent_iterations;
    if (recent != kUnknownIterations && problem.recent_later_iterations != kUnknownIterations)
        recent = recent > problem.recent_later_iterations ? recent : problem.recent_later_iterations;
    return issued_iterations(problem.params.pressure_iterations, recent, problem.recent_converged);
}

class PressureSolver {
public:
    virtual ~PressureSolver() = default;
    // Allocates buffers, builds programs and registers statistics entries. Errors are logged
    // (prefixed with `fn`) and returned; the solver is unusable then.
    virtual pf_result init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid, const Log& log,
                           const char* fn) = 0;
    // Records the solve of one substep into the GL command stream (no CPU wait).
    virtual void solve(PassRunner& runner, const PressureProblem& problem) = 0;
    // Whether solve_pair() is available: MGPCG made for pairs (make_pressure_solver's `pairs`).
    virtual bool solves_pairs() const { return false; }
    // Records the solves of two problems on the same cell types in the same passes (a pair solve,
    // docs/design.md §4.6): `first` and `second` each as solve() would, neither with separation.
    // Only where solves_pairs(); any other solver records nothing.
    virtual void solve_pair(PassRunner& runner, const PressureProblem& first, const PressureProblem& second) {
        (void)runner, (void)first, (void)second;
    }
};

// A new, uninitialised solver of `kind`, or nullptr for an unknown kind; `pairs`: one that also
// solves pairs where the kind can (MGPCG).
std::unique_ptr<PressureSolver> make_pressure_solver(pf_pressure_solver kind, bool pairs = false);

}  // namespace pf
