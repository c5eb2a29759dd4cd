// pf_push: the velocity impulse lands exactly where and as strongly as documented, is
// validated, is clamped to max_speed, and the next step's CFL estimate sees it.
#include <glad/gl.h>

#include <cmath>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class Push : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc)));
    }
};

TEST_F(Push, ImpulseFollowsTheFalloffInsideTheSphereOnly) {
    pf_sim_desc d = test_desc(16, 16, 16, 0.1f);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.2f, 0.2f, 0.2f}, hi[3] = {1.4f, 1.4f, 1.4f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const float c[3] = {0.8f, 0.7f, 0.9f}, r = 0.35f, dv[3] = {1.5f, -0.5f, 2.0f};
    ASSERT_EQ(pf_push(sim.get(), c, r, dv), PF_OK) << last_log();
    ParticleState p = read_all(sim.get());
    int inside = 0;
    for (size_t i = 0; i < p.count(); ++i) {
        const double dx = p.pos[i * 3] - c[0], dy = p.pos[i * 3 + 1] - c[1], dz = p.pos[i * 3 + 2] - c[2];
        const double q = (dx * dx + dy * dy + dz * dz) / (double(r) * r);
        const double w = q < 1.0 ? (1.0 - q) * (1.0 - q) : 0.0;
        inside += q < 1.0;
        for (int a = 0; a < 3; ++a) ASSERT_NEAR(p.vel[i * 3 + a], w * dv[a], 1e-5) << "particle " << i;
    }
    EXPECT_GT(inside, 100);  // the sphere really covered liquid
}

TEST_F(Push, ClampsToMaxSpeedAndRaisesTheFlag) {
    pf_sim_desc d = test_desc(8, 8, 8, 0.1f);
    d.max_speed = 5.0f;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.2f, 0.2f, 0.2f}, hi[3] = {0.6f, 0.6f, 0.6f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const float c[3] = {0.4f, 0.4f, 0.4f}, dv[3] = {0.0f, 40.0f, 0.0f};
    ASSERT_EQ(pf_push(sim.get(), c, 1.0f, dv), PF_OK);
    ParticleState p = read_all(sim.get());
    const double fastest = max_speed_of(p);
    EXPECT_LE(fastest, 5.0 * (1 + 1e-6));
    EXPECT_GT(fastest, 4.9);
    glFinish();
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);  // the status readback of this step carries the flag
    glFinish();
    pf_stats st{};
    ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
    EXPECT_NE(st.flags & PF_FLAG_SPEED_CLAMPED, 0u);
}

// A huge finite impulse is clamped along its direction, not zeroed: |v|^2 of dv = 1e20 is beyond
// float range, and v * max_speed / |v| used to turn it into 0 (issue 7).
TEST_F(Push, HugeImpulseIsClampedAlongItsDirection) {
    for (const float magnitude : {1e20f, 3e38f}) {
        SCOPED_TRACE(magnitude);
        pf_sim_desc d = test_desc(8, 8, 8, 0.1f);
        d.max_speed = 5.0f;
        SimPtr sim = create(d);
        ASSERT_TRUE(sim);
        const float lo[3] = {0.2f, 0.2f, 0.2f}, hi[3] = {0.6f, 0.6f, 0.6f};
        ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
        const float c[3] = {0.4f, 0.4f, 0.4f}, dv[3] = {magnitude, -magnitude, 0.5f * magnitude};
        ASSERT_EQ(pf_push(sim.get(), c, 1.0f, dv), PF_OK) << last_log();
        const ParticleState p = read_all(sim.get());
        const double norm = 1.5;  // |(1, -1, 0.5)|
        for (size_t i = 0; i < p.count(); ++i) {
            ASSERT_NEAR(p.vel[i * 3 + 0], 5.0 * 1.0 / norm, 1e-4) << "particle " << i;
            ASSERT_NEAR(p.vel[i * 3 + 1], -5.0 * 1.0 / norm, 1e-4) << "particle " << i;
            ASSERT_NEAR(p.vel[i * 3 + 2], 5.0 * 0.5 / norm, 1e-4) << "particle " << i;
        }
    }
}

