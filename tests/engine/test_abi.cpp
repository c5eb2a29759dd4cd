// The ABI rules of pf.h (src/api/abi.h): a caller compiled against an older header passes
// smaller structs (struct_size = its sizeof) and gets the defaults for the fields it lacks; the
// library reads and writes no byte beyond struct_size (each struct sits in a buffer whose bytes
// after it are poison that would fail validation or show as changed); a zero-initialised struct
// means the defaults for every field; pf_create refuses a header of another major.minor version.
#include <glad/gl.h>

#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "support/render_fixture.h"

namespace pf::test {
namespace {

constexpr float kDt = 1.0f / 60.0f;

// pf_sim_params of a header without its last field (free_surface).
struct OldParams {
    uint32_t struct_size;
    float gravity[3];
    float flip_ratio;
    uint32_t pressure_iterations;
    float jacobi_omega;
    float cfl;
    uint32_t max_substeps;
    uint32_t extrapolation_layers;
    uint32_t separation;
    pf_pressure_solver pressure_solver;
    float pressure_tolerance;
    float sor_omega;
    pf_transfer transfer;
    pf_advection advection;
    float volume_correction;
    pf_p2g p2g;
    float volume_loss_limit;
    float energy_gain_limit;
};
static_assert(sizeof(OldParams) + 4 == sizeof(pf_sim_params), "one field fewer");
static_assert(offsetof(OldParams, energy_gain_limit) == offsetof(pf_sim_params, energy_gain_limit), "same prefix");

// pf_sim_desc of a header without `features`, holding params of that older layout.
struct OldDesc {
    uint32_t struct_size;
    uint32_t header_version;
    uint32_t grid_size[3];
    float cell_size;
    float origin[3];
    uint32_t max_particles;
    float max_speed;
    float density;
    uint32_t fill_particles_per_cell;
    float fill_jitter;
    uint32_t seed;
    OldParams params;
    pf_gl_get_proc_address_fn gl_get_proc_address;
    pf_logger logger;
};
static_assert(offsetof(OldDesc, params) == offsetof(pf_sim_desc, params), "same head");

// The old params as an older caller's pf_default_sim_params() would give them.
OldParams old_default_params() {
    const pf_sim_params d = pf_default_sim_params();
    OldParams p;
    std::memcpy(&p, &d, sizeof p);
    p.struct_size = sizeof p;
    return p;
}

// A struct of `bytes` bytes followed by poison (0xFF: NaN floats, huge counts, all feature bits).
template <typename T>
struct Poisoned {
    explicit Poisoned(const T& value) : bytes(sizeof(T) + 64, 0xFF) { std::memcpy(bytes.data(), &value, sizeof(T)); }
    void* data() { return bytes.data(); }
    bool tail_intact() const {
        for (size_t i = sizeof(T); i < bytes.size(); ++i)
            if (bytes[i] != 0xFF) return false;
        return true;
    }
    std::vector<uint8_t> bytes;
};

// sizeof(pf_sim_desc) before program_cache was appended (pflip 0.2 with features).
constexpr size_t kSimDescBeforeProgramCache = 176;

class Abi : public RenderTest {};

TEST_F(Abi, OlderParamsWithoutTheirLastFieldTakeItsDefault) {
    OldParams old = old_default_params();
    old.flip_ratio = 0.5f;
    old.volume_loss_limit = 0.3f;
    Poisoned<OldParams> buf(old);
    ASSERT_EQ(pf_set_params(sim_.get(), static_cast<const pf_sim_params*>(buf.data())), PF_OK) << last_log();
    pf_sim_params got = sized_params();
    ASSERT_EQ(pf_get_params(sim_.get(), &got), PF_OK);
    EXPECT_EQ(got.flip_ratio, 0.5f);
    EXPECT_EQ(got.volume_loss_limit, 0.3f);
    EXPECT_EQ(got.energy_gain_limit, pf_default_sim_params().energy_gain_limit);
    EXPECT_EQ(got.free_surface, pf_default_sim_params().free_surface) << "the missing field's default";
    EXPECT_TRUE(buf.tail_intact());

    // Written back to the older caller: only its bytes, struct_size saying how many.
    Poisoned<OldParams> out(OldParams{});
    reinterpret_cast<OldParams*>(out.data())->struct_size = sizeof(OldParams);
    ASSERT_EQ(pf_get_params(sim_.get(), static_cast<pf_sim_params*>(out.data())), PF_OK);
    const auto* o = reinterpret_cast<const OldParams*>(out.data());
    EXPECT_EQ(o->struct_size, uint32_t(sizeof(OldParams)));
    EXPECT_EQ(o->flip_ratio, 0.5f);
    EXPECT_TRUE(out.tail_intact()) << "pf_get_params wrote beyond struct_size";
}

TEST_F(Abi, DescWithoutProgramCacheIsNotReadPastItsSize) {
    // The 176-byte pf_sim_desc before program_cache and prepared_features, followed by poison
    // that would be called (program_cache.load) or refused (prepared_features) if it were read.
    constexpr size_t kOld = offsetof(pf_sim_desc, program_cache);
    static_assert(kOld == kSimDescBeforeProgramCache, "the layout older callers know");
    pf_sim_desc cur = test_desc(8, 8, 8);
    cur.struct_size = uint32_t(kOld);
    std::vector<uint8_t> buf(sizeof(pf_sim_desc) + 64, 0xFF);
    std::memcpy(buf.data(), &cur, kOld);
    pf_sim* s = nullptr;
    clear_log();
    ASSERT_EQ(pf_create(reinterpret_cast<const pf_sim_desc*>(buf.data()), &s), PF_OK) << last_log();
    SimPtr sim(s);
    const float lo[3] = {0.1f, 0.1f, 0.1f}, hi[3] = {0.4f, 0.4f, 0.4f};
    ASSERT_EQ(pf_fill_box(s, lo, hi, nullptr), PF_OK) << last_log();
    EXPECT_EQ(pf_step(s, kDt), PF_OK) << last_log();
    for (size_t i = kOld; i < buf.size(); ++i) ASSERT_EQ(buf[i], 0xFF) << "byte " << i << " written";
}

TEST_F(Abi, OlderDescWithOlderParamsAndNoFeaturesCreates) {
    const pf_sim_desc cur = test_desc(8, 8, 8);
    OldDesc old{};
    std::memcpy(&old, &cur, offsetof(OldDesc, params));  // the head: same layout
    old.struct_size = sizeof old;
    old.params = old_default_params();
    old.params.cfl = 2.0f;
    old.gl_get_proc_address = cur.gl_get_proc_address;
    old.logger = cur.logger;
    Poisoned<OldDesc> buf(old);
    pf_sim* s = nullptr;
    clear_log();
    ASSERT_EQ(pf_create(static_cast<const pf_sim_desc*>(buf.data()), &s), PF_OK) << last_log();
    SimPtr sim(s);
    uint32_t features = 99;
    ASSERT_EQ(pf_get_features(s, &features), PF_OK);
    EXPECT_EQ(features, 0u) << "the missing features field is read as poison instead of its default";
    pf_sim_params got = sized_params();
    ASSERT_EQ(pf_get_params(s, &got), PF_OK);
    EXPECT_EQ(got.cfl, 2.0f);
    EXPECT_EQ(got.free_surface, pf_default_sim_params().free_surface);
    // The logger was found after the older (shorter) params: a refused call reaches it.
    clear_log();
    EXPECT_EQ(pf_step(s, -1.0f), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(last_log()).find("pf_step"), std::string::npos) << "logger not found: " << last_log();
    const float lo[3] = {0.1f, 0.1f, 0.1f}, hi[3] = {0.4f, 0.4f, 0.4f};
    ASSERT_EQ(pf_fill_box(s, lo, hi, nullptr), PF_OK);
    EXPECT_EQ(pf_step(s, kDt), PF_OK) << last_log();
    EXPECT_TRUE(buf.tail_intact());
}

TEST_F(Abi, OlderStatsGetOnlyTheirBytes) {
    constexpr uint32_t kOld = offsetof(pf_stats, energy_drift);  // a header without energy_drift
    std::vector<uint8_t> buf(sizeof(pf_stats) + 64, 0xFF);
    std::memcpy(buf.data(), &kOld, 4);
    ASSERT_EQ(pf_get_stats(sim_.get(), reinterpret_cast<pf_stats*>(buf.data())), PF_OK);
    uint32_t written = 0, capacity = 0;
    std::memcpy(&written, buf.data(), 4);
    std::memcpy(&capacity, buf.data() + offsetof(pf_stats, max_particles), 4);
    EXPECT_EQ(written, kOld);
    EXPECT_EQ(capacity, 1u << 16);  // RenderTest's max_particles
    for (size_t i = kOld; i < buf.size(); ++i) ASSERT_EQ(buf[i], 0xFF) << "byte " << i << " written beyond struct_size";
    // Zero (a zero-initialised pf_stats, which may be an older header's): the first layout, the
    // struct as it was when struct_size was introduced (it ended before liquid_volume), and not a
    // byte more: the library cannot know how large a zeroed struct is.
    constexpr uint32_t kFirst = offsetof(pf_stats, liquid_volume);
    std::vector<uint8_t> zeroed(sizeof(pf_stats) + 64, 0xFF);
    std::memset(zeroed.data(), 0, 4);
    ASSERT_EQ(pf_get_stats(sim_.get(), reinterpret_cast<pf_stats*>(zeroed.data())), PF_OK);
    std::memcpy(&written, zeroed.data(), 4);
    EXPECT_EQ(written, kFirst);
    for (size_t i = kFirst; i < zeroed.size(); ++i) ASSERT_EQ(zeroed[i], 0xFF) << "byte " << i << " written beyond the first layout";
    // struct_size = sizeof: this header's whole struct.
    pf_stats st{};
    st.struct_size = sizeof st;
    ASSERT_EQ(pf_get_stats(sim_.get(), &st), PF_OK);
    EXPECT_EQ(st.struct_size, uint32_t(sizeof(pf_stats)));
    EXPECT_EQ(st.max_particles, capacity);
}

TEST_F(Abi, NewerCallersStructsAreAcceptedAndTheirExtraFieldsIgnored) {
    // A caller whose pf_sim_params has 8 more bytes than this library knows.
    std::vector<uint8_t> buf(sizeof(pf_sim_params) + 8, 0xAB);
    ASSERT_EQ(pf_init_sim_params(reinterpret_cast<pf_sim_params*>(buf.data()), uint32_t(buf.size())), PF_OK);
    uint32_t size = 0;
    std::memcpy(&size, buf.data(), 4);
    EXPECT_EQ(size, uint32_t(buf.size()));
    for (size_t i = sizeof(pf_sim_params); i < buf.size(); ++i) EXPECT_EQ(buf[i], 0) << "unknown fields are zeroed";
    ASSERT_EQ(pf_set_params(sim_.get(), reinterpret_cast<const pf_sim_params*>(buf.data())), PF_OK) << last_log();
}

TEST_F(Abi, BadStructSizesAreRefusedAndLogged) {
    for (uint32_t bad : {1u, 2u, 3u, 6u, 81u}) {
        SCOPED_TRACE(bad);
        pf_sim_params p = pf_default_sim_params();
        p.struct_size = bad;
        clear_log();
        EXPECT_EQ(pf_set_params(sim_.get(), &p), PF_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(std::string(last_log()).find("struct_size"), std::string::npos) << last_log();
        pf_stats st{};
        st.struct_size = bad;
        EXPECT_EQ(pf_get_stats(sim_.get(), &st), PF_ERROR_INVALID_ARGUMENT);
        pf_sim_desc d = test_desc(8, 8, 8);
        d.struct_size = bad;
        pf_sim* s = nullptr;
        EXPECT_EQ(pf_create(&d, &s), PF_ERROR_INVALID_ARGUMENT);
        EXPECT_EQ(s, nullptr);
        EXPECT_EQ(pf_init_sim_params(&p, bad), PF_ERROR_INVALID_ARGUMENT);
    }
    EXPECT_EQ(pf_init_sim_params(nullptr, sizeof(pf_sim_params)), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_init_sim_desc(nullptr, sizeof(pf_sim_desc)), PF_ERROR_INVALID_ARGUMENT);
    pf_ssf_params ssf{};
    EXPECT_EQ(pf_init_ssf_params(&ssf, 0), PF_ERROR_INVALID_ARGUMENT);
    pf_particle_params pp{};
    EXPECT_EQ(pf_init_particle_params(&pp, 2), PF_ERROR_INVALID_ARGUMENT);
}

// The effect descriptors (pf_force_field, pf_obstacle, pf_emitter, pf_sink, pf_domain_motion)
// follow the same rules. For each, a caller of an older header that lacked the last field
// passes struct_size up to it and poison after: accepted, so the poison was not read, while the
// same poison inside a struct of today's size is refused (the control: it would have shown).
template <typename T>
struct OlderCase {
    const char* what;
    T value;           // a valid descriptor of today's layout
    size_t last;       // offset of its last field, which the older header lacks
    pf_result (*add)(pf_sim*, const T*);
};

template <typename T>
void expect_older_accepted_and_poison_refused(pf_sim* sim, const OlderCase<T>& c) {
    SCOPED_TRACE(c.what);
    // Control: today's size with the last word poisoned is refused.
    T poisoned = c.value;
    std::memset(reinterpret_cast<uint8_t*>(&poisoned) + c.last, 0xFF, sizeof(T) - c.last);
    clear_log();
    EXPECT_EQ(c.add(sim, &poisoned), PF_ERROR_INVALID_ARGUMENT) << "the control: poison in the last field must be refused";
    // The older caller: struct_size stops before the last field; the poison after is not read.
    T older = poisoned;
    older.struct_size = uint32_t(c.last);
    EXPECT_EQ(c.add(sim, &older), PF_OK) << last_log();
    // Bad sizes are refused with a message naming struct_size.
    for (uint32_t bad : {2u, 6u}) {
        T b = c.value;
        b.struct_size = bad;
        clear_log();
        EXPECT_EQ(c.add(sim, &b), PF_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(std::string(last_log()).find("struct_size"), std::string::npos) << last_log();
    }
}

TEST_F(Abi, EffectDescriptorsOfAnOlderHeaderTakeDefaultsForTheirMissingFields) {
    ASSERT_EQ(pf_set_features(sim_.get(), PF_FEATURE_ALL), PF_OK) << last_log();
    pf_sim* s = sim_.get();
    pf_force_field field = pf_default_force_field();
    field.vector[0] = 1.0f;
    expect_older_accepted_and_poison_refused<pf_force_field>(
        s, {"force field (older: no drag)", field, offsetof(pf_force_field, drag),
            [](pf_sim* h, const pf_force_field* f) { return pf_add_force_field(h, f, nullptr); }});
    pf_obstacle box = pf_default_obstacle();
    box.position[0] = box.position[1] = box.position[2] = 0.8f;
    expect_older_accepted_and_poison_refused<pf_obstacle>(
        s, {"obstacle (older: no sdf_scale)", box, offsetof(pf_obstacle, sdf_scale),
            [](pf_sim* h, const pf_obstacle* o) { return pf_add_obstacle(h, o, nullptr); }});
    pf_emitter nozzle = pf_default_emitter();
    nozzle.position[0] = nozzle.position[1] = nozzle.position[2] = 0.8f;
    nozzle.rate = 100.0f;
    expect_older_accepted_and_poison_refused<pf_emitter>(
        s, {"emitter (older: no rate_unit)", nozzle, offsetof(pf_emitter, rate_unit),
            [](pf_sim* h, const pf_emitter* e) { return pf_add_emitter(h, e, nullptr); }});
    pf_sink drain = pf_default_sink();
    drain.shape = PF_SINK_SPHERE;
    drain.position[0] = drain.position[1] = drain.position[2] = 0.8f;
    expect_older_accepted_and_poison_refused<pf_sink>(
        s, {"sink (older: no radius)", drain, offsetof(pf_sink, radius),
            [](pf_sim* h, const pf_sink* k) { return pf_add_sink(h, k, nullptr); }});
    pf_domain_motion motion = pf_default_domain_motion();
    motion.velocity[0] = 0.5f;
    expect_older_accepted_and_poison_refused<pf_domain_motion>(
        s, {"domain motion (older: no angular_velocity)", motion, offsetof(pf_domain_motion, angular_velocity),
            [](pf_sim* h, const pf_domain_motion* m) { return pf_set_domain_motion(h, m); }});

    // What was stored has the default in the field the older caller lacked, and goes back to an
    // older caller as its own bytes only.
    Poisoned<pf_domain_motion> out(pf_domain_motion{});
    reinterpret_cast<pf_domain_motion*>(out.data())->struct_size = uint32_t(offsetof(pf_domain_motion, angular_velocity));
    std::memset(out.bytes.data() + offsetof(pf_domain_motion, angular_velocity), 0xFF,
                out.bytes.size() - offsetof(pf_domain_motion, angular_velocity));
    ASSERT_EQ(pf_get_domain_motion(s, static_cast<pf_domain_motion*>(out.data())), PF_OK);
    const auto* got = reinterpret_cast<const pf_domain_motion*>(out.data());
    EXPECT_EQ(got->struct_size, uint32_t(offsetof(pf_domain_motion, angular_velocity)));
    EXPECT_EQ(got->velocity[0], 0.5f);
    for (size_t i = offsetof(pf_domain_motion, angular_velocity); i < out.bytes.size(); ++i)
        ASSERT_EQ(out.bytes[i], 0xFF) << "pf_get_domain_motion wrote beyond struct_size, byte " << i;
    pf_domain_motion full{};
    full.struct_size = sizeof full;
    ASSERT_EQ(pf_get_domain_motion(s, &full), PF_OK);
    EXPECT_EQ(full.angular_velocity[0], 0.0f) << "the missing field took its default";
    EXPECT_EQ(full.angular_velocity[1], 0.0f);
    EXPECT_EQ(full.angular_velocity[2], 0.0f);

    // pf_init_* of every descriptor: sizes below 4 or not multiples of 4, and NULL, refused.
    EXPECT_EQ(pf_init_force_field(&field, 2), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_init_obstacle(nullptr, sizeof(pf_obstacle)), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_init_emitter(&nozzle, 6), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_init_sink(&drain, 0), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_init_domain_motion(&motion, 3), PF_ERROR_INVALID_ARGUMENT);
}

// A zero-initialised descriptor (struct_size 0) takes the default for every zero field: a sink
// with only its position set is the default 0.1 m box there (zero half extents would be refused).
TEST_F(Abi, ZeroInitialisedEffectDescriptorsTakeDefaults) {
    ASSERT_EQ(pf_set_features(sim_.get(), PF_FEATURE_SINKS | PF_FEATURE_OBSTACLES), PF_OK) << last_log();
    pf_sink drain{};
    drain.position[0] = drain.position[1] = drain.position[2] = 0.8f;
    EXPECT_EQ(pf_add_sink(sim_.get(), &drain, nullptr), PF_OK) << last_log();
    pf_obstacle ball{};
    ball.shape = PF_OBSTACLE_SPHERE;
    ball.position[0] = ball.position[1] = ball.position[2] = 0.5f;
    EXPECT_EQ(pf_add_obstacle(sim_.get(), &ball, nullptr), PF_OK) << last_log();
    // Today's size with the same zeros means zeros: refused.
    ball.struct_size = sizeof ball;
    clear_log();
    EXPECT_EQ(pf_add_obstacle(sim_.get(), &ball, nullptr), PF_ERROR_INVALID_ARGUMENT);
}

TEST_F(Abi, HeaderVersionMustMatchMajorMinor) {
    struct Case {
        uint32_t version;
        pf_result want;
    };
    const uint32_t v = PF_VERSION;
    for (const Case& c : {Case{v, PF_OK}, Case{0, PF_OK}, Case{v + 1, PF_OK} /* another patch */,
                          Case{v + 100, PF_ERROR_INVALID_ARGUMENT} /* another minor */,
                          Case{v + 10000, PF_ERROR_INVALID_ARGUMENT} /* another major */}) {
        SCOPED_TRACE(c.version);
        pf_sim_desc d = test_desc(8, 8, 8);
        EXPECT_EQ(d.header_version, v) << "pf_default_sim_desc sets it";
        d.header_version = c.version;
        pf_sim* s = nullptr;
        clear_log();
        EXPECT_EQ(pf_create(&d, &s), c.want) << last_log();
        if (c.want != PF_OK) {
            EXPECT_EQ(s, nullptr);
            EXPECT_NE(std::string(last_log()).find("compiled against pf.h"), std::string::npos) << last_log();
        }
        pf_destroy(s);
    }
}

// Zero-initialised structs mean the defaults for every field: a desc with only the loader set
// creates the default simulation, and zeroed render parameters draw with the default look
// (a zero shininess or light direction would otherwise be refused).
TEST_F(Abi, ZeroInitialisedStructsMeanDefaults) {
    pf_sim_desc d{};
    d.gl_get_proc_address = get_proc;
    pf_sim* s = nullptr;
    ASSERT_EQ(pf_create(&d, &s), PF_OK) << last_log();
    SimPtr sim(s);
    pf_stats st{};
    ASSERT_EQ(pf_get_stats(s, &st), PF_OK);
    EXPECT_EQ(st.max_particles, pf_default_sim_desc().max_particles);
    pf_sim_params got = sized_params();
    ASSERT_EQ(pf_get_params(s, &got), PF_OK);
    const pf_sim_params def = pf_default_sim_params();
    EXPECT_EQ(0, std::memcmp(&got, &def, sizeof got));

    add({0.8f, 0.8f, 0.8f});
    EngineTarget t(32, 32, GL_RGBA8);
    const int vp[4] = {0, 0, 32, 32};
    const TestCamera c = camera(vp);
    const pf_render_target target{t.fbo, t.color, t.depth, 0};
    const pf_ssf_params zero_ssf{};
    EXPECT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, &zero_ssf), PF_OK) << last_log();
    const pf_particle_params zero_particles{};
    EXPECT_EQ(pf_render_particles(sim_.get(), &c.cam, &target, &zero_particles), PF_OK) << last_log();
    // With struct_size set, the same zero shininess is literal, hence refused.
    pf_ssf_params literal = pf_default_ssf_params();
    literal.shininess = 0.0f;
    EXPECT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, &literal), PF_ERROR_INVALID_ARGUMENT);
}

}  // namespace
}  // namespace pf::test
