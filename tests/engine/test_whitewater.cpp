// Whitewater (PF_FEATURE_WHITEWATER) against what it promises: a tank at rest makes none; a jet
// falling into a pool makes it, every particle inside the domain with a kind and a life within
// the set range; an obstacle stops spray at its face; the count never exceeds the capacity, and
// a full capacity raises and logs PF_FLAG_WHITEWATER_FULL; with the rates at zero every particle
// is gone after the longest lifetime; the liquid moves bit for bit as without it (it never acts
// on the liquid); the buffers are there only while it is on and keep their names; a snapshot
// keeps the parameters and clears the particles; bad parameters are refused with nothing changed.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "support/engine_state.h"
#include "support/render_scene.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

constexpr float kFrame = 1.0f / 60.0f;

struct Whitewater {
    std::vector<float> pos, vel;  // 4 floats per particle
    uint32_t count() const { return uint32_t(pos.size() / 4); }
};

// The live whitewater particles, read from pf_get_whitewater_buffers (waits for the GPU).
Whitewater read_whitewater(pf_sim* sim) {
    pf_whitewater_buffers b{};
    EXPECT_EQ(pf_get_whitewater_buffers(sim, &b), PF_OK) << last_log();
    std::array<uint32_t, 8> record{};
    glBindBuffer(GL_COPY_READ_BUFFER, b.draw_indirect);
    glGetBufferSubData(GL_COPY_READ_BUFFER, 0, sizeof(record), record.data());
    EXPECT_EQ(record[1], 1u);
    EXPECT_EQ(record[4], 4u);
    EXPECT_EQ(record[5], record[0]);  // both draw records hold the live count
    EXPECT_LE(record[0], b.capacity);
    Whitewater w;
    w.pos.resize(size_t(record[0]) * 4);
    w.vel.resize(size_t(record[0]) * 4);
    if (record[0] > 0) {
        glBindBuffer(GL_COPY_READ_BUFFER, b.positions);
        glGetBufferSubData(GL_COPY_READ_BUFFER, 0, GLsizeiptr(w.pos.size() * 4), w.pos.data());
        glBindBuffer(GL_COPY_READ_BUFFER, b.velocities);
        glGetBufferSubData(GL_COPY_READ_BUFFER, 0, GLsizeiptr(w.vel.size() * 4), w.vel.data());
    }
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    return w;
}

class WhitewaterTest : public GpuTest {
protected:
    // A 0.8 m x 1.2 m x 0.8 m tank of 5 cm cells with a pool 0.3 m deep.
    SimPtr pool(uint32_t features) {
        pf_sim_desc d = test_desc(16, 24, 16, 0.05f);
        d.features = features;
        d.max_particles = 1u << 18;
        SimPtr sim = create(d);
        if (!sim) return sim;
        const float lo[3] = {0.0f, 0.0f, 0.0f}, hi[3] = {0.8f, 0.3f, 0.8f};
        EXPECT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
        return sim;
    }
    // A disc nozzle 0.9 m up shooting 3 m/s down into the pool.
    static void add_jet(pf_sim* sim) {
        pf_emitter e = pf_default_emitter();
        e.shape = PF_EMITTER_DISC;
        e.position[0] = 0.4f, e.position[1] = 0.9f, e.position[2] = 0.4f;
        e.rotation[0] = 1.0f, e.rotation[1] = 0.0f, e.rotation[2] = 0.0f, e.rotation[3] = 0.0f;  // local +y -> -y
        e.radius = 0.08f;
        e.velocity[1] = -3.0f;
        e.rate = 12000.0f;
        ASSERT_EQ(pf_add_emitter(sim, &e, nullptr), PF_OK) << last_log();
    }
    static void set(pf_sim* sim, const pf_whitewater& w) { ASSERT_EQ(pf_set_whitewater(sim, &w), PF_OK) << last_log(); }
};

// Liquid at rest traps no air, breaks nowhere and moves too slowly: nothing is made in 1 s.
TEST_F(WhitewaterTest, RestingTankMakesNone) {
    SimPtr sim = pool(PF_FEATURE_WHITEWATER);
    ASSERT_TRUE(sim);
    for (int f = 0; f < 60; ++f) {
        ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
        if (f % 20 == 19) EXPECT_EQ(read_whitewater(sim.get()).count(), 0u) << "frame " << f + 1;
    }
    pf_stats st{};
    st.struct_size = sizeof st;
    ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
    EXPECT_EQ(st.whitewater_count, 0u);
    EXPECT_EQ(st.flags & PF_FLAG_WHITEWATER_FULL, 0u);
}

