// PF_ADVECTION_LEAPFROG (docs/design.md §5): a block of liquid thrown through the air follows its
// parabola exactly, however the frames are cut into substeps, where Euler's whole moves at the
// end-of-substep velocity put it ahead by g/2 times the sum of the squared substeps. Positions and
// velocities meet at the frame's end (nothing to correct when reading them). At a large projection
// CFL its projections are at least what the liquid's strain asks, and the volume correction runs
// in each of them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

constexpr float kDx = 0.05f;
constexpr double kG = 9.81;

struct Flight {
    double x = 0, y = 0, vx = 0, vy = 0;  // the block's mean position and velocity
};

class Leapfrog : public GpuTest {
protected:
    // A 2 x 2 x 2-cell block of 8 particles a cell, its centre at (0.4, 1.2, 0.4) m, thrown at
    // (1, 0.5, 0) m/s in a 16 x 32 x 16 domain of 5 cm cells, stepped through `frames`; the block
    // stays far from every wall.
    Flight fly(pf_advection advection, const std::vector<float>& frames) {
        pf_sim_desc d = test_desc(16, 32, 16, kDx);
        d.params.advection = advection;
        d.params.cfl = 1.0f;  // the substep counts of kFrames below
        SimPtr sim = create(d);
        if (!sim) return {};
        const float lo[3] = {0.35f, 1.15f, 0.35f}, hi[3] = {0.45f, 1.25f, 0.45f}, v[3] = {1.0f, 0.5f, 0.0f};
        EXPECT_EQ(pf_fill_box(sim.get(), lo, hi, v), PF_OK);
        for (float f : frames) EXPECT_EQ(pf_step(sim.get(), f), PF_OK);
        const ParticleState p = read_all(sim.get());
        Flight m;
        for (size_t i = 0; i < p.count(); ++i) {
            m.x += p.pos[i * 3] / double(p.count()), m.y += p.pos[i * 3 + 1] / double(p.count());
            m.vx += p.vel[i * 3] / double(p.count()), m.vy += p.vel[i * 3 + 1] / double(p.count());
        }
        return m;
    }
};

// Frames of 1/60, 1/30, 1/120 and 1/20 s: their substep counts differ (the block speeds up).
const std::vector<float> kFrames = {1.0f / 60, 1.0f / 30, 1.0f / 120, 1.0f / 20, 1.0f / 60};

TEST_F(Leapfrog, AThrownBlockFollowsItsParabola) {
    double t = 0;
    for (float f : kFrames) t += f;
    const double x = 0.4 + 1.0 * t, y = 1.2 + 0.5 * t - 0.5 * kG * t * t, vy = 0.5 - kG * t;
    const Flight leapfrog = fly(PF_ADVECTION_LEAPFROG, kFrames);
    const Flight euler = fly(PF_ADVECTION_EULER, kFrames);
    const double drop = 1.2 + 0.5 * t - y;  // how far gravity moved it
    std::printf("after %.4f s: drop %.5f m; leapfrog %+.2e m off, Euler %+.2e m off; velocity %.4f / %.4f (exact %.4f)\n",
                t, drop, leapfrog.y - y, euler.y - y, leapfrog.vy, euler.vy, vy);
    EXPECT_NEAR(leapfrog.x, x, 1e-5);
    EXPECT_NEAR(leapfrog.vx, 1.0, 1e-3);
    EXPECT_NEAR(leapfrog.y, y, 1e-3 * drop) << "leapfrog's flight is exact";
    // Velocities carry the fixed-point P2G's rounding (max_speed / 2^20 a particle and transfer,
    // design.md §4.2) through every substep: 1.0e-4 m/s off on the H200 after these frames.
    EXPECT_NEAR(leapfrog.vy, vy, 1e-3);
    // Euler's error, the one leapfrog removes: g/2 times the sum of its squared substeps, ahead of
    // the parabola (lower) by several percent of the drop here.
    EXPECT_LT(euler.y - y, -0.02 * drop);
    EXPECT_NEAR(euler.vy, vy, 1e-3) << "both integrate the velocity alike";
}

// A collapsing column at laboratory scale (4 mm cells), at a projection CFL of 8: its speed asks
// for one projection a frame, its strain for several. Each step takes
// max(speed count, ceil(frame_dt P / 0.5 1/s * sqrt(dx / |g|) / 0.0190816 s)) projections from the
// previous step's readback (docs/design.md §5), and the volume correction moves the particles in
// every one of them.
TEST_F(Leapfrog, AStrainingFlowTakesTheProjectionsItsStrainAsks) {
    constexpr float kCell = 0.004f, kFrame = 1.0f / 60.0f;
    pf_sim_desc d = test_desc(32, 20, 4, kCell);
    d.params.advection = PF_ADVECTION_LEAPFROG;
    d.params.cfl = 8.0f;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {8 * kCell, 16 * kCell, 4 * kCell};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    pf_stats before{};
    int raised = 0;
    for (int f = 0; f < 20; ++f) {
        ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
        const pf_stats st = settled_stats(sim.get());  // its strain is the next step's input
        ASSERT_EQ(st.metrics_step, st.steps);
        if (f >= 2) {  // the first steps also count the speed of the fill
            const double v = before.max_speed + 9.81 * kFrame;
            const double by_speed = std::max(1.0, std::ceil(kFrame * v / (d.params.cfl * kCell)));
            const double gravity_time = std::sqrt(double(kCell) / 9.81);
            const double by_strain = std::ceil(kFrame * double(before.strain) / 0.5 * gravity_time / 0.0190816);
            EXPECT_EQ(double(st.substeps), std::min(16.0, std::max(by_speed, by_strain)))
                << "frame " << f << ": strain " << before.strain << " 1/s^2, speed " << before.max_speed << " m/s";
            raised += by_strain > by_speed;
        }
        // The correction's move runs once in each projection.
        std::string moves = "none";
        uint32_t n = 0;
        ASSERT_EQ(pf_get_pass_count(sim.get(), &n), PF_OK);
        for (uint32_t i = 0; i < n; ++i) {
            pf_pass_stats pass{};
            ASSERT_EQ(pf_get_pass_stats(sim.get(), i, &pass), PF_OK);
            if (std::string(pass.name) == "volume_correction_move") moves = std::to_string(pass.dispatches);
        }
        EXPECT_EQ(moves, std::to_string(st.substeps)) << "frame " << f;
        before = st;
    }
    // Measured on llvmpipe: in all 18.
    std::printf("the strain asked for more projections than the speed in %d of 18 frames\n", raised);
    EXPECT_GE(raised, 5) << "the strain never outweighed the speed: the test does not exercise the limit";
}

}  // namespace
}  // namespace pf::test
