// Case 11 (docs/stability.md), the obstacle part: obstacles (PF_FEATURE_OBSTACLES) moved by the
// engine with pf_set_obstacle faster than one cell per step through liquid. Moved without a
// velocity the obstacle is teleported, so the liquid it lands on is pushed out along the distance
// gradient after advection; moved with its velocity, its solid faces also push the liquid
// (v + w x r) and the CFL estimate takes its surface speed. Either way every particle must stay
// sound and outside it after every step (measured with the feature off: particle centres up to
// 0.13 m inside), and its force readback finite. Emitters and sinks: tests/stability/test_sources.cpp.
#include <cmath>

#include "stability/stability.h"

namespace pf::test {
namespace {

class ObstacleStability : public Stability {
protected:
    void sweep(bool with_velocity);
};

TEST_P(ObstacleStability, SphereSweptThroughLiquidAtTwoAndAHalfCellsPerStep) { sweep(false); }

TEST_P(ObstacleStability, SphereSweptWithItsVelocityAtTwoAndAHalfCellsPerStep) { sweep(true); }

void ObstacleStability::sweep(bool with_velocity) {
    pf_sim_desc d = desc(16, 8, 8, 0.1f);
    d.features = PF_FEATURE_OBSTACLES;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {1.6f, 0.4f, 0.8f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const size_t n = settled_stats(sim.get()).particle_count;
    pf_obstacle ball = pf_default_obstacle();
    ball.shape = PF_OBSTACLE_SPHERE;
    ball.radius = 0.15f;
    ball.position[0] = 0.2f, ball.position[1] = 0.2f, ball.position[2] = 0.4f;
    uint32_t id = 0;
    ASSERT_EQ(pf_add_obstacle(sim.get(), &ball, &id), PF_OK) << last_log();
    double deepest = 0;
    for (int f = 1; f <= 5 * 2; ++f) {
        // 0.25 m (2.5 cells) per 1/60 s frame: 15 m/s, back and forth across the tank.
        ball.position[0] = 0.2f + 0.25f * float(f <= 5 ? f : 10 - f);
        if (with_velocity) ball.velocity[0] = f <= 5 ? 15.0f : -15.0f;
        ASSERT_EQ(pf_set_obstacle(sim.get(), id, &ball), PF_OK);
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 1));
        check(sim.get(), d, n, "frame " + std::to_string(f));
        pf_obstacle_force force{};
        ASSERT_EQ(pf_get_obstacle_force(sim.get(), id, &force), PF_OK);
        for (int a = 0; a < 3; ++a) ASSERT_TRUE(std::isfinite(force.force[a]) && std::isfinite(force.torque[a]));
        const ParticleState p = read_all(sim.get());
        for (size_t i = 0; i < p.count(); ++i) {
            double r2 = 0;
            for (int a = 0; a < 3; ++a) r2 += std::pow(double(p.pos[i * 3 + a]) - ball.position[a], 2);
            deepest = std::min(deepest, std::sqrt(r2) - ball.radius);
        }
        if (HasFailure()) return;
    }
    record("deepest_inside_m", deepest);
    // Pushed out after every step: no centre deeper than float rounding inside the sphere.
    EXPECT_GT(deepest, -1e-5);
    ball.velocity[0] = 0.0f;
    ASSERT_EQ(pf_set_obstacle(sim.get(), id, &ball), PF_OK);
    ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 30));
    check(sim.get(), d, n, "settled after the sweep");
    expect_usable(sim.get(), d, "after the sweep");
}

PF_STABILITY_PRESETS(ObstacleStability);

}  // namespace
}  // namespace pf::test