// A 3 m/s jet plunging into the pool makes whitewater within a second: every particle inside
// the domain, of a known kind, with a life within the set range, bubbles inside the liquid;
// the count reaches pf_stats.
TEST_F(WhitewaterTest, JetIntoAPoolMakesSprayFoamAndBubbles) {
    SimPtr sim = pool(PF_FEATURE_WHITEWATER | PF_FEATURE_EMITTERS);
    ASSERT_TRUE(sim);
    add_jet(sim.get());
    const pf_whitewater settings = pf_default_whitewater();
    for (int f = 0; f < 60; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    const Whitewater w = read_whitewater(sim.get());
    ASSERT_GT(w.count(), 100u);
    // Which of the 16 x 24 x 16 cells hold liquid particles, and how many of the 27 around a point do.
    const ParticleState liquid = read_all(sim.get());
    std::vector<uint8_t> wet(16 * 24 * 16, 0);
    auto cell_of = [](const float* x, int a) { return std::clamp(int(std::floor(x[a] / 0.05f)), 0, a == 1 ? 23 : 15); };
    for (size_t i = 0; i < liquid.count(); ++i) {
        const float* x = &liquid.pos[i * 3];
        wet[size_t(cell_of(x, 0) + 16 * (cell_of(x, 1) + 24 * cell_of(x, 2)))] = 1;
    }
    auto liquid_near = [&](const float* x) {
        int n = 0;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int c[3] = {cell_of(x, 0) + dx, cell_of(x, 1) + dy, cell_of(x, 2) + dz};
                    if (c[0] < 0 || c[1] < 0 || c[2] < 0 || c[0] > 15 || c[1] > 23 || c[2] > 15) continue;
                    n += wet[size_t(c[0] + 16 * (c[1] + 24 * c[2]))];
                }
        return n;
    };
    uint32_t kinds[3] = {0, 0, 0};
    for (uint32_t i = 0; i < w.count(); ++i) {
        const float* p = &w.pos[size_t(i) * 4];
        const float* v = &w.vel[size_t(i) * 4];
        for (int a = 0; a < 3; ++a) {
            ASSERT_TRUE(std::isfinite(p[a]) && std::isfinite(v[a])) << i;
            EXPECT_GE(p[a], 0.0f) << i;
        }
        EXPECT_LE(p[0], 0.8f);
        EXPECT_LE(p[1], 1.2f);
        EXPECT_LE(p[2], 0.8f);
        EXPECT_GT(p[3], 0.0f) << "a particle past its life was kept";
        EXPECT_LE(p[3], settings.lifetime[1]) << i;
        const int kind = int(v[3]);
        ASSERT_TRUE(v[3] == float(kind) && kind >= PF_WHITEWATER_SPRAY && kind <= PF_WHITEWATER_BUBBLE) << v[3];
        ++kinds[kind];
        // Bubbles are inside the liquid (the pool or the jet's column): liquid particles in
        // the cells around them (they were classified before this step's move).
        if (kind == PF_WHITEWATER_BUBBLE) EXPECT_GE(liquid_near(p), 9) << i << " at " << p[0] << " " << p[1] << " " << p[2];
    }
    EXPECT_GT(kinds[PF_WHITEWATER_FOAM], 0u);
    EXPECT_GT(kinds[PF_WHITEWATER_BUBBLE], 0u);
    for (int f = 0; f < 4; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);  // the stats lag a few steps
    pf_stats st{};
    st.struct_size = sizeof st;
    ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
    EXPECT_GT(st.whitewater_count, 100u);
}

