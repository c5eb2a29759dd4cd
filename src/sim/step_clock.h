// The step's two clocks (docs/design.md §5). A pf_step of frame_dt takes a number of substeps,
// each one pressure projection (P2G ... solve ... G2P), from the projection CFL (params.cfl) and
// the limits effects declare; inside each substep's advection every particle is traced in
// sub-steps of at most one cell (shaders/common/particle_trace.glsl), so the projections can be
// few while no particle jumps over a wall or an obstacle. Pure functions of their inputs:
// tests drive them without a GL context.
#pragma once
#include <cstdint>

#include "pf/pf.h"

namespace pf {

// What decides the projection count of one frame.
struct ProjectionDemand {
    float frame_dt = 0.0f;
    float cell_size = 0.0f;
    float cfl = 1.0f;             // cells a particle may cross per projection
    uint32_t max_projections = 1; // params.max_substeps
    float speed = 0.0f;           // fastest particle at the frame's start (the previous step's readback)
    float acceleration = 0.0f;    // largest acceleration, m/s^2: gravity and the effects'
    float imposed_speed = 0.0f;   // a speed effects impose whatever was measured
    float max_dt = 0.0f;          // the longest substep every effect stays stable at (0: no limit)
    // The liquid's mean strain P = (tr(G^2) - tr(G)^2) / 2 of its velocity gradient G, 1/s^2
    // (shaders/sim/metrics.comp; the previous step's readback), for an integrator that moves
    // particles along straight lines at large CFL (leapfrog); 0: no strain limit.
    float strain = 0.0f;
    // The integrator's longest projection step in units of the gravity time sqrt(cell_size /
    // gravity) (kLeapfrogLongestProjection); 0, or no gravity: no limit.
    float longest_projection = 0.0f;
    // |g|, m/s^2: the gravity time sqrt(cell_size / gravity) is the unit of the strain limit and of
    // the longest projection.
    float gravity = 0.0f;
};

// A straight move of dt through a divergence-free flow changes a volume by the factor
// 1 - dt^2 P (strain compresses, rotation expands), so k projections of frame_dt / k compress
// the liquid by frame_dt^2 P / k a frame. The strain limit keeps that at most kStrainRate
// times the frame's length in units of the gravity time sqrt(dx / |g|) over the gravity time of
// the laboratory columns it was measured on (kStrainGravityTime): 0.83% per 1/60 s there, where
// the dam-break experiments' bounds held over perturbed fills and 1% missed one
// (docs/notes/2026-12-05-strain-count-accuracy.md). In units of the gravity time a liquid and the
// same liquid built larger take the same projections; in seconds, the columns built four times
// larger took half as many and two of eight lost liquid volume to compression (docs/accuracy.md,
// "The strain count at a game's size").
constexpr float kStrainRate = 0.5f;  // 1/s at kStrainGravityTime
// sqrt(dx / |g|) of the Martin & Moyce columns at 16 cells (3.572 mm), s; without gravity the
// strain limit takes this unit.
constexpr float kStrainGravityTime = 0.0190816f;

// Leapfrog's longest projection step, in units of sqrt(dx / |g|): the time in which gravity moves
// liquid about a cell, so that a liquid and the same liquid built larger (Froude similarity) take
// the same steps. At a large projection CFL a slow liquid asks for one projection however long
// the frame, and a projection much longer than that is too long a step for the pressure and the
// volume correction of a liquid at rest: a noisy tank's depth changed 6.1% in 10 s at 0.99 of the
// unit (10 cm cells, 0.1 s frames), 6.2% in 3.2 s at 1 cm cells and 30 frames a second (the same
// flow, built smaller), 1.9% in 7 s at 0.69 and 0.4% in 5 s at 0.49 (docs/notes/2026-12-05-leapfrog-longest-projection.md). A 1/60 s
// frame takes one projection from cells of 10.9 mm up.
constexpr float kLeapfrogLongestProjection = 0.5f;

// The longest projection step in seconds: kLeapfrogLongestProjection-like `units` of
// sqrt(cell_size / gravity); 0 (no limit) without gravity.
float longest_projection_seconds(float units, float cell_size, float gravity);

struct ProjectionCount {
    uint32_t count = 1;
    bool clamped = false;       // the physics wanted more than max_projections
    float travel_cells = 0.0f;  // cells the fastest particle may cross in one projection step
};

// The speed was measured at the end of the previous step: it may grow by one frame of
// acceleration before this frame ends. k = clamp(ceil(frame_dt v / (cfl dx)), 1, max), at least
// as many as the effects' own limits, the strain limit (frame_dt P / kStrainRate times the gravity
// time over kStrainGravityTime) and the integrator's longest projection ask for.
ProjectionCount projections_for(const ProjectionDemand& demand);

// The GPU time of the newest measured step (the library's own timer queries, a few steps late).
struct MeasuredStep {
    uint64_t step = 0;          // 0: nothing measured yet
    uint32_t projections = 0;   // its substeps
    float total_ms = 0.0f;      // the whole step
    float solve_ms = 0.0f;      // its pressure solves (the PF_PASS_PRESSURE_SOLVE group)
    uint32_t iterations = 0;    // the most iterations one of its solves took
};

// What a GPU-time budget lets the next step do (pf_set_gpu_budget, docs/design.md §5).
struct BudgetPlan {
    uint32_t projections = 1;
    uint32_t iteration_cap = 0;  // most pressure iterations per solve (params.pressure_iterations when not cut)
    bool fewer_projections = false;  // fewer than the projection CFL wants
};

// Fits the wanted projections, each at most max_iterations solver iterations, into budget_ms
// from the measured step: a projection costs what one of its projections cost. When even one
// does not fit, the solve's iterations are cut (at least one) by the time one iteration took.
// With no budget (0) or nothing measured the wanted work is returned unchanged.
BudgetPlan fit_budget(float budget_ms, uint32_t wanted, uint32_t max_iterations, const MeasuredStep& measured);

// Face layers the velocity is extrapolated into air: params.extrapolation_layers beyond the first
// cell of a particle's travel, so the trace samples extrapolated velocity as far as a projection
// step carries a particle (ceil(travel_cells) cells, at most 16 more layers).
uint32_t extrapolation_layers(const pf_sim_params& params, float travel_cells);

}  // namespace pf
