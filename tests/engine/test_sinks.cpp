// Sinks (PF_FEATURE_SINKS) through the public API: the GPU compaction removes exactly the
// particles inside and keeps every other one once (none lost, none duplicated), a drain empties
// a tank to the last particle and the simulation stays usable, the draw records engines use
// hold the live count, and bad sinks are refused with nothing changed.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class Sinks : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc)));
    }
};

constexpr float kFrame = 1.0f / 60.0f;

using Point = std::array<float, 3>;

std::vector<Point> points_of(const ParticleState& p) {
    std::vector<Point> out(p.count());
    for (size_t i = 0; i < p.count(); ++i) out[i] = {p.pos[i * 3], p.pos[i * 3 + 1], p.pos[i * 3 + 2]};
    std::sort(out.begin(), out.end());
    return out;
}

// Particles at rest in zero gravity with no volume correction stay exactly where they are, so
// after one step with a sink the particles must be exactly the starting ones outside the sink
// (compared as sorted lists: the compaction reorders survivors), each present once. Two sinks,
// one turned, both over parts of the fill; 4096 particles.
TEST_F(Sinks, CompactionRemovesExactlyThoseInsideAndKeepsEveryOtherOnce) {
    pf_sim_desc d = test_desc(16, 16, 16, 0.05f);
    d.features = PF_FEATURE_SINKS;
    d.params.gravity[1] = 0.0f;
    d.params.volume_correction = 0.0f;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.0f, 0.0f, 0.0f}, hi[3] = {0.4f, 0.4f, 0.4f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const std::vector<Point> start = points_of(read_all(sim.get()));
    ASSERT_EQ(start.size(), 4096u);
    pf_sink box = pf_default_sink();
    box.position[0] = 0.1f, box.position[1] = 0.1f, box.position[2] = 0.1f;
    const float s = std::sin(0.3f), c = std::cos(0.3f);
    box.rotation[0] = 0.0f, box.rotation[1] = s, box.rotation[2] = 0.0f, box.rotation[3] = c;  // 0.6 rad about y
    box.half_extents[0] = 0.08f, box.half_extents[1] = 0.05f, box.half_extents[2] = 0.06f;
    pf_sink ball = pf_default_sink();
    ball.shape = PF_SINK_SPHERE;
    ball.position[0] = 0.3f, ball.position[1] = 0.3f, ball.position[2] = 0.25f;
    ball.radius = 0.09f;
    ASSERT_EQ(pf_add_sink(sim.get(), &box, nullptr), PF_OK) << last_log();
    ASSERT_EQ(pf_add_sink(sim.get(), &ball, nullptr), PF_OK) << last_log();
    // The expected survivors, computed on the host with the same shapes.
    std::vector<Point> expected;
    for (const Point& p : start) {
        const double dx = p[0] - 0.1, dy = p[1] - 0.1, dz = p[2] - 0.1;
        // Into the box's frame: rotate by -0.6 rad about y.
        const double ca = std::cos(0.6), sa = std::sin(0.6);
        const double lx = ca * dx - sa * dz, lz = sa * dx + ca * dz;
        const bool in_box = std::abs(lx) < 0.08 && std::abs(dy) < 0.05 && std::abs(lz) < 0.06;
        const bool in_ball = std::hypot(p[0] - 0.3, p[1] - 0.3, p[2] - 0.25) < 0.09;
        if (!in_box && !in_ball) expected.push_back(p);
    }
    ASSERT_LT(expected.size(), start.size() - 200) << "both sinks should cover particles";
    ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    const std::vector<Point> after = points_of(read_all(sim.get()));
    EXPECT_EQ(after.size(), expected.size());
    EXPECT_TRUE(std::adjacent_find(after.begin(), after.end()) == after.end()) << "a particle was duplicated";
    EXPECT_EQ(after, expected);
    // A second step removes nothing more.
    ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    EXPECT_EQ(points_of(read_all(sim.get())), expected);
}

