// Snapshots (pf_snapshot_size / pf_save_snapshot / pf_restore_snapshot): save after N steps, run
// M more, restore (after changing particles, parameters and effects meanwhile), run M again:
// bit-identical particles, in the same simulation and in a fresh one with the same grid, for the
// default scheme and for MGPCG + APIC + force fields + obstacles. A NULL, short, truncated,
// corrupted or foreign buffer is refused with a logged error and changes nothing.
#include <glad/gl.h>

#include <cstring>
#include <string>
#include <vector>

#include "support/engine_state.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

constexpr float kDt = 1.0f / 60.0f;

struct Config {
    const char* name;
    pf_pressure_solver solver;
    pf_transfer transfer;
    uint32_t features;
    pf_advection advection = PF_ADVECTION_EULER;
};

class Snapshots : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc)));
        drain_gl_errors();
    }

    static pf_sim_desc desc() {
        pf_sim_desc d = test_desc(16, 16, 16, 0.05f);
        d.max_particles = 40000;
        return d;
    }

    SimPtr scene(const Config& c) {
        pf_sim_desc d = desc();
        d.features = c.features;
        d.params.pressure_solver = c.solver;
        d.params.transfer = c.transfer;
        d.params.advection = c.advection;
        SimPtr s = create(d);
        const float lo[3] = {0.05f, 0.05f, 0.05f}, hi[3] = {0.4f, 0.6f, 0.5f}, v[3] = {0.8f, 0.0f, 0.3f};
        EXPECT_EQ(pf_fill_box(s.get(), lo, hi, v), PF_OK) << last_log();
        if (c.features & PF_FEATURE_FORCE_FIELDS) {
            pf_force_field f = pf_default_force_field();
            f.type = PF_FORCE_FIELD_VORTEX;
            f.position[0] = f.position[2] = 0.4f;
            f.vector[1] = 1.0f;
            f.strength = 6.0f;
            f.radius = 0.3f;
            EXPECT_EQ(pf_add_force_field(s.get(), &f, nullptr), PF_OK);
        }
        if (c.features & PF_FEATURE_OBSTACLES) {
            pf_obstacle o = pf_default_obstacle();
            o.shape = PF_OBSTACLE_SPHERE;
            o.position[0] = 0.55f;
            o.position[1] = 0.15f;
            o.position[2] = 0.4f;
            o.radius = 0.1f;
            EXPECT_EQ(pf_add_obstacle(s.get(), &o, nullptr), PF_OK);
        }
        return s;
    }

    // Steps with the GPU finished after each (as a frame waiting for vsync): the CFL estimate
    // then sees every readback at the same step in every run.
    static void run(pf_sim* s, int steps) {
        for (int i = 0; i < steps; ++i) {
            ASSERT_EQ(pf_step(s, kDt), PF_OK) << last_log();
            glFinish();
        }
    }

    static std::vector<uint8_t> save(pf_sim* s) {
        size_t size = 0;
        EXPECT_EQ(pf_snapshot_size(s, &size), PF_OK);
        std::vector<uint8_t> bytes(size);
        EXPECT_EQ(pf_save_snapshot(s, bytes.data(), bytes.size()), PF_OK) << last_log();
        return bytes;
    }

    static ParticleState particles(pf_sim* s) { return read_all(s); }

    static void expect_identical(const ParticleState& a, const ParticleState& b, const char* what) {
        ASSERT_EQ(a.count(), b.count()) << what;
        size_t differ = 0;
        for (size_t i = 0; i < a.pos.size(); ++i)
            differ += std::memcmp(&a.pos[i], &b.pos[i], 4) != 0 || std::memcmp(&a.vel[i], &b.vel[i], 4) != 0;
        EXPECT_EQ(differ, 0u) << what << ": floats differing from the original continuation";
    }

    void continuation(const Config& c);
};