// A wall of obstacle one cell thick splits the tank beside the jet: whitewater stops at it as
// at the domain's walls. After every step no whitewater particle is inside the wall's cells or
// beyond it (its side of the tank holds still liquid, which makes none), and spray does reach its
// face. Before the change a particle moved into the wall and was dropped a step later.
TEST_F(WhitewaterTest, SprayStopsAtAnObstacle) {
    SimPtr sim = pool(PF_FEATURE_WHITEWATER | PF_FEATURE_EMITTERS | PF_FEATURE_OBSTACLES);
    ASSERT_TRUE(sim);
    add_jet(sim.get());
    // Cells x = 11, every y and z (cell centres inside the box are SOLID), 0.07 m from the jet.
    const float lo[3] = {0.55f, 0.0f, 0.0f}, hi[3] = {0.6f, 1.2f, 0.8f};
    pf_obstacle wall = pf_default_obstacle();
    wall.shape = PF_OBSTACLE_BOX;
    for (int a = 0; a < 3; ++a) {
        wall.position[a] = 0.5f * (lo[a] + hi[a]);
        wall.half_extents[a] = 0.5f * (hi[a] - lo[a]);
    }
    ASSERT_EQ(pf_add_obstacle(sim.get(), &wall, nullptr), PF_OK) << last_log();
    uint32_t inside = 0, beyond = 0, at_face = 0, seen = 0;
    for (int f = 0; f < 90; ++f) {
        ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
        if (f < 20) continue;
        const Whitewater w = read_whitewater(sim.get());
        seen += w.count();
        for (uint32_t i = 0; i < w.count(); ++i) {
            const float x = w.pos[size_t(i) * 4];
            inside += x >= lo[0] && x < hi[0];
            beyond += x >= hi[0];
            at_face += x >= lo[0] - 0.05f && x < lo[0];
        }
    }
    std::printf("%u whitewater particles seen over 70 steps, %u within a cell of the wall, %u inside it, %u beyond\n",
                seen, at_face, inside, beyond);
    EXPECT_GT(at_face, 20u) << "the spray must reach the wall for this test to mean anything";
    EXPECT_EQ(inside, 0u);
    EXPECT_EQ(beyond, 0u);
}

// 64 slots and rates far beyond them: the count stops at exactly 64, PF_FLAG_WHITEWATER_FULL is
// raised and logged.
TEST_F(WhitewaterTest, CountStopsAtTheCapacityWithAFlagAndALogLine) {
    SimPtr sim = pool(PF_FEATURE_WHITEWATER | PF_FEATURE_EMITTERS);
    ASSERT_TRUE(sim);
    add_jet(sim.get());
    pf_whitewater w = pf_default_whitewater();
    w.capacity = 64;
    w.trapped_air_rate = w.wave_crest_rate = 5000.0f;
    set(sim.get(), w);
    bool logged = false;
    for (int f = 0; f < 40; ++f) {
        ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
        logged = logged || std::strstr(last_log(), "PF_FLAG_WHITEWATER_FULL") != nullptr;
        EXPECT_LE(read_whitewater(sim.get()).count(), 64u);
    }
    EXPECT_EQ(read_whitewater(sim.get()).count(), 64u);
    pf_stats st{};
    st.struct_size = sizeof st;
    ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
    EXPECT_NE(st.flags & PF_FLAG_WHITEWATER_FULL, 0u);
    EXPECT_TRUE(logged) << "no log line named PF_FLAG_WHITEWATER_FULL";
}

