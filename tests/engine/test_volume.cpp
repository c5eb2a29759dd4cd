// Volume preservation (docs/design.md §4.5): the hydrostatic start keeps a tank at rest from
// its first frame, and the particle-density volume correction keeps particles from clumping
// (PIC/FLIP compresses slowly: a resting tank loses depth, a dam break loses volume).
// Every bound is a measurement on llvmpipe with margin, stated next to it.
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

struct NoisyTank {
    double depth_change, volume_change, roughness;  // relative to the start
};

class Volume : public GpuTest {
protected:
    void expect_same_in_turn(pf_pressure_solver solver, uint32_t separation, uint32_t iterations);
    NoisyTank run_noisy_tank(float volume_correction, void (*adjust)(pf_sim_params&) = nullptr, float cell_size = 0.1f);
};

// Equilibrium start: a 24^3 tank of 5 cm cells filled half full, at rest, in the default
// configuration. Starting the first solve from p = 0, the fast preset's 40 Jacobi sweeps let it
// sag 5.8% of its depth in the first 0.5 s, moving at up to 0.36 m/s (measured on llvmpipe: 40
// sweeps are far too few to climb to the hydrostatic pressure of a 12-cell column, and the
// column falls meanwhile). The hydrostatic start is the exact discrete solution of a flat tank,
// so every solver keeps it: measured depth loss 0 and speed 0 (MGPCG, the default).
TEST_F(Volume, TankStartsInEquilibrium) {
    pf_sim_desc d = test_desc(24, 24, 24, 0.05f);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {1.2f, 0.6f, 1.2f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const double depth0 = surface_depth_of(read_all(sim.get()), d);
    for (int f = 0; f < 30; ++f) ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    const ParticleState end = read_all(sim.get());
    const double loss = 1.0 - surface_depth_of(end, d) / depth0;
    RecordProperty("depth_loss_0_5s", std::to_string(loss));
    RecordProperty("max_speed_0_5s", std::to_string(max_speed_of(end)));
    EXPECT_LT(std::abs(loss), 0.01);
}

// Measured over a long run: RMS of count / rest - 1 over FLUID cells with a FLUID cell above
// them (the surface layer is partly filled by nature), i.e. how far the particle density is from
// flat where the liquid is not thin.
double density_roughness(const std::vector<uint32_t>& count, const pf_sim_desc& d) {
    const uint32_t nx = d.grid_size[0], ny = d.grid_size[1], nz = d.grid_size[2];
    double sum = 0;
    size_t cells = 0;
    for (uint32_t k = 0; k < nz; ++k)
        for (uint32_t j = 0; j + 1 < ny; ++j)
            for (uint32_t i = 0; i < nx; ++i) {
                const size_t c = i + size_t(nx) * (j + size_t(ny) * k), above = c + nx;
                if (count[c] == 0 || count[above] == 0) continue;
                const double e = double(count[c]) / d.fill_particles_per_cell - 1.0;
                sum += e * e;
                ++cells;
            }
    return cells ? std::sqrt(sum / double(cells)) : 0.0;
}

// The long-run scenes use 10 cm cells: substeps stay few (1-2 per frame) on llvmpipe. Every
// other parameter is the default configuration (the balanced preset: MGPCG to 1e-3, separation
// off), which issue 6 requires to keep these volumes.
pf_sim_desc long_run_desc(uint32_t nx, uint32_t ny, uint32_t nz, float volume_correction) {
    pf_sim_desc d = test_desc(nx, ny, nz, 0.1f);
    d.params.volume_correction = volume_correction;
    return d;
}

// A resting tank (16x24x16, half full) in the default configuration: over 10 s
// it keeps its depth and stays still. Measured on llvmpipe: depth change 0, speed 0 at 1 s and
// at 10 s, every cell at exactly the rest count (the hydrostatic start is the exact discrete
// solution, so nothing moves and nothing compresses; without the correction the same holds, so
// in this scene the correction cannot be flatter: it is asserted not to be rougher).
TEST_F(Volume, RestingTankKeepsItsDepthAndStaysStill) {
    const pf_sim_desc d = long_run_desc(16, 24, 16, pf_default_sim_params().volume_correction);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {1.6f, 1.2f, 1.6f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const double depth0 = surface_depth_of(read_all(sim.get()), d);
    const double speed_bound = 0.01 * std::sqrt(9.81 * d.cell_size);
    for (int f = 1; f <= 100; ++f) {
        ASSERT_EQ(pf_step(sim.get(), 0.1f), PF_OK);
        if (f == 10) EXPECT_LT(max_speed_of(read_all(sim.get())), speed_bound) << "spurious speed after 1 s";
    }
    const ParticleState end = read_all(sim.get());
    const double change = surface_depth_of(end, d) / depth0 - 1.0;
    RecordProperty("depth_change_10s", std::to_string(change));
    EXPECT_LT(std::abs(change), 0.01);
    EXPECT_LT(max_speed_of(end), speed_bound);
    EXPECT_EQ(density_roughness(cell_counts_of(end, d), d), 0.0);
}

// A 16^3 tank of 10 cm cells, half full, carrying FLIP noise (the pf_fill_box lattice, 2 x 2 x 2
// jittered samples per cell, every particle with a random velocity of up to 1 cm/s per component,
// as a tank has after any disturbance), stepped 10 s at 0.1 s frames; `adjust` changes the default
// parameters. Its depth, particle-density volume and density roughness, relative to the start.
// Another `cell_size` builds the same tank larger or smaller by Froude similarity: its frames and
// its noise scale by sqrt(cell_size / 0.1 m), so it is the same flow in 100 frames.
NoisyTank Volume::run_noisy_tank(float volume_correction, void (*adjust)(pf_sim_params&), float cell_size) {
    pf_sim_desc d = long_run_desc(16, 16, 16, volume_correction);
    d.cell_size = cell_size;
    const float froude = std::sqrt(cell_size / 0.1f);
    if (adjust) adjust(d.params);
    SimPtr sim = create(d);
    EXPECT_TRUE(sim);
    if (!sim) return {};
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-0.5f, 0.5f), noise(-0.01f * froude, 0.01f * froude);
    std::vector<float> pos, vel;
    const float s = d.cell_size / 2;
    for (int k = 0; k < 32; ++k)
        for (int j = 0; j < 16; ++j)
            for (int i = 0; i < 32; ++i) {
                pos.insert(pos.end(), {(i + 0.5f + 0.8f * u(rng)) * s, (j + 0.5f + 0.8f * u(rng)) * s,
                                       (k + 0.5f + 0.8f * u(rng)) * s});
                vel.insert(vel.end(), {noise(rng), noise(rng), noise(rng)});
            }
    EXPECT_EQ(pf_add_particles(sim.get(), pos.data(), vel.data(), uint32_t(pos.size() / 3)), PF_OK);
    const ParticleState start = read_all(sim.get());
    const double depth0 = surface_depth_of(start, d), volume0 = particle_volume_of(cell_counts_of(start, d), d);
    for (int f = 0; f < 100; ++f) EXPECT_EQ(pf_step(sim.get(), 0.1f * froude), PF_OK);
    const ParticleState end = read_all(sim.get());
    const std::vector<uint32_t> count = cell_counts_of(end, d);
    return NoisyTank{surface_depth_of(end, d) / depth0 - 1.0, particle_volume_of(count, d) / volume0 - 1.0,
                     density_roughness(count, d)};
}

// The noisy tank: without the correction the noise drives particles into clumps and the tank
// sinks; with it the density stays flat. Measured on llvmpipe (10 s, the default configuration
// since 2026-11-23): without the correction depth -1.1%, particle volume -5.5%, roughness 0.142;
// with 0.1 depth +0.74% (the one-sided correction at the surface lifts it a little), volume
// -2.1%, roughness 0.073. Bounds: roughness below 3/4 of the uncorrected one, depth within 1.5%.
TEST_F(Volume, CorrectionKeepsANoisyTankFlatterThanWithout) {
    const NoisyTank off = run_noisy_tank(0.0f), on = run_noisy_tank(pf_default_sim_params().volume_correction);
    RecordProperty("off_depth", std::to_string(off.depth_change));
    RecordProperty("off_volume", std::to_string(off.volume_change));
    RecordProperty("off_roughness", std::to_string(off.roughness));
    RecordProperty("on_depth", std::to_string(on.depth_change));
    RecordProperty("on_volume", std::to_string(on.volume_change));
    RecordProperty("on_roughness", std::to_string(on.roughness));
    EXPECT_LT(on.roughness, 0.75 * off.roughness);
    EXPECT_GT(on.volume_change, off.volume_change);
    EXPECT_LT(std::abs(on.depth_change), 0.015);
}

// Leapfrog at a projection CFL of 8 in the same tank: the noise is slow, so the speed asks for one
// projection however long the frame, and at one projection per 0.1 s frame the tank rose 6.1%
// (llvmpipe, 2026-12-05). Its projections are at most half of sqrt(dx / |g|) (0.05 s here;
// kLeapfrogLongestProjection in src/sim/step_clock.h): two a frame. The same tank built ten times
// smaller (1 cm cells, frames of 0.032 s: a game at 30 frames a second) is the same flow, and
// with projections of at most 1/30 s it took one a frame and its depth changed -6.2% in 3.2 s.
// Measured now (llvmpipe): -0.78% and -1.07%. Bound: the correction's above.
void expect_leapfrog_keeps_the_depth(const NoisyTank& lf) {
    ::testing::Test::RecordProperty("depth", std::to_string(lf.depth_change));
    ::testing::Test::RecordProperty("volume", std::to_string(lf.volume_change));
    ::testing::Test::RecordProperty("roughness", std::to_string(lf.roughness));
    EXPECT_LT(std::abs(lf.depth_change), 0.015);
}
void leapfrog_at_cfl_8(pf_sim_params& p) {
    p.advection = PF_ADVECTION_LEAPFROG;
    p.cfl = 8.0f;
}
TEST_F(Volume, LeapfrogAtALargeCflKeepsANoisyTanksDepthInLongFrames) {
    expect_leapfrog_keeps_the_depth(run_noisy_tank(pf_default_sim_params().volume_correction, leapfrog_at_cfl_8));
}
TEST_F(Volume, LeapfrogAtALargeCflKeepsASmallNoisyTanksDepthAtThirtyFramesASecond) {
    expect_leapfrog_keeps_the_depth(run_noisy_tank(pf_default_sim_params().volume_correction, leapfrog_at_cfl_8, 0.01f));
}

// The liquid-volume change (mass over density, liquid_volume_of) of the small dam break below
// after `frames` frames of frame_dt, measured on the CPU from the particles (NaN if a step
// failed); max_substeps 0 keeps the default cap. Its capped count sum is recorded beside it.
struct VolumeChange {
    double liquid = std::nan(""), particle = std::nan("");
};
VolumeChange dam_break_volume_change(int frames, float frame_dt, uint32_t max_substeps = 0) {
    pf_sim_desc d = long_run_desc(16, 16, 16, pf_default_sim_params().volume_correction);
    if (max_substeps) d.params.max_substeps = max_substeps;
    pf_sim* raw = nullptr;
    EXPECT_EQ(pf_create(&d, &raw), PF_OK) << last_log();
    SimPtr sim(raw);
    if (!sim) return {};
    const float lo[3] = {0, 0, 0}, hi[3] = {0.6f, 1.2f, 1.6f};
    EXPECT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const std::vector<uint32_t> count0 = cell_counts_of(read_all(sim.get()), d);
    for (int f = 0; f < frames; ++f) {
        const pf_result r = pf_step(sim.get(), frame_dt);
        EXPECT_EQ(r, PF_OK);
        if (r != PF_OK) return {};
    }
    const std::vector<uint32_t> count = cell_counts_of(read_all(sim.get()), d);
    return {liquid_volume_of(count, d) / liquid_volume_of(count0, d) - 1.0,
            particle_volume_of(count, d) / particle_volume_of(count0, d) - 1.0};
}

// A small dam break (16^3 cells of 10 cm, a 0.6 x 1.2 x 1.6 m column) with the default
// correction: its liquid volume after 10 s, measured on the CPU from the particles. Measured on
// llvmpipe at frame dt 1/60 (1 substep a frame), with the position-only correction of issue 17:
// -0.7% (capped count sum -3.3%, which also reads the spread of counts as loss). Before issue
// 17 this bounded the capped count sum: -29% without the velocity correction, -1.2% with it.
// About 7 s on llvmpipe: 600 MGPCG substeps.
TEST_F(Volume, DamBreakKeepsItsVolumeAtSixtyFramesASecond) {
    const VolumeChange change = dam_break_volume_change(600, 1.0f / 60.0f);
    RecordProperty("liquid_volume_change_10s", std::to_string(change.liquid));
    RecordProperty("particle_volume_change_10s", std::to_string(change.particle));
    EXPECT_LT(std::abs(change.liquid), 0.02);
}

// The same dam break at frame dt 0.5 s: CFL wants more substeps than the default cap of 16
// allows (1/32 s each). Measured on llvmpipe with issue 17's correction (every substep here: each
// is longer than VolumeCorrection::kInterval): liquid volume +2.1% after 10 s (capped count sum
// -3.6%); with the earlier cap of 8 substeps -0.2% (count sum -6.2%). The issue's bound, 5%, is
// asserted. (Before issue 17 a control asserted that the cap of 8 lost at least 3 points more:
// with the velocity correction once per substep the loss followed the substep length, -8.1%
// against -2.9%. With the correction scheduled by simulated time it no longer does, so the cap-8
// run is only recorded.)
TEST_F(Volume, DamBreakAtHalfSecondFramesLosesLittleVolume) {
    ASSERT_EQ(pf_default_sim_params().max_substeps, 16u);
    const VolumeChange change = dam_break_volume_change(20, 0.5f), cap8 = dam_break_volume_change(20, 0.5f, 8);
    RecordProperty("liquid_volume_change_10s", std::to_string(change.liquid));
    RecordProperty("particle_volume_change_10s", std::to_string(change.particle));
    RecordProperty("liquid_volume_change_10s_cap8", std::to_string(cap8.liquid));
    RecordProperty("particle_volume_change_10s_cap8", std::to_string(cap8.particle));
    EXPECT_LT(std::abs(change.liquid), 0.05);
    EXPECT_LT(std::abs(cap8.liquid), 0.05);
}

// The issue's own dam break (issue 6): a 48 x 24 x 8 tank of 5 cm cells, a 0.8 x 0.9 x 0.4 m
// column, the default configuration, run 10 s (CI's fast mode: 5 s at 1/60 s frames). Its
// volume is the liquid volume, mass over density (liquid_volume_of, pf_stats.liquid_volume):
// the capped count sum of particle_volume also reads the cell-to-cell spread of counts in a
// disordered liquid as loss (measured at the end of the 10 s 1/60 run: interior cells hold 7.98
// particles on average, rest 8, with a standard deviation of 0.71, which costs the capped sum
// 2.6%; docs/notes/2026-11-25-volume-correction.md).
struct DamBreakRun {
    double liquid_end = 0, liquid_worst = 0;  // drift of the liquid volume: at the end, largest |drift| sampled
    double particle_end = 0;                  // drift of the capped count sum at the end (reported)
    double gpu_liquid_end = 0;                // pf_stats.liquid_volume_drift of the last step
    // A geometric check that reads no count: the mean surface height (each column's highest
    // particle plus half the particle spacing, dx / 4 at 8 per cell) at the end against the depth the
    // particles fill at rest density over the tank's floor. The mean height of a surface is the
    // volume under it over the floor, waves or not; splashes and trapped air lift it.
    double surface_end = 0;
};
DamBreakRun issue_dam_break(float frame_dt, float volume_correction, double seconds = 10.0) {
    pf_sim_desc d = test_desc(48, 24, 8, 0.05f);
    d.params = pf_default_sim_params();
    d.params.volume_correction = volume_correction;
    d.max_particles = 1u << 16;
    DamBreakRun out;
    pf_sim* raw = nullptr;
    EXPECT_EQ(pf_create(&d, &raw), PF_OK) << last_log();
    SimPtr sim(raw);
    if (!sim) return out;
    const float lo[3] = {0, 0, 0}, hi[3] = {0.8f, 0.9f, 0.4f};
    EXPECT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const std::vector<uint32_t> count0 = cell_counts_of(read_all(sim.get()), d);
    const double liquid0 = liquid_volume_of(count0, d), particle0 = particle_volume_of(count0, d);
    const int frames = int(std::lround(seconds / frame_dt)), every = std::max(1, int(std::lround(0.25 / frame_dt)));
    for (int f = 1; f <= frames; ++f) {
        EXPECT_EQ(pf_step(sim.get(), frame_dt), PF_OK);
        if (f % every != 0 && f != frames) continue;
        const ParticleState now = read_all(sim.get());
        const std::vector<uint32_t> count = cell_counts_of(now, d);
        const double liquid = liquid_volume_of(count, d) / liquid0 - 1.0;
        if (std::abs(liquid) > std::abs(out.liquid_worst)) out.liquid_worst = liquid;
        if (f == frames) {
            out.liquid_end = liquid;
            out.particle_end = particle_volume_of(count, d) / particle0 - 1.0;
            const ParticleState& end = now;
            const double rest_depth = double(end.count()) / d.fill_particles_per_cell * std::pow(double(d.cell_size), 3) /
                                      (double(d.grid_size[0]) * d.grid_size[2] * d.cell_size * d.cell_size);
            out.surface_end = (surface_depth_of(end, d) + d.cell_size / 4) / rest_depth - 1.0;
        }
    }
    glFinish();  // the last step's readback fence has passed (pf_get_stats never waits)
    pf_stats st{};
    st.struct_size = sizeof st;
    EXPECT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
    out.gpu_liquid_end = st.liquid_volume_drift;
    return out;
}

void record(const char* prefix, const DamBreakRun& r) {
    const std::string p(prefix);
    ::testing::Test::RecordProperty(p + "liquid_volume_change_end", std::to_string(r.liquid_end));
    ::testing::Test::RecordProperty(p + "liquid_volume_change_worst", std::to_string(r.liquid_worst));
    ::testing::Test::RecordProperty(p + "gpu_liquid_volume_drift_end", std::to_string(r.gpu_liquid_end));
    ::testing::Test::RecordProperty(p + "particle_volume_change_end", std::to_string(r.particle_end));
    ::testing::Test::RecordProperty(p + "mean_surface_height_change_end", std::to_string(r.surface_end));
}

// At frame dt 1/60 the issue asks for 2% after 10 s. Measured on llvmpipe with issue 17's
// position-only correction: +0.0% at 10 s, at most +1.4% at any quarter second, the GPU's figure
// +0.5% (with the velocity correction before: +0.2%, -0.6% .. +1.4%; count sum -2.6%). Asserted:
// 2% at the end and at every sample. The GPU's own figure (from the last substep's P2G counts)
// within the same 2%. CI's fast mode runs the first 5 s (the front's impact and the first
// sloshes, about 30 s on llvmpipe) with the same bounds; the long mode (PF_STABILITY_LONG, as the
// stability suite) the issue's 10 s. The 16^3 dam break above runs 10 s in both.
TEST_F(Volume, IssueDamBreakKeepsItsLiquidVolumeAtSixtyFramesASecond) {
    const double seconds = long_mode() ? 10.0 : 5.0;
    const DamBreakRun r = issue_dam_break(1.0f / 60.0f, pf_default_sim_params().volume_correction, seconds);
    RecordProperty("seconds", std::to_string(seconds));
    record("", r);
    EXPECT_LT(std::abs(r.liquid_end), 0.02);
    EXPECT_LT(std::abs(r.liquid_worst), 0.02);
    EXPECT_LT(std::abs(r.gpu_liquid_end), 0.02);
}

// At frame dt 0.5 s (16 substeps of 1/32 s, fewer than CFL wants) the issue asks for 5% after
// 10 s. Measured on llvmpipe with issue 17's correction (every substep at these frames): +0.2%
// at 10 s, the GPU's figure +0.9%, the mean surface height +1.0% (with the velocity correction
// before: -0.4% at 10 s, -10.2% at the worst frame, -8.6% in the capped count sum). The control
// without the correction ends at -42% (interior cells hold 13.8 particles, rest 8): the measure
// sees compression. The mean surface height, which reads no count, agrees (before issue 17:
// -0.1% against the rest-density depth with the default), -46% without (the liquid has settled by 10 s at these
// frames; at dt 1/60 it still sloshes and splashes lift it, +4.5%, so it is not asserted there).
// Asserted: 5% at the end with the default for both measures, more than 20% lost without.
TEST_F(Volume, IssueDamBreakKeepsItsLiquidVolumeAtHalfSecondFrames) {
    const DamBreakRun on = issue_dam_break(0.5f, pf_default_sim_params().volume_correction);
    const DamBreakRun off = issue_dam_break(0.5f, 0.0f);
    record("", on);
    record("off_", off);
    EXPECT_LT(std::abs(on.liquid_end), 0.05);
    EXPECT_LT(std::abs(on.gpu_liquid_end), 0.05);
    EXPECT_LT(std::abs(on.surface_end), 0.05);
    EXPECT_LT(off.liquid_end, -0.20);
    EXPECT_LT(off.surface_end, -0.20);
}

// The correction's solve is issued in lockstep with the projection's (one barrier a pair of
// their passes), except under per-kernel timing, which issues them in turn: a dam break's
// particles are the same either way, bit for bit, and both ran the same correction passes.
// With PCG and separation (the CG family's active-set rounds copy the cell types inside the
// recording) and with 41 Jacobi sweeps (an odd count starts with a copy). (MGPCG solves both on
// one instance: in the same passes without separation, as the balanced and fast presets have it,
// tests/internal/test_volume_correction.cpp; in turn with it.)
void Volume::expect_same_in_turn(pf_pressure_solver solver, uint32_t separation, uint32_t iterations) {
    std::vector<float> pos[2];
    uint32_t correction_dispatches[2] = {0, 0};
    for (int in_turn = 0; in_turn < 2; ++in_turn) {
        pf_sim_desc d = long_run_desc(16, 12, 8, 0.5f);
        d.params.pressure_solver = solver;
        d.params.separation = separation;
        d.params.pressure_iterations = iterations;
        SimPtr sim = create(d);
        ASSERT_TRUE(sim);
        if (in_turn) ASSERT_EQ(pf_set_gpu_timing(sim.get(), PF_GPU_TIMING_KERNELS), PF_OK);
        const float lo[3] = {0, 0, 0}, hi[3] = {0.6f, 0.8f, 0.8f};
        ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
        for (int f = 0; f < 20; ++f) ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        pos[in_turn] = read_all(sim.get()).pos;
        for (const pf_pass_stats& ps : pass_list(sim.get()))
            if (std::string(ps.name).rfind("volume_correction_solve", 0) == 0) correction_dispatches[in_turn] += ps.dispatches;
    }
    ASSERT_EQ(pos[0].size(), pos[1].size());
    EXPECT_EQ(0, std::memcmp(pos[0].data(), pos[1].data(), pos[0].size() * 4)) << "the schedule changed the particles";
    EXPECT_GT(correction_dispatches[0], 0u);
    EXPECT_EQ(correction_dispatches[0], correction_dispatches[1]);
}

TEST_F(Volume, CorrectionSolvedAlongsideTheProjectionMatchesInTurn) {
    expect_same_in_turn(PF_PRESSURE_SOLVER_PCG, 1, 40);
    expect_same_in_turn(PF_PRESSURE_SOLVER_JACOBI, 0, 41);
}

// With MGPCG the correction's solve goes with the projection's as a pair (no separation), in turn
// with it (separation), or not at all (volume_correction 0), and pf_set_params may move a
// running simulation between the three: each step then runs the configuration asked
// (its passes say which: a pair's correction solve counts no pass of its own), the liquid
// stays in the domain with its particles intact, and no switch allocates GPU memory (one
// solver instance serves all three).
TEST_F(Volume, CorrectionFollowsTheParamsBetweenPairedAloneAndOff) {
    pf_sim_desc d = long_run_desc(16, 12, 8, 0.5f);
    d.params.pressure_solver = PF_PRESSURE_SOLVER_MGPCG;
    d.params.separation = 0;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.6f, 0.8f, 0.8f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const uint32_t particles = live_count(sim.get());
    uint64_t memory = 0;
    struct Phase {
        uint32_t separation;
        float correction;
        bool own_solve, moves;  // the correction's solve has passes of its own; its move runs
    };
    const Phase phases[] = {{0, 0.5f, false, true}, {1, 0.5f, true, true}, {0, 0.5f, false, true},
                            {0, 0.0f, false, false}, {0, 0.5f, false, true}, {1, 0.0f, false, false}};
    for (const Phase& phase : phases) {
        SCOPED_TRACE("separation " + std::to_string(phase.separation) + ", correction " + std::to_string(phase.correction));
        pf_sim_params p = d.params;
        p.separation = phase.separation;
        p.volume_correction = phase.correction;
        ASSERT_EQ(pf_set_params(sim.get(), &p), PF_OK);
        for (int f = 0; f < 5; ++f) ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        uint32_t solve = 0, move = 0, pressure = 0;
        for (const pf_pass_stats& ps : pass_list(sim.get())) {
            const std::string name = ps.name;
            if (name == "volume_correction_solve") solve = ps.dispatches;
            if (name == "volume_correction_move") move = ps.dispatches;
            if (name.rfind("mgpcg", 0) == 0) pressure += ps.dispatches;
        }
        EXPECT_EQ(solve > 0, phase.own_solve);
        EXPECT_EQ(move > 0, phase.moves);
        EXPECT_GT(pressure, 0u);
        pf_stats stats{};
        stats.struct_size = sizeof stats;
        ASSERT_EQ(pf_get_stats(sim.get(), &stats), PF_OK);
        ASSERT_GT(stats.gpu_memory_bytes, 0u);
        if (memory == 0) memory = stats.gpu_memory_bytes;
        EXPECT_EQ(stats.gpu_memory_bytes, memory);
        const ParticleState state = read_all(sim.get());
        ASSERT_EQ(state.pos.size(), size_t(particles) * 3);
        for (size_t i = 0; i < state.pos.size(); ++i) {
            ASSERT_TRUE(std::isfinite(state.pos[i])) << i;
            ASSERT_GE(state.pos[i], 0.0f) << i;
            ASSERT_LE(state.pos[i], float(d.grid_size[i % 3]) * d.cell_size) << i;
        }
    }
}

}  // namespace
}  // namespace pf::test