void Snapshots::continuation(const Config& c) {
    constexpr int kN = 8, kM = 8;
    SimPtr sim = scene(c);
    pf_sim* s = sim.get();
    run(s, kN);
    const std::vector<uint8_t> snap = save(s);
    const ParticleState at_save = particles(s);
    run(s, kM);
    const ParticleState original = particles(s);
    pf_stats st{};
    ASSERT_EQ(pf_get_stats(s, &st), PF_OK);
    // The liquid moved between the save and the end: the comparison below means something.
    ParticleState moved = original;
    EXPECT_NE(0, std::memcmp(at_save.pos.data(), moved.pos.data(), at_save.pos.size() * 4));

    // Change what a restore must put back: particles, parameters, effects' objects.
    const float xyz[3] = {0.7f, 0.7f, 0.7f};
    ASSERT_EQ(pf_add_particles(s, xyz, nullptr, 1), PF_OK);
    const float center[3] = {0.2f, 0.2f, 0.2f}, dv[3] = {0.0f, 2.0f, 0.0f};
    ASSERT_EQ(pf_push(s, center, 0.3f, dv), PF_OK);
    pf_sim_params p = sized_params();
    ASSERT_EQ(pf_get_params(s, &p), PF_OK);
    const pf_sim_params saved_params = p;
    p.flip_ratio = 0.5f;
    p.pressure_solver = PF_PRESSURE_SOLVER_CG;
    p.transfer = PF_TRANSFER_PIC_FLIP;
    ASSERT_EQ(pf_set_params(s, &p), PF_OK);
    pf_force_field extra = pf_default_force_field();
    extra.vector[0] = 3.0f;
    ASSERT_EQ(pf_set_features(s, PF_FEATURE_ALL), PF_OK);
    ASSERT_EQ(pf_add_force_field(s, &extra, nullptr), PF_OK);
    run(s, 2);

    ASSERT_EQ(pf_restore_snapshot(s, snap.data(), snap.size()), PF_OK) << last_log();
    expect_identical(particles(s), at_save, "right after the restore");
    pf_sim_params restored = sized_params();
    ASSERT_EQ(pf_get_params(s, &restored), PF_OK);
    EXPECT_EQ(0, std::memcmp(&restored, &saved_params, sizeof restored)) << "parameters not restored";
    uint32_t features = 0;
    ASSERT_EQ(pf_get_features(s, &features), PF_OK);
    EXPECT_EQ(features, c.features);
    run(s, kM);
    expect_identical(particles(s), original, "same simulation");

    // A fresh simulation with the same grid, restored, continues the same way.
    SimPtr fresh = create(desc());
    ASSERT_TRUE(fresh);
    ASSERT_EQ(pf_restore_snapshot(fresh.get(), snap.data(), snap.size()), PF_OK) << last_log();
    run(fresh.get(), kM);
    expect_identical(particles(fresh.get()), original, "fresh simulation");
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Snapshots, RestoreContinuesBitIdenticallyJacobiScheme) {
    continuation({"jacobi", PF_PRESSURE_SOLVER_JACOBI, PF_TRANSFER_PIC_FLIP, 0});
}

TEST_F(Snapshots, RestoreContinuesBitIdenticallyMgpcgApicEffects) {
    continuation({"mgpcg+apic+effects", PF_PRESSURE_SOLVER_MGPCG, PF_TRANSFER_APIC, PF_FEATURE_ALL});
}

// Leapfrog's positions and velocities meet at every step's end: a snapshot holds all of its state.
TEST_F(Snapshots, RestoreContinuesBitIdenticallyLeapfrog) {
    continuation({"leapfrog", PF_PRESSURE_SOLVER_MGPCG, PF_TRANSFER_PIC_FLIP, 0, PF_ADVECTION_LEAPFROG});
}

