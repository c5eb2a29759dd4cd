// The volume correction (docs/design.md §4.5): once per step (and per 1/60 s of simulated
// time in longer steps), particles in over-full cells
// are moved apart along the gradient of a displacement potential, solved with a solver of the
// simulation's kind: with MGPCG the projection's own, made for pairs (the two problems in the
// same passes; in turn with separation), else an instance of its own, issued alongside the
// projection's. It moves positions only: velocities, and so FLIP's
// velocity difference and the kinetic energy, never see it (issue 17: as a divergence target
// of the projection it added energy when the solve was unconverged and smothered waves when
// it was converged).
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>

#include "gl/buffer.h"
#include "gl/gl.h"
#include "pf/pf.h"
#include "sim/pass_runner.h"
#include "sim/solvers/pressure_solver.h"

namespace pf {

class VolumeCorrection {
public:
    // Allocates its right-hand side, potential and solver-report buffers for `cells` cells,
    // builds its two kernels and registers its statistics entries (setup, solve — the
    // solver's passes counted apart from the pressure solve's — and move). Returns an error
    // message, empty on success.
    std::string init(const gl::Api& gl, PassRunner& runner, uint32_t cells);

    // What it reads and moves: this substep's cell types and P2G counts, the last solve's
    // pressure (with separation, where liquid may be leaving a wall), the free surface's face
    // fractions, the particles.
    struct Inputs {
        const gl::Buffer& positions;
        const gl::Buffer& cell_type;
        const gl::Buffer& cell_count;
        const gl::Buffer& pressure;
        const gl::Buffer& face_fraction;
        uint64_t cells = 0;
        uint64_t particles = 0;
        // The tiled P2G's particle order for the move, where G2P reads in it (else null).
        const gl::Buffer* order = nullptr;
    };
    // Records the correction (setup, the solve, the particle move); nothing when
    // params.volume_correction is 0.
    void run(PassRunner& runner, PressureSolver& solver, const pf_sim_params& params, const Inputs& in);
    // Its three parts, for a step that issues its solve alongside the projection's (the solve
    // reads only the setup's buffers and the cell types; the move, only the solved potential):
    // the right-hand side (and q = 0), the solve with `solver` (its own buffers, not the
    // projection's, when the two are interleaved), and the particles' move.
    void setup(PassRunner& runner, const Inputs& in);
    void solve(PassRunner& runner, PressureSolver& solver, const pf_sim_params& params, const Inputs& in);
    void move(PassRunner& runner, const Inputs& in);
    // The solve paired with the projection's (`projection` first) in the same passes, on `solver`
    // (solves_pairs(); the projection without separation): what solve() and the projection's own
    // solve would record, with one pass of each kind for both.
    void solve_paired(PassRunner& runner, PressureSolver& solver, const pf_sim_params& params, const Inputs& in,
                      const PressureProblem& projection);

    // The solve's parameters: the simulation's solver without separation (the potential has
    // either sign), to the pressure's tolerance but never below kTolerance, with at most
    // kMaxKrylovIterations Krylov iterations (a correction that moves part of the excess needs
    // no more; stationary solvers keep the simulation's sweep count). 1e-2 was too loose for
    // mirrored runs to stay mirror images (tests/stability/test_corners.cpp: 1.6e-3 cells apart
    // after 0.25 s, bound 1e-3).
    static constexpr float kTolerance = 1e-3f;
    static constexpr uint32_t kMaxKrylovIterations = 10;
    static pf_sim_params solve_params(const pf_sim_params& params);
    // Simulated time between two runs within a step (the first substep of every step runs it):
    // at 60 frames a second once a step; in long frames every substep of 1/60 s or longer
    // (docs/notes/2026-11-25-volume-correction.md: once per 0.5 s frame left the last substeps' counts 5% thin).
    static constexpr float kInterval = 1.0f / 60.0f;
    // Leapfrog's large steps compress the liquid within a frame (a straight move through strain),
    // and a correction once a frame left the short dam break 8.7% compressed at 32 cells; with it
    // the correction runs in every projection.
    static bool every_projection(const pf_sim_params& params) { return params.advection == PF_ADVECTION_LEAPFROG; }
    // The largest displacement of one run, in cells an axis (shaders/sim/volume_correction_move.comp):
    // half a cell per kInterval of the substep dt, between a quarter and a half. Half a cell in
    // each of several projections a frame clumped the floor's rows of a column; a quarter in a
    // frame of one projection left a tank's gauge further from the experiment
    // (docs/notes/2026-12-05-strain-count-accuracy.md).
    static float reach_cells(const pf_sim_params& params, float dt) {
        return every_projection(params) ? std::clamp(0.5f * dt / kInterval, 0.25f, 0.5f) : 0.5f;
    }
    // Before a step that corrects: learns what its solves needed lately from `status_words`, the
    // newest step read back (PF_STATUS_CORRECTION_*), so that they issue that need plus a margin
    // (issued_iterations in sim/solvers/pressure_solver.h), not the whole of kMaxKrylovIterations
    // (a pair solve issues the larger of its two problems' counts); and restarts its figures, as
    // the projection's do. `same_solver`: that step solved with the simulation's solver.
    void begin_step(const uint32_t* status_words, bool same_solver);
    // After a step's last correction: copies its most iterations and largest residual into the
    // status words that are read back (PF_STATUS_CORRECTION_RESIDUAL, _ITERATIONS).
    void report(PassRunner& runner, const gl::Buffer& status);

    // The displacement potential q of the last run (metres; tests read it).
    const gl::Buffer& potential() const { return potential_; }

private:
    // Its problem for the parameters `solve` (solve_params), with what recent solves needed.
    PressureProblem problem(const Inputs& in, const pf_sim_params& solve) const;

    gl::Buffer rhs_, potential_, report_;
    uint32_t recent_iterations_ = kUnknownIterations;  // not known, as a residual below 0
    float recent_residual_ = -1.0f;
    StatId setup_stat_ = 0, solve_stat_ = 0, move_stat_ = 0;
};

}  // namespace pf
