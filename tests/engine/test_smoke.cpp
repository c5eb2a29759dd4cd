#include <cmath>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class Smoke : public GpuTest {};

TEST_F(Smoke, DamBreakRunsAndStaysFinite) {
    pf_sim_desc d = test_desc(16, 16, 16);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.0f, 0.0f, 0.0f}, hi[3] = {0.6f, 1.0f, 1.6f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK) << last_log();
    for (int i = 0; i < 10; ++i) ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    ParticleState p = read_all(sim.get());
    ASSERT_GT(p.count(), 0u);
    for (size_t i = 0; i < p.count() * 3; ++i) {
        ASSERT_TRUE(std::isfinite(p.pos[i]));
        ASSERT_TRUE(std::isfinite(p.vel[i]));
    }
    const double max_speed = max_speed_of(p);
    EXPECT_GT(max_speed, 0.1);   // the column is collapsing
    EXPECT_LT(max_speed, 10.0);  // and nothing exploded
}

}  // namespace
}  // namespace pf::test
