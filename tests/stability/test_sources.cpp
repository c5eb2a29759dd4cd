// Case 11 (docs/stability.md), emitters and sinks: an emitter inside an obstacle (its particles
// start inside the solid and must end every step outside it), a sink draining a tank to its
// last particle and a lone particle dropped into a sink (the simulation then steps on with no
// particles and takes new ones), and a fountain pouring into a drain for seconds (the count
// stays bounded, every particle sound). Every case under every preset.
#include <cmath>

#include "stability/stability.h"

namespace pf::test {
namespace {

class SourceStability : public Stability {};

constexpr float kFrame = 1.0f / 60.0f;

// An emitter (a ball of 0.1 m, 10 particles a frame at rest) inside a sphere obstacle of
// 0.15 m: every new particle starts inside the solid; the obstacle pushes each out after the
// step's advection, so after every frame no particle centre lies inside, the count is exactly
// what was emitted, and the particles pushed onto the sphere run off it under gravity.
TEST_P(SourceStability, EmitterInsideAnObstacle) {
    pf_sim_desc d = desc(16, 16, 16, 0.05f);
    d.features = PF_FEATURE_OBSTACLES | PF_FEATURE_EMITTERS;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    pf_obstacle ball = pf_default_obstacle();
    ball.shape = PF_OBSTACLE_SPHERE;
    ball.radius = 0.15f;
    ball.position[0] = 0.4f, ball.position[1] = 0.4f, ball.position[2] = 0.4f;
    ASSERT_EQ(pf_add_obstacle(sim.get(), &ball, nullptr), PF_OK);
    pf_emitter e = pf_default_emitter();
    e.position[0] = 0.4f, e.position[1] = 0.4f, e.position[2] = 0.4f;
    e.radius = 0.1f;
    e.rate = 600.0f;
    uint32_t id = 0;
    ASSERT_EQ(pf_add_emitter(sim.get(), &e, &id), PF_OK) << last_log();
    double deepest = 0, fastest = 0;
    const int frames = 60;
    for (int f = 1; f <= frames; ++f) {
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), kFrame, 1));
        if (f % 10 != 0) continue;
        const Soundness s = check(sim.get(), d, size_t(10 * f), "frame " + std::to_string(f));
        fastest = std::max(fastest, s.max_speed);
        const ParticleState p = read_all(sim.get());
        for (size_t i = 0; i < p.count(); ++i) {
            double r2 = 0;
            for (int a = 0; a < 3; ++a) r2 += std::pow(double(p.pos[i * 3 + a]) - ball.position[a], 2);
            deepest = std::min(deepest, std::sqrt(r2) - ball.radius);
        }
        if (HasFailure()) return;
    }
    record("deepest_inside_m", deepest);
    record("max_speed", fastest);
    EXPECT_GT(deepest, -1e-5);
    // Nothing falls faster than free fall from the top of the domain for the run's second: the
    // push-out adds no speed of its own.
    EXPECT_LT(fastest, 9.81 * frames * kFrame);
    ASSERT_EQ(pf_remove_emitter(sim.get(), id), PF_OK);
    expect_usable(sim.get(), d, "after the emitter");
}

// A tank 0.25 m deep over a floor drain: the count only falls and reaches exactly 0 within a
// second; then, with no particle left, 30 more frames step soundly, the stats catch up, and a
// lone particle dropped from 0.4 m into the drain is removed too (the last particle again).
TEST_P(SourceStability, SinkDrainsTheLastParticle) {
    pf_sim_desc d = desc(12, 12, 12, 0.05f);
    d.features = PF_FEATURE_SINKS;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.0f, 0.0f, 0.0f}, hi[3] = {0.6f, 0.25f, 0.6f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    uint32_t previous = live_count(sim.get());
    pf_sink drain = pf_default_sink();
    drain.position[0] = 0.3f, drain.position[1] = 0.0f, drain.position[2] = 0.3f;
    drain.half_extents[0] = 0.3f, drain.half_extents[1] = 0.05f, drain.half_extents[2] = 0.3f;
    ASSERT_EQ(pf_add_sink(sim.get(), &drain, nullptr), PF_OK);
    int f = 0;
    for (; f < 60 && previous > 0; f += 5) {
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), kFrame, 5));
        const uint32_t now = live_count(sim.get());
        EXPECT_LE(now, previous) << "frame " << f;
        check(sim.get(), d, now, "frame " + std::to_string(f));
        previous = now;
        if (HasFailure()) return;
    }
    EXPECT_EQ(previous, 0u);
    record("frames_to_drain", f);
    ASSERT_NO_FATAL_FAILURE(run(sim.get(), kFrame, 30));
    check(sim.get(), d, 0, "30 frames empty");
    EXPECT_EQ(settled_stats(sim.get()).particle_count, 0u);
    const float x[3] = {0.3f, 0.4f, 0.3f};
    ASSERT_EQ(pf_add_particles(sim.get(), x, nullptr, 1), PF_OK);
    ASSERT_NO_FATAL_FAILURE(run(sim.get(), kFrame, 30));  // falls 0.35 m in 0.27 s
    check(sim.get(), d, 0, "the lone particle");
    expect_usable(sim.get(), d, "after draining");
}

// A fountain (a disc nozzle, 3 m/s upwards, 1200 particles/s) over a floor drain for 3 s: the
// pool it feeds drains as fast as it fills, so the count levels off far below what was emitted
// (bounded: at most the particles of 1 s in flight and pooled), and every particle stays sound.
TEST_P(SourceStability, FountainIntoADrainStaysBounded) {
    pf_sim_desc d = desc(12, 16, 12, 0.05f);
    d.features = PF_FEATURE_EMITTERS | PF_FEATURE_SINKS;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    pf_emitter e = pf_default_emitter();
    e.shape = PF_EMITTER_DISC;
    e.position[0] = 0.3f, e.position[1] = 0.1f, e.position[2] = 0.3f;
    e.radius = 0.04f;
    e.velocity[1] = 3.0f;
    e.rate = 1200.0f;
    ASSERT_EQ(pf_add_emitter(sim.get(), &e, nullptr), PF_OK);
    pf_sink drain = pf_default_sink();
    drain.position[0] = 0.3f, drain.position[1] = 0.0f, drain.position[2] = 0.3f;
    drain.half_extents[0] = 0.3f, drain.half_extents[1] = 0.03f, drain.half_extents[2] = 0.3f;
    ASSERT_EQ(pf_add_sink(sim.get(), &drain, nullptr), PF_OK);
    uint32_t most = 0;
    for (int s = 1; s <= 3; ++s) {
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), kFrame, 60));
        const uint32_t now = live_count(sim.get());
        check(sim.get(), d, now, "second " + std::to_string(s));
        most = std::max(most, now);
        if (HasFailure()) return;
    }
    record("most_particles", most);
    EXPECT_GT(most, 0u);
    EXPECT_LE(most, 1200u);  // never more than one second's emission alive at once
    EXPECT_EQ(settled_stats(sim.get()).flags & (PF_FLAG_NONFINITE | PF_FLAG_EMITTERS_FULL), 0u);
}

PF_STABILITY_PRESETS(SourceStability);

}  // namespace
}  // namespace pf::test
