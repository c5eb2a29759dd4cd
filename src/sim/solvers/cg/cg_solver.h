// Preconditioned conjugate gradients, matrix-free on the GPU: plain CG (no preconditioner),
// PCG with the Jacobi (diagonal) preconditioner, and — through StoredPreconditioner — CG with a
// preconditioner that writes z = M^-1 r into a buffer (the multigrid V-cycle of MGPCG).
// Warm-started from the previous substep's pressure; every scalar (alpha, beta, the residual
// test) is formed on the GPU by the last workgroup of the pass that sums its terms, and
// convergence empties the remaining iterations' indirect dispatches. An iteration is two passes
// (the direction with A p, the update) plus the stored preconditioner's. A singular system (no
// AIR cell) is made consistent by removing the mean of b, and the mean of z is removed every
// iteration (the null space is the constants). With separation on (p >= 0), the unconstrained solve is followed by
// kActiveSetRounds primal-dual active-set rounds: cells with p < 0 are held at p = 0, held
// cells whose residual asks for pressure are released, and the system is solved again from
// the current pressure (docs/design.md §4.6).
#pragma once
#include <memory>

#include "sim/solvers/common/solve_control.h"
#include "sim/solvers/pressure_solver.h"

namespace pf {

// A preconditioner that reads r and writes z (both fine-grid cell buffers), and CG's sums of z.
class StoredPreconditioner {
public:
    virtual ~StoredPreconditioner() = default;
    virtual std::string init(const gl::Api& gl, PassRunner& runner, SolveControl& control) = 0;
    // Allocates for pair solves too when control.pairs() (values of two problems a cell).
    // Once per Krylov solve, before the first apply: the system's cell types are fixed until the next.
    virtual void begin(PassRunner& runner, StatId stat, const gl::Buffer& cell_type) = 0;
    // Where CG's update writes the preconditioner's first step, which needs only each cell's
    // new r: r / diag on red FLUID cells, 0 elsewhere (cg_update_stored.comp).
    virtual const gl::Buffer& first_sweep() const = 0;
    // z = M^-1 r on FLUID cells of `cell_type`; its last pass sums (r.r, r.z, sum z, sum r) over
    // the control's orbits and runs CG's scalar step `cg_step` (PF_CG_STEP_START or _BETA) in its
    // last workgroup (shaders/solvers/cg/cg_scalar_step.glsl). Dispatches through the control's
    // records so a converged solve skips it. `first_sweep_done`: CG's update wrote
    // first_sweep() from this r. M must be symmetric positive definite (CG requires it).
    // `pair`: r and z hold two problems' values (a pair solve, SolveControl), each preconditioned alone.
    virtual void apply(PassRunner& runner, StatId stat, const gl::Buffer& cell_type, const gl::Buffer& r,
                       const gl::Buffer& z, bool first_sweep_done, uint32_t cg_step, bool pair) = 0;
};

class ConjugateGradientSolver final : public PressureSolver {
public:
    enum class Preconditioner { none, jacobi, stored };
    // Rounds measured on the adversarial test problem (tests/internal/test_solvers.cpp): the
    // complementarity residual is 0.127 after the unconstrained solve, 0.075 after 2 rounds,
    // 3e-3 after 4, at the tolerance after 8. A round whose active set did not change costs a
    // few passes: its solve starts converged.
    static constexpr uint32_t kActiveSetRounds = 4;

    // `stored` must be given for Preconditioner::stored (and only then); `name` is the stat entry.
    // `pairs` (with `stored` only): the solver also solves pairs (solve_pair), its vectors twice as large.
    ConjugateGradientSolver(Preconditioner kind, const char* name, std::unique_ptr<StoredPreconditioner> stored = {},
                            bool pairs = false);
    pf_result init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid, const Log& log,
                   const char* fn) override;
    void solve(PassRunner& runner, const PressureProblem& problem) override;
    bool solves_pairs() const override { return pairs_; }
    void solve_pair(PassRunner& runner, const PressureProblem& first, const PressureProblem& second) override;

private:
    // The kernels of this kind (of a pair solve: `pair`).
    gl::ProgramId init_program(bool pair = false) const;
    gl::ProgramId update_program(bool pair = false) const;
    gl::ProgramId matvec_program(bool pair = false) const;
    // One Krylov solve of `problem` from its pressure (a round of an active-set solve when
    // another_round), without the final report; with `second`, of both problems of a pair.
    void krylov(PassRunner& runner, const PressureProblem& problem, bool another_round,
                const PressureProblem* second = nullptr);

    Preconditioner kind_;
    const char* name_;
    std::unique_ptr<StoredPreconditioner> stored_;
    bool pairs_ = false;
    SolverGrid grid_{};
    SolveControl control_;
    gl::Buffer r_, p_[2], q_, z_, working_type_;  // p: the previous and the new direction
    StatId stat_ = 0, precondition_stat_ = 0;
};

}  // namespace pf
