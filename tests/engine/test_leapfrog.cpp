// PF_ADVECTION_LEAPFROG (docs/design.md §5): a block of liquid thrown through the air follows its
// parabola exactly, however the frames are cut into substeps, where Euler's whole moves at the
// end-of-substep velocity put it ahead by g/2 times the sum of the squared substeps. Positions and
// velocities meet at the frame's end (nothing to correct when reading them).
#include <cmath>
#include <cstdio>
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

}  // namespace
}  // namespace pf::test
