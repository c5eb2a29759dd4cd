// Spray: a particle alone in its cell, in flight over liquid it does not touch, under FLIP. Its
// velocity stencil reaches faces between two AIR cells that P2G gave the liquid's velocity and the
// extrapolation refills after the projection; a FLIP delta taken there against P2G's leftovers fed
// on itself (docs/notes/2026-12-06-lone-particle-flip.md).
#include <cmath>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class Spray : public GpuTest {};

// A sheet 0.8 cells deep slides along the floor at 4 m/s; a droplet 2.08 cells up flies the other
// way at 4.5 m/s. Over four 1/60 s frames, before it reaches the sheet, only gravity can add to its
// speed: at most g·t above the start's (the grid may slow it or turn it with the sheet, never speed
// it up). Before the fix it reached 7.2 m/s in two frames.
TEST_F(Spray, LoneDropletOverAMovingSheetGainsNoSpeed) {
    const float dx = 0.05f;
    pf_sim_desc d = test_desc(32, 16, 32, dx);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {32 * dx, 0.8f * dx, 32 * dx}, sheet[3] = {4.0f, 0.0f, 0.0f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, sheet), PF_OK);
    const float drop[3] = {16.59f * dx, 2.08f * dx, 16.41f * dx}, drop_vel[3] = {-4.0f, 0.0f, -2.0f};
    ASSERT_EQ(pf_add_particles(sim.get(), drop, drop_vel, 1), PF_OK);
    const size_t last = read_all(sim.get()).count() - 1;
    const double speed0 = std::sqrt(double(drop_vel[0] * drop_vel[0] + drop_vel[2] * drop_vel[2]));
    const double frame = 1.0 / 60.0, g = 9.81;
    for (int f = 1; f <= 4; ++f) {
        ASSERT_EQ(pf_step(sim.get(), float(frame)), PF_OK);
        const ParticleState s = read_all(sim.get());
        ASSERT_EQ(s.count(), last + 1);
        const float* v = &s.vel[last * 3];
        const double speed = std::sqrt(double(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
        EXPECT_LE(speed, speed0 + g * f * frame) << "frame " << f;
        ASSERT_GT(s.pos[last * 3 + 1], 1.3f * dx) << "frame " << f << ": the droplet reached the sheet, too early for this test";
    }
}

}  // namespace
}  // namespace pf::test
