// What every pressure solver shares: the state buffer whose scalars and indirect-dispatch
// records let the GPU decide convergence (shaders/solvers/common/solver_state.h), the
// per-workgroup partial sums, the start of a solve (null-space detection, b.b), convergence
// checks, and the final residual report into the simulation's status buffer.
//
// Flow of one solve: begin() → the solver's iterations, whose cell-wide passes dispatch
// through record(k) → check() now and then (stationary solvers) → finish(). A control made for
// pairs (MGPCG's, `pairs`) also runs pair solves: two problems with the same cell types in the
// same passes (shaders/solvers/common/solver_value.glsl), begin_pair() → iterations →
// finish() of both, each problem with its own scalars, tolerance, iteration cap and report. Once a check (or a
// Krylov scalar step) finds the tolerance met, it zeroes the records: every later iteration
// of that solve dispatches no workgroups, and the CPU has not waited for anything.
#pragma once
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "sim/solvers/pressure_solver.h"

namespace pf {

class SolveControl {
public:
    // Allocates the state and partials buffers and builds the shared programs; record 0 is
    // the fine grid's cells, record orbit_record() its mirror orbits (the reduction kernels'
    // workgroups take PF_WORKGROUP_SIZE orbits each, shaders/solvers/common/orbit_main.glsl).
    // Returns an error message, empty on success.
    // `pairs`: also for pair solves (two partial sums a workgroup, the pair programs).
    std::string init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid, bool pairs = false);
    bool pairs() const { return pairs_; }
    // Adds an indirect record dispatching `invocations` (a coarser grid level); its index.
    uint32_t add_record(uint64_t invocations);
    Indirect record(uint32_t k) const;
    // Indirect record and size of the reduction kernels' dispatch, in orbits (either mapping runs
    // a workgroup per PF_WORKGROUP_SIZE orbits).
    Indirect orbit_record() const { return record(orbit_record_); }
    uint32_t orbit_count() const { return orbits_; }
    // Mirror orbits of a grid of `size` cells: the cells (i, j, k) with i and k in the lower halves
    // of their axes (shaders/solvers/common/poisson.glsl's orbit_count).
    static uint64_t orbits(glm::ivec3 size) {
        return GridLayout::volume(glm::ivec3((size.x + 1) / 2, size.y, (size.z + 1) / 2));
    }
    // The permutation of reduction kernel `id` (orbit_main.glsl) for this grid's mapping; any
    // other kernel is returned as it is.
    gl::ProgramId reduction(gl::ProgramId id) const;
    // Kernel `id` for a pair solve (`pair`) or a single one, in this grid's reduction mapping.
    gl::ProgramId program(gl::ProgramId id, bool pair) const { return reduction(pair ? paired(id) : id); }
    // The pair permutation of a kernel that has one (any other is returned as it is).
    static gl::ProgramId paired(gl::ProgramId id);
    // Workgroups (and partial sums) of a reduction pass over the fine grid.
    uint32_t partial_count() const { return partials_; }

    // Resets the state for a new solve of `problem` (tolerance, singular mean, b.b); a further
    // round of the same solve (`another_round`) keeps counting its iterations.
    void begin(PassRunner& runner, StatId stat, const PressureProblem& problem, bool another_round = false);
    // Residual of `x` against the tolerance; `iterations` done since the previous check.
    // Skipped (indirectly) once converged.
    void check(PassRunner& runner, StatId stat, const PressureProblem& problem, uint32_t iterations);
    // The final residual of the problem's pressure and the iteration count, into the status
    // buffer; with `second`, of both problems of a pair solve, each into its own.
    void finish(PassRunner& runner, StatId stat, const PressureProblem& problem, const PressureProblem* second = nullptr);
    // begin() for a pair solve of `first` and `second` (same cell types, neither with
    // separation); each problem stops after its own `caps` of iterations.
    void begin_pair(PassRunner& runner, StatId stat, const PressureProblem& first, const PressureProblem& second,
                    const uint32_t caps[2]);

    const gl::Buffer& state() const { return state_; }
    const gl::Buffer& partials() const { return partials_buffer_; }
    // The level-size uniform of the solver kernels that work on cells.
    static Uniform dims_uniform(glm::ivec3 dims);
    Uniform dims_uniform() const { return dims_uniform(grid_.layout.dims); }
    glm::ivec3 dims() const { return grid_.layout.dims; }

private:
    // residual.comp over one problem, or both of a pair (second non-null).
    void residual(PassRunner& runner, StatId stat, const PressureProblem& problem, bool direct,
                  const PressureProblem* second = nullptr);
    // rhs_stats over one problem, or both of a pair (second non-null).
    void rhs_stats(PassRunner& runner, StatId stat, const PressureProblem& problem, const PressureProblem* second);

    SolverGrid grid_{};
    gl::Buffer state_, partials_buffer_;
    uint32_t partials_ = 0;
    uint32_t orbits_ = 0, orbit_record_ = 0;
    uint32_t records_ = 0;
    bool pairs_ = false;
    const PassRunner* runner_ = nullptr;
};

}  // namespace pf