// A centre and radius near float range: |offset|^2 and r^2 are both +Inf in float, and their
// ratio NaN (the API fuzzer found NaN velocities from exactly this). The falloff is computed
// without squaring first, so particles get the impulse they should: a radius of 1e20 around a
// centre 1e20 away covers them with falloff ~0, a radius of FLT_MAX around a centre at the
// domain covers them fully.
TEST_F(Push, CentreAndRadiusNearFloatRangeStayFinite) {
    pf_sim_desc d = test_desc(8, 8, 8, 0.1f);
    d.max_speed = 5.0f;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.2f, 0.2f, 0.2f}, hi[3] = {0.4f, 0.4f, 0.4f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const float dv[3] = {1.0f, 0.0f, 0.0f};
    const float far[3] = {1e20f, 0.3f, 0.3f}, huge_centre[3] = {3.4e38f, 0.3f, 0.3f}, near[3] = {0.3f, 0.3f, 0.3f};
    ASSERT_EQ(pf_push(sim.get(), far, 1e20f, dv), PF_OK);
    ASSERT_EQ(pf_push(sim.get(), huge_centre, 3.4e38f, dv), PF_OK);
    ParticleState p = read_all(sim.get());
    for (size_t i = 0; i < p.count(); ++i) {
        ASSERT_TRUE(std::isfinite(p.vel[i * 3]) && std::isfinite(p.vel[i * 3 + 1]) && std::isfinite(p.vel[i * 3 + 2]))
            << "particle " << i;
        ASSERT_LT(p.vel[i * 3], 1e-3) << "a sphere whose rim passes the liquid gives it (almost) nothing";
    }
    ASSERT_EQ(pf_push(sim.get(), near, 3.4e38f, dv), PF_OK);
    p = read_all(sim.get());
    for (size_t i = 0; i < p.count(); ++i) ASSERT_NEAR(p.vel[i * 3], 1.0, 2e-3) << "particle " << i;
}

// Right after a push the GPU readback does not know the new speeds yet; the substep count
// of the next step must still honour CFL for them.
TEST_F(Push, NextStepTakesSubstepsForThePushedSpeed) {
    pf_sim_desc d = test_desc(16, 16, 16, 0.1f);
    d.params.gravity[1] = 0.0f;
    d.params.max_substeps = 32;
    d.params.cfl = 1.0f;  // the count below
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.4f, 0.4f, 0.4f}, hi[3] = {1.2f, 1.2f, 1.2f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    for (int i = 0; i < 3; ++i) ASSERT_EQ(pf_step(sim.get(), 1.0f / 30.0f), PF_OK);
    glFinish();
    pf_stats st{};
    pf_get_stats(sim.get(), &st);
    ASSERT_EQ(st.substeps, 1u);  // at rest
    const float c[3] = {0.8f, 0.8f, 0.8f}, dv[3] = {8.0f, 0.0f, 0.0f};
    ASSERT_EQ(pf_push(sim.get(), c, 0.3f, dv), PF_OK);
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 30.0f), PF_OK);
    pf_get_stats(sim.get(), &st);
    EXPECT_EQ(st.substeps, uint32_t(std::ceil((1.0 / 30.0) * 8.0 / (d.params.cfl * 0.1))));  // at CFL 1: 2.67 -> 3
    EXPECT_GT(st.substeps, 1u);
}

TEST_F(Push, RejectsBadArgumentsAndChangesNothing) {
    pf_sim_desc d = test_desc(8, 8, 8, 0.1f);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.2f, 0.2f, 0.2f}, hi[3] = {0.6f, 0.6f, 0.6f}, v[3] = {0.1f, 0.2f, 0.3f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, v), PF_OK);
    ParticleState before = read_all(sim.get());
    const float c[3] = {0.4f, 0.4f, 0.4f}, dv[3] = {1, 1, 1}, bad[3] = {NAN, 0, 0}, inf[3] = {0, INFINITY, 0};
    EXPECT_EQ(pf_push(nullptr, c, 0.1f, dv), PF_ERROR_INVALID_ARGUMENT);
    clear_log();
    EXPECT_EQ(pf_push(sim.get(), nullptr, 0.1f, dv), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(last_log()).find("pf_push"), std::string::npos);
    EXPECT_EQ(pf_push(sim.get(), c, 0.1f, nullptr), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_push(sim.get(), bad, 0.1f, dv), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_push(sim.get(), c, 0.1f, inf), PF_ERROR_INVALID_ARGUMENT);
    for (float r : {0.0f, -1.0f, NAN, INFINITY}) EXPECT_EQ(pf_push(sim.get(), c, r, dv), PF_ERROR_INVALID_ARGUMENT) << r;
    ParticleState after = read_all(sim.get());
    EXPECT_EQ(before.vel, after.vel);
    EXPECT_EQ(before.pos, after.pos);
}

}  // namespace
}  // namespace pf::test