// Lives of 0.2-0.4 s: once the rates drop to zero, every particle is gone after 0.4 s, and none
// comes back.
TEST_F(WhitewaterTest, EveryParticleIsRemovedAfterItsLifetime) {
    SimPtr sim = pool(PF_FEATURE_WHITEWATER | PF_FEATURE_EMITTERS);
    ASSERT_TRUE(sim);
    add_jet(sim.get());
    pf_whitewater w = pf_default_whitewater();
    w.lifetime[0] = 0.2f, w.lifetime[1] = 0.4f;
    set(sim.get(), w);
    for (int f = 0; f < 40; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    ASSERT_GT(read_whitewater(sim.get()).count(), 0u);
    w.trapped_air_rate = w.wave_crest_rate = 0.0f;
    set(sim.get(), w);
    for (int f = 0; f < 24; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);  // 0.4 s
    EXPECT_EQ(read_whitewater(sim.get()).count(), 0u);
    for (int f = 0; f < 6; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    EXPECT_EQ(read_whitewater(sim.get()).count(), 0u);
}

// Whitewater never acts on the liquid: with it on, the liquid's particles move bit for bit as
// with it off.
TEST_F(WhitewaterTest, TheLiquidMovesExactlyAsWithoutIt) {
    std::vector<ParticleState> runs;
    for (uint32_t features : {uint32_t(PF_FEATURE_EMITTERS), uint32_t(PF_FEATURE_EMITTERS | PF_FEATURE_WHITEWATER)}) {
        SimPtr sim = pool(features);
        ASSERT_TRUE(sim);
        add_jet(sim.get());
        for (int f = 0; f < 30; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
        if (features & PF_FEATURE_WHITEWATER) EXPECT_GT(read_whitewater(sim.get()).count(), 0u);
        runs.push_back(read_all(sim.get()));
    }
    ASSERT_EQ(runs[0].count(), runs[1].count());
    EXPECT_EQ(runs[0].pos, runs[1].pos);
    EXPECT_EQ(runs[0].vel, runs[1].vel);
}

// The buffers: refused while the feature is off; the same names step after step; a new capacity
// reallocates them (and clears the whitewater).
TEST_F(WhitewaterTest, BuffersExistOnlyWhileOnAndKeepTheirNames) {
    SimPtr sim = pool(PF_FEATURE_EMITTERS);
    ASSERT_TRUE(sim);
    add_jet(sim.get());
    pf_whitewater_buffers b{};
    EXPECT_EQ(pf_get_whitewater_buffers(sim.get(), &b), PF_ERROR_INVALID_STATE);
    EXPECT_EQ(b.positions, 0u);
    EXPECT_EQ(pf_get_whitewater_buffers(sim.get(), nullptr), PF_ERROR_INVALID_ARGUMENT);
    ASSERT_EQ(pf_set_features(sim.get(), PF_FEATURE_EMITTERS | PF_FEATURE_WHITEWATER), PF_OK) << last_log();
    ASSERT_EQ(pf_get_whitewater_buffers(sim.get(), &b), PF_OK);
    EXPECT_EQ(b.capacity, pf_default_whitewater().capacity);
    EXPECT_EQ(b.stride, 16u);
    for (int f = 0; f < 30; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    pf_whitewater_buffers later{};
    ASSERT_EQ(pf_get_whitewater_buffers(sim.get(), &later), PF_OK);
    EXPECT_EQ(std::memcmp(&b, &later, sizeof b), 0);
    ASSERT_GT(read_whitewater(sim.get()).count(), 0u);
    pf_whitewater w = pf_default_whitewater();
    w.capacity = 1000;
    w.trapped_air_rate = w.wave_crest_rate = 0.0f;
    set(sim.get(), w);
    ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    ASSERT_EQ(pf_get_whitewater_buffers(sim.get(), &later), PF_OK);
    EXPECT_EQ(later.capacity, 1000u);
    EXPECT_EQ(read_whitewater(sim.get()).count(), 0u);
}

// A snapshot carries the parameters; restoring clears the particles (they are not saved).
TEST_F(WhitewaterTest, SnapshotKeepsTheParametersAndClearsTheParticles) {
    SimPtr sim = pool(PF_FEATURE_WHITEWATER | PF_FEATURE_EMITTERS);
    ASSERT_TRUE(sim);
    add_jet(sim.get());
    pf_whitewater w = pf_default_whitewater();
    w.bubble_buoyancy = 3.5f;
    set(sim.get(), w);
    size_t size = 0;
    ASSERT_EQ(pf_snapshot_size(sim.get(), &size), PF_OK);
    std::vector<uint8_t> snap(size);
    ASSERT_EQ(pf_save_snapshot(sim.get(), snap.data(), size), PF_OK) << last_log();
    for (int f = 0; f < 30; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    ASSERT_GT(read_whitewater(sim.get()).count(), 0u);
    pf_whitewater other = pf_default_whitewater();
    set(sim.get(), other);
    ASSERT_EQ(pf_restore_snapshot(sim.get(), snap.data(), size), PF_OK) << last_log();
    pf_whitewater got{};
    got.struct_size = sizeof got;
    ASSERT_EQ(pf_get_whitewater(sim.get(), &got), PF_OK);
    EXPECT_EQ(got.bubble_buoyancy, 3.5f);
    w.trapped_air_rate = w.wave_crest_rate = 0.0f;  // nothing new: only what the restore kept
    set(sim.get(), w);
    ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    EXPECT_EQ(read_whitewater(sim.get()).count(), 0u);
}

// pf_render_ssf draws the whitewater over the liquid (brighter pixels than the same frame with
// skip_whitewater), hides it behind the engine's scene depth, and keeps the engine's GL state.
TEST_F(WhitewaterTest, DrawnOverTheLiquidHiddenBehindTheSceneAndEngineStateKept) {
    ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc)));
    SimPtr sim = pool(PF_FEATURE_WHITEWATER | PF_FEATURE_EMITTERS);
    ASSERT_TRUE(sim);
    add_jet(sim.get());
    for (int f = 0; f < 45; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    ASSERT_GT(read_whitewater(sim.get()).count(), 100u);
    EngineTarget t(160, 120, GL_RGBA16F);
    const int vp[4] = {0, 0, t.width, t.height};
    const TestCamera c = make_camera({0.4, 0.7, 2.2}, {0.4, 0.35, 0.4}, 45.0, vp, 0.1, 10.0, PF_DEPTH_STANDARD);
    const size_t pixels = size_t(t.width) * t.height;
    auto render = [&](uint32_t skip) {
        pf_ssf_params p = pf_default_ssf_params();
        p.skip_whitewater = skip;
        const pf_render_target target{t.fbo, t.color, t.depth, 0};
        EXPECT_EQ(pf_render_ssf(sim.get(), &c.cam, &target, &p), PF_OK) << last_log();
    };
    auto draw = [&](uint32_t skip, float scene_depth) {
        t.write_color(std::vector<float>(pixels * 4, 0.05f));
        t.write_depth(std::vector<float>(pixels, scene_depth));
        render(skip);
        return t.read_color();
    };
    const std::vector<float> liquid = draw(1, 1.0f), both = draw(0, 1.0f);
    size_t brighter = 0;
    for (size_t i = 0; i < pixels; ++i) {
        float gain = 0.0f;
        for (int ch = 0; ch < 3; ++ch) gain += both[i * 4 + ch] - liquid[i * 4 + ch];
        brighter += gain > 0.15f ? 1 : 0;
    }
    EXPECT_GT(brighter, 50u) << "the whitewater brightened too few pixels";
    // A scene surface just past the near plane everywhere: nothing of pflip's shows.
    const std::vector<float> hidden_liquid = draw(1, 0.001f), hidden_both = draw(0, 0.001f);
    EXPECT_EQ(std::memcmp(hidden_liquid.data(), hidden_both.data(), hidden_both.size() * 4), 0)
        << "whitewater drawn in front of the scene's depth";
    Engine engine(EngineProgram::graphics);
    guarded_call(engine, 1, "pf_render_ssf with whitewater", [&] { render(0); });
    engine.unbind_all();
}

// Bad parameters: each refused with a logged reason, the previous ones kept.
TEST_F(WhitewaterTest, BadParametersAreRefusedAndChangeNothing) {
    SimPtr sim = pool(0);
    ASSERT_TRUE(sim);
    pf_whitewater good = pf_default_whitewater();
    good.spray_drag = 1.25f;
    set(sim.get(), good);
    const float nan = std::nanf("");
    struct Case {
        const char* what;
        void (*edit)(pf_whitewater&, float);
    };
    const Case cases[] = {
        {"capacity", [](pf_whitewater& w, float) { w.capacity = 0; }},
        {"capacity", [](pf_whitewater& w, float) { w.capacity = (1u << 23) + 1; }},
        {"trapped_air_rate", [](pf_whitewater& w, float n) { w.trapped_air_rate = n; }},
        {"wave_crest_rate", [](pf_whitewater& w, float) { w.wave_crest_rate = -1.0f; }},
        {"trapped_air_range", [](pf_whitewater& w, float) { w.trapped_air_range[0] = 7.0f; }},
        {"wave_crest_range", [](pf_whitewater& w, float n) { w.wave_crest_range[1] = n; }},
        {"energy_range", [](pf_whitewater& w, float) { w.energy_range[0] = -0.5f; }},
        {"lifetime", [](pf_whitewater& w, float) { w.lifetime[0] = 0.0f; }},
        {"lifetime", [](pf_whitewater& w, float) { w.lifetime[0] = 4.0f; }},
        {"bubble_buoyancy", [](pf_whitewater& w, float n) { w.bubble_buoyancy = n; }},
        {"bubble_drag", [](pf_whitewater& w, float) { w.bubble_drag = 2000.0f; }},
        {"spray_drag", [](pf_whitewater& w, float) { w.spray_drag = -0.1f; }},
    };
    for (const Case& c : cases) {
        pf_whitewater bad = pf_default_whitewater();
        c.edit(bad, nan);
        clear_log();
        EXPECT_EQ(pf_set_whitewater(sim.get(), &bad), PF_ERROR_INVALID_ARGUMENT) << c.what;
        EXPECT_NE(std::strstr(last_log(), c.what), nullptr) << last_log();
        pf_whitewater got{};
        got.struct_size = sizeof got;
        ASSERT_EQ(pf_get_whitewater(sim.get(), &got), PF_OK);
        EXPECT_EQ(std::memcmp(&got, &good, sizeof got), 0) << c.what;
    }
    EXPECT_EQ(pf_set_whitewater(sim.get(), nullptr), PF_ERROR_INVALID_ARGUMENT);
}

}  // namespace
}  // namespace pf::test