TEST_F(Snapshots, BadBuffersAreRefusedAndChangeNothing) {
    SimPtr sim = scene({"effects", PF_PRESSURE_SOLVER_JACOBI, PF_TRANSFER_APIC, PF_FEATURE_ALL});
    pf_sim* s = sim.get();
    run(s, 3);
    const std::vector<uint8_t> good = save(s);
    // Another state to fall back from: one more step.
    run(s, 1);
    const std::vector<uint8_t> current = save(s);
    ASSERT_NE(good, current);

    struct Case {
        const char* what;
        std::vector<uint8_t> bytes;
        size_t size;
        const char* mention;
    };
    std::vector<Case> cases;
    cases.push_back({"empty", {}, 0, "shorter than a snapshot header"});
    cases.push_back({"header only, cut", good, 20, "shorter than a snapshot header"});
    cases.push_back({"truncated by one byte", good, good.size() - 1, "truncated"});
    cases.push_back({"half", good, good.size() / 2, "truncated"});
    {
        std::vector<uint8_t> b = good;
        b[b.size() / 2] ^= 0x40;
        cases.push_back({"one bit flipped in the particles", b, b.size(), "checksum"});
    }
    {
        std::vector<uint8_t> b = good;
        b[200] ^= 0x01;
        cases.push_back({"one bit flipped in the host state", b, b.size(), "checksum"});
    }
    {
        std::vector<uint8_t> b = good;
        b[0] = 'x';
        cases.push_back({"wrong magic", b, b.size(), "magic"});
    }
    {
        std::vector<uint8_t> b = good;
        b[8] += 1;  // format number
        cases.push_back({"another format", b, b.size(), "format"});
    }
    {
        std::vector<uint8_t> b = good;
        b.resize(good.size() + 64, 0);
        uint64_t total = 0;
        std::memcpy(&total, b.data() + 16, 8);
        total += 64;  // claims more than it holds
        std::memcpy(b.data() + 16, &total, 8);
        cases.push_back({"size field too large", b, good.size(), "truncated"});
    }
    {
        pf_sim_desc d = desc();
        d.grid_size[0] = 15;
        SimPtr other = create(d);
        const float lo[3] = {0.1f, 0.1f, 0.1f}, hi[3] = {0.3f, 0.3f, 0.3f};
        ASSERT_EQ(pf_fill_box(other.get(), lo, hi, nullptr), PF_OK);
        const std::vector<uint8_t> b = save(other.get());
        cases.push_back({"another grid", b, b.size(), "another grid"});
    }
    {
        // Well-formed (checksum recomputed) but impossible: a particle far outside the domain.
        std::vector<uint8_t> b = good;
        pf_stats st{};
        ASSERT_EQ(pf_get_stats(s, &st), PF_OK);
        // Layout tail: positions, velocities, APIC affine (this scene is APIC), pressure (16^3 cells).
        const size_t pos_at = b.size() - 16u * 16u * 16u * 4u - size_t(st.particle_count) * (16 + 16 + 48);
        const float far = 1e9f;
        std::memcpy(b.data() + pos_at, &far, 4);
        uint64_t h = 1469598103934665603ull;  // FNV-1a 64 of everything after the 40-byte header
        for (size_t i = 40; i < b.size(); ++i) {
            h ^= b[i];
            h *= 1099511628211ull;
        }
        std::memcpy(b.data() + 24, &h, 8);
        cases.push_back({"a particle outside the domain", b, b.size(), "outside the domain"});
    }
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        clear_log();
        EXPECT_EQ(pf_restore_snapshot(s, c.bytes.empty() ? good.data() : c.bytes.data(), c.size),
                  PF_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(std::string(last_log()).find(c.mention), std::string::npos) << last_log();
        EXPECT_EQ(save(s), current) << "a refused restore changed the simulation";
    }
    clear_log();
    EXPECT_EQ(pf_restore_snapshot(s, nullptr, good.size()), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(last_log()).find("buffer"), std::string::npos) << last_log();
    EXPECT_EQ(save(s), current);

    // More particles than the restoring simulation's capacity.
    pf_sim_desc small = desc();
    small.max_particles = 100;
    SimPtr tiny = create(small);
    clear_log();
    EXPECT_EQ(pf_restore_snapshot(tiny.get(), good.data(), good.size()), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(last_log()).find("max_particles"), std::string::npos) << last_log();
    pf_stats st{};
    ASSERT_EQ(pf_get_stats(tiny.get(), &st), PF_OK);
    EXPECT_EQ(st.particle_count, 0u);

    // Saving: NULL or too small a buffer is refused and nothing is written.
    size_t size = 0;
    ASSERT_EQ(pf_snapshot_size(s, &size), PF_OK);
    EXPECT_EQ(pf_snapshot_size(s, nullptr), PF_ERROR_INVALID_ARGUMENT);
    std::vector<uint8_t> buf(size, 0xAB);
    clear_log();
    EXPECT_EQ(pf_save_snapshot(s, buf.data(), size - 1), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(last_log()).find("pf_snapshot_size"), std::string::npos) << last_log();
    EXPECT_EQ(buf, std::vector<uint8_t>(size, 0xAB));
    EXPECT_EQ(pf_save_snapshot(s, nullptr, size), PF_ERROR_INVALID_ARGUMENT);
    // And the good one still restores.
    EXPECT_EQ(pf_restore_snapshot(s, good.data(), good.size()), PF_OK) << last_log();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// The GL state promise holds for all three calls.
TEST_F(Snapshots, LeavesTheEngineStateAlone) {
    SimPtr sim = scene({"jacobi", PF_PRESSURE_SOLVER_JACOBI, PF_TRANSFER_PIC_FLIP, 0});
    pf_sim* s = sim.get();
    run(s, 2);
    Engine engine(EngineProgram::graphics);
    size_t size = 0;
    guarded_call(engine, 0, "pf_snapshot_size", [&] { ASSERT_EQ(pf_snapshot_size(s, &size), PF_OK); });
    std::vector<uint8_t> b(size);
    guarded_call(engine, 1, "pf_save_snapshot", [&] { ASSERT_EQ(pf_save_snapshot(s, b.data(), size), PF_OK); });
    guarded_call(engine, 2, "pf_restore_snapshot", [&] { ASSERT_EQ(pf_restore_snapshot(s, b.data(), size), PF_OK); });
}

}  // namespace
}  // namespace pf::test