// A tank drained through a box sink in its floor (reaching below the domain, as a drain cut by
// the floor may): the count falls every few frames and reaches exactly 0; with no particles
// left the simulation steps, renders and takes new particles.
TEST_F(Sinks, DrainEmptiesATankToTheLastParticle) {
    pf_sim_desc d = test_desc(12, 12, 12, 0.05f);
    d.features = PF_FEATURE_SINKS;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.0f, 0.0f, 0.0f}, hi[3] = {0.6f, 0.3f, 0.6f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const uint32_t full = live_count(sim.get());
    pf_sink drain = pf_default_sink();
    drain.position[0] = 0.3f, drain.position[1] = 0.0f, drain.position[2] = 0.3f;
    drain.half_extents[0] = 0.3f, drain.half_extents[1] = 0.06f, drain.half_extents[2] = 0.3f;
    ASSERT_EQ(pf_add_sink(sim.get(), &drain, nullptr), PF_OK) << last_log();
    uint32_t previous = full;
    int frames = 0;
    for (; frames < 600 && previous > 0; ++frames) {
        ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
        if (frames % 10 != 9) continue;
        const uint32_t now = live_count(sim.get());
        EXPECT_LE(now, previous);
        previous = now;
        pf_gl_buffers b{};
        ASSERT_EQ(pf_get_gl_buffers(sim.get(), &b), PF_OK);
        EXPECT_GE(b.count, now);  // the host's bound never undercounts
    }
    EXPECT_EQ(live_count(sim.get()), 0u) << "after " << frames << " frames";
    // The top particles must fall 0.3 - 0.06 m into the drain: at least the free-fall time
    // sqrt(2 * 0.24 / 9.81) = 0.221 s (13.3 frames); the liquid falls freely once its bottom
    // is gone, so well within a second (measured: 20 frames, counted in tens).
    EXPECT_GE(frames, 14);
    EXPECT_LE(frames, 60);
    RecordProperty("frames_to_drain", std::to_string(frames));
    for (int f = 0; f < 5; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    pf_stats st{};
    ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
    EXPECT_EQ(st.particle_count, 0u);  // the readback arrived: the stats agree
    EXPECT_EQ(st.flags & PF_FLAG_NONFINITE, 0u);
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    EXPECT_EQ(live_count(sim.get()), full);
    ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    EXPECT_LT(live_count(sim.get()), full);  // draining again
}

// pf_gl_buffers.draw_indirect holds {live, 1, 0, 0} and {4, live, 0, 0} after every kind of
// change: fill, the sink's compaction, clear.
TEST_F(Sinks, DrawRecordsHoldTheLiveCount) {
    pf_sim_desc d = test_desc(12, 12, 12, 0.05f);
    d.features = PF_FEATURE_SINKS;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    auto record = [&] {
        pf_gl_buffers b{};
        EXPECT_EQ(pf_get_gl_buffers(sim.get(), &b), PF_OK);
        std::array<uint32_t, 8> words{};
        glBindBuffer(GL_COPY_READ_BUFFER, b.draw_indirect);
        glGetBufferSubData(GL_COPY_READ_BUFFER, 0, sizeof(words), words.data());
        glBindBuffer(GL_COPY_READ_BUFFER, 0);
        return words;
    };
    auto expect = [](uint32_t n) { return std::array<uint32_t, 8>{n, 1, 0, 0, 4, n, 0, 0}; };
    EXPECT_EQ(record(), expect(0));
    const float lo[3] = {0.0f, 0.0f, 0.0f}, hi[3] = {0.6f, 0.3f, 0.6f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    EXPECT_EQ(record(), expect(live_count(sim.get())));
    pf_sink k = pf_default_sink();
    k.position[0] = 0.3f, k.position[1] = 0.1f, k.position[2] = 0.3f;
    ASSERT_EQ(pf_add_sink(sim.get(), &k, nullptr), PF_OK);
    ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    const uint32_t n = live_count(sim.get());
    EXPECT_LT(n, 12u * 6u * 12u * 8u);
    EXPECT_EQ(record(), expect(n));
    ASSERT_EQ(pf_clear_particles(sim.get()), PF_OK);
    EXPECT_EQ(record(), expect(0));
}

// Bad sinks: each refused with a logged reason and nothing changed.
TEST_F(Sinks, BadSinksAreRefusedAndChangeNothing) {
    pf_sim_desc d = test_desc(12, 12, 12, 0.05f);
    d.features = PF_FEATURE_SINKS;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.0f, 0.0f, 0.0f}, hi[3] = {0.6f, 0.3f, 0.6f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    pf_sink good = pf_default_sink();
    good.position[0] = 0.5f, good.position[1] = 0.55f, good.position[2] = 0.5f;  // in the air: removes nothing
    uint32_t id = 0;
    ASSERT_EQ(pf_add_sink(sim.get(), &good, &id), PF_OK);
    struct Case {
        const char* what;
        const char* message;
        void (*edit)(pf_sink&);
    };
    const Case cases[] = {
        {"unknown shape", "unknown sink shape", [](pf_sink& k) { k.shape = pf_sink_shape(2); }},
        {"negative shape", "unknown sink shape", [](pf_sink& k) { k.shape = pf_sink_shape(-3); }},
        {"NaN position", "finite", [](pf_sink& k) { k.position[2] = std::nanf(""); }},
        {"NaN rotation", "finite", [](pf_sink& k) { k.rotation[0] = std::nanf(""); }},
        {"Inf half extent", "finite", [](pf_sink& k) { k.half_extents[0] = INFINITY; }},
        {"zero half extent", "half_extents[2] must be > 0", [](pf_sink& k) { k.half_extents[2] = 0.0f; }},
        {"negative radius", "radius must be > 0", [](pf_sink& k) { k.shape = PF_SINK_SPHERE, k.radius = -1.0f; }},
        {"misses the domain", "does not overlap the domain", [](pf_sink& k) { k.position[1] = -0.5f; }},
    };
    for (const Case& c : cases) {
        pf_sink bad = good;
        c.edit(bad);
        clear_log();
        EXPECT_EQ(pf_add_sink(sim.get(), &bad, nullptr), PF_ERROR_INVALID_ARGUMENT) << c.what;
        EXPECT_NE(std::string(last_log()).find(c.message), std::string::npos) << c.what << ": " << last_log();
        EXPECT_EQ(pf_set_sink(sim.get(), id, &bad), PF_ERROR_INVALID_ARGUMENT) << c.what;
    }
    EXPECT_EQ(pf_add_sink(sim.get(), nullptr, nullptr), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_remove_sink(sim.get(), id + 7), PF_ERROR_INVALID_ARGUMENT);
    const uint32_t before = live_count(sim.get());
    for (int f = 0; f < 3; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    EXPECT_EQ(live_count(sim.get()), before);  // the one good sink is in the air
    ASSERT_EQ(pf_remove_sink(sim.get(), id), PF_OK);
    for (uint32_t i = 0; i < PF_MAX_SINKS; ++i) ASSERT_EQ(pf_add_sink(sim.get(), &good, nullptr), PF_OK);
    EXPECT_EQ(pf_add_sink(sim.get(), &good, nullptr), PF_ERROR_CAPACITY);
}

}  // namespace
}  // namespace pf::test
