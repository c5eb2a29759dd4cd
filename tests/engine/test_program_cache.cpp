// pf_sim_desc.program_cache and prepared_features: the first pf_create stores one blob per
// program, a second of the same configuration links every program from its blob and stores
// none, and the simulation gives the same particles bit for bit as one without a cache; a blob
// that is damaged, truncated, not ours, made for another program or refused by the driver is
// rebuilt and stored again, never used; the renderer's programs go through the same cache;
// prepared features build their programs at pf_create, so turning the effects on later builds
// nothing; bad input is refused.
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "support/render_fixture.h"

namespace pf::test {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr size_t kHeader = 40;          // src/gl/program_binary_cache.h: ProgramBlobHeader
constexpr size_t kPayloadSizeAt = 24;   // its payload_size
constexpr size_t kChecksumAt = 32;      // its payload_checksum

uint64_t fnv1a64(const uint8_t* p, size_t n) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 0x100000001b3ull;
    return h;
}

// The engine's side: blobs in a map, every call counted.
struct MemoryCache {
    std::map<std::string, std::vector<uint8_t>> blobs;
    uint32_t loads = 0, hits = 0, stores = 0;
    std::vector<std::string> stored_keys;

    pf_program_cache callbacks() { return pf_program_cache{this, &load, &store}; }
    void reset_counts() {
        loads = hits = stores = 0;
        stored_keys.clear();
    }
    static size_t load(void* user, const char* key, void* data, size_t capacity) {
        auto& c = *static_cast<MemoryCache*>(user);
        ++c.loads;
        const auto it = c.blobs.find(key);
        if (it == c.blobs.end()) return 0;
        if (it->second.size() <= capacity) {
            std::memcpy(data, it->second.data(), it->second.size());
            ++c.hits;
        }
        return it->second.size();
    }
    static void store(void* user, const char* key, const void* data, size_t size) {
        auto& c = *static_cast<MemoryCache*>(user);
        ++c.stores;
        c.stored_keys.emplace_back(key);
        const auto* p = static_cast<const uint8_t*>(data);
        c.blobs[key].assign(p, p + size);
    }
};

// Every message of a simulation.
struct Messages {
    std::vector<std::string> lines;
    static void fn(void* user, pf_log_level, pf_result, const char* message) {
        static_cast<Messages*>(user)->lines.emplace_back(message);
    }
    size_t count(const std::string& part) const {
        size_t n = 0;
        for (const std::string& l : lines) n += l.find(part) != std::string::npos ? 1 : 0;
        return n;
    }
};

class ProgramCache : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        using GetIntegerv = void (*)(GLenum, GLint*);
        GLint formats = 0;
        reinterpret_cast<GetIntegerv>(get_proc("glGetIntegerv"))(GL_NUM_PROGRAM_BINARY_FORMATS, &formats);
        if (formats == 0)
            GTEST_SKIP() << "this GL offers no program binary format (Mesa: MESA_SHADER_CACHE_DISABLE is set)";
    }
    pf_sim_desc desc(MemoryCache* cache, Messages* messages = nullptr) {
        pf_sim_desc d = test_desc(16, 16, 16);
        d.max_particles = 1u << 15;
        if (cache) d.program_cache = cache->callbacks();
        if (messages) d.logger = pf_logger{&Messages::fn, messages};
        return d;
    }
    // A small dam break, a few steps; the particles after it.
    static ParticleState dam_break(pf_sim* sim) {
        const float lo[3] = {0.0f, 0.0f, 0.0f}, hi[3] = {0.6f, 1.0f, 1.6f};
        EXPECT_EQ(pf_fill_box(sim, lo, hi, nullptr), PF_OK) << last_log();
        for (int i = 0; i < 4; ++i) EXPECT_EQ(pf_step(sim, kDt), PF_OK) << last_log();
        return read_all(sim);
    }
    static void expect_identical(const ParticleState& a, const ParticleState& b) {
        ASSERT_EQ(a.count(), b.count());
        ASSERT_GT(a.count(), 0u);
        EXPECT_EQ(std::memcmp(a.pos.data(), b.pos.data(), a.pos.size() * 4), 0) << "positions differ";
        EXPECT_EQ(std::memcmp(a.vel.data(), b.vel.data(), a.vel.size() * 4), 0) << "velocities differ";
    }
    ParticleState reference() {
        SimPtr plain = create(desc(nullptr));
        return plain ? dam_break(plain.get()) : ParticleState{};
    }
};

TEST_F(ProgramCache, SecondCreateLoadsEveryProgramAndStepsBitIdentically) {
    MemoryCache cache;
    {
        SimPtr first = create(desc(&cache));
        ASSERT_TRUE(first);
        EXPECT_GT(cache.stores, 10u);
        EXPECT_EQ(cache.hits, 0u);
        EXPECT_EQ(cache.loads, cache.stores) << "one load (a miss) and one store per program";
        EXPECT_EQ(cache.blobs.size(), cache.stores) << "one blob per program, each under its own key";
        for (const auto& [key, blob] : cache.blobs) {
            EXPECT_EQ(key.rfind("pflip-", 0), 0u) << key;
            EXPECT_GT(blob.size(), kHeader) << key;
        }
    }
    const uint32_t programs = cache.stores;
    cache.reset_counts();
    Messages messages;
    SimPtr second = create(desc(&cache, &messages));
    ASSERT_TRUE(second);
    EXPECT_EQ(cache.loads, programs);
    EXPECT_EQ(cache.hits, programs) << "every program linked from its blob";
    EXPECT_EQ(cache.stores, 0u) << "nothing compiled, nothing stored";
    EXPECT_EQ(messages.count("program cache: " + std::to_string(programs) + " programs loaded, 0 compiled"), 1u);
    expect_identical(dam_break(second.get()), reference());
    EXPECT_EQ(cache.stores, 0u);
}

TEST_F(ProgramCache, WithoutCallbacksNothingIsCalledAndOnlyOneCallbackWorks) {
    // A load-only cache (say, blobs shipped with the game) loads and never stores.
    MemoryCache filled;
    { SimPtr first = create(desc(&filled)); }
    MemoryCache read_only;
    read_only.blobs = filled.blobs;
    pf_sim_desc d = desc(&read_only);
    d.program_cache.store = nullptr;
    SimPtr loaded = create(d);
    ASSERT_TRUE(loaded);
    EXPECT_EQ(read_only.hits, filled.stores);
    // A store-only cache stores each program it compiles.
    MemoryCache write_only;
    d = desc(&write_only);
    d.program_cache.load = nullptr;
    SimPtr stored = create(d);
    ASSERT_TRUE(stored);
    EXPECT_EQ(write_only.loads, 0u);
    EXPECT_EQ(write_only.stores, filled.stores);
    // user set, no callbacks: no cache, nothing called (user is never dereferenced).
    d = desc(nullptr);
    d.program_cache.user = reinterpret_cast<void*>(uintptr_t(1));
    SimPtr none = create(d);
    ASSERT_TRUE(none);
    expect_identical(dam_break(loaded.get()), dam_break(none.get()));
}

enum class Damage { flipped_payload_byte, truncated, shorter_than_header, wrong_magic, other_key, refused_by_driver };

class ProgramCacheDamage : public ProgramCache, public ::testing::WithParamInterface<Damage> {};

TEST_P(ProgramCacheDamage, IsDetectedRebuiltAndStoredAgain) {
    MemoryCache cache;
    { SimPtr first = create(desc(&cache)); }
    const uint32_t programs = cache.stores;
    ASSERT_GT(programs, 1u);
    const std::map<std::string, std::vector<uint8_t>> good = cache.blobs;
    // Damage every blob.
    std::vector<std::string> keys;
    for (const auto& kv : good) keys.push_back(kv.first);
    for (size_t i = 0; i < keys.size(); ++i) {
        std::vector<uint8_t>& b = cache.blobs[keys[i]];
        switch (GetParam()) {
            case Damage::flipped_payload_byte: b[kHeader + (b.size() - kHeader) / 2] ^= 0x10; break;
            case Damage::truncated: b.resize(b.size() - 3); break;
            case Damage::shorter_than_header: b.resize(kHeader / 2); break;
            case Damage::wrong_magic: b[0] ^= 0xFF; break;
            case Damage::other_key: b = good.at(keys[(i + 1) % keys.size()]); break;
            case Damage::refused_by_driver: {
                // A well-formed blob of ours whose driver binary is garbage: only the GL can tell.
                for (size_t j = kHeader; j < b.size(); ++j) b[j] = uint8_t(j * 131u + 7u);
                const uint64_t sum = fnv1a64(b.data() + kHeader, b.size() - kHeader);
                std::memcpy(b.data() + kChecksumAt, &sum, 8);
                uint64_t size = 0;
                std::memcpy(&size, b.data() + kPayloadSizeAt, 8);
                ASSERT_EQ(size, b.size() - kHeader);
                break;
            }
        }
    }
    cache.reset_counts();
    Messages messages;
    SimPtr rebuilt = create(desc(&cache, &messages));
    ASSERT_TRUE(rebuilt) << (messages.lines.empty() ? "" : messages.lines.back());
    EXPECT_EQ(cache.hits, programs) << "each damaged blob was read";
    EXPECT_EQ(cache.stores, programs) << "each program compiled from source and stored again";
    EXPECT_EQ(messages.count("is not used"), programs) << "each rejection logged";
    for (const std::string& k : keys) EXPECT_EQ(cache.blobs[k].size() > kHeader, true) << k;
    expect_identical(dam_break(rebuilt.get()), reference());
    // The blobs stored again are good: a third create loads them all.
    cache.reset_counts();
    SimPtr third = create(desc(&cache));
    ASSERT_TRUE(third);
    EXPECT_EQ(cache.hits, programs);
    EXPECT_EQ(cache.stores, 0u);
}

std::string damage_name(const ::testing::TestParamInfo<Damage>& info) {
    static const char* const kNames[] = {"FlippedPayloadByte", "Truncated", "ShorterThanHeader",
                                         "WrongMagic",         "OtherKey",  "RefusedByDriver"};
    return kNames[int(info.param)];
}

INSTANTIATE_TEST_SUITE_P(Blobs, ProgramCacheDamage,
                         ::testing::Values(Damage::flipped_payload_byte, Damage::truncated, Damage::shorter_than_header,
                                           Damage::wrong_magic, Damage::other_key, Damage::refused_by_driver),
                         damage_name);

TEST_F(ProgramCache, ALargerBlobIsFetchedWithASecondCall) {
    // load reports a size above the capacity it was given: pflip calls again with room for it.
    struct Padded {
        MemoryCache inner;
        uint32_t calls = 0;
        static size_t load(void* user, const char* key, void* data, size_t capacity) {
            auto& p = *static_cast<Padded*>(user);
            ++p.calls;
            const size_t size = MemoryCache::load(&p.inner, key, data, capacity);
            return size != 0 && p.calls % 2 == 1 ? capacity + 1 : size;  // first call of each: "too small"
        }
    } padded;
    { SimPtr first = create(desc(&padded.inner)); }
    const uint32_t programs = padded.inner.stores;
    padded.inner.reset_counts();
    pf_sim_desc d = desc(nullptr);
    d.program_cache = pf_program_cache{&padded, &Padded::load, &MemoryCache::store};
    Messages messages;
    d.logger = pf_logger{&Messages::fn, &messages};
    SimPtr second = create(d);
    ASSERT_TRUE(second);
    EXPECT_EQ(padded.calls, 2 * programs);
    // The second call's answer (the real size) fits the buffer sized for the first's.
    EXPECT_EQ(padded.inner.stores, 0u);
    EXPECT_EQ(messages.count("is not used"), 0u);
}

TEST_F(ProgramCache, TheRenderersProgramsUseTheSimulationsCache) {
    ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc)));
    MemoryCache cache;
    const std::vector<float> xyz = {0.4f, 0.4f, 0.8f, 1.2f, 0.4f, 0.8f};
    EngineTarget t(64, 48, GL_RGBA32F);
    const int vp[4] = {0, 0, 64, 48};
    const TestCamera c = make_camera({0.8, 0.8, 3.2}, {0.8, 0.8, 0.8}, 45.0, vp, 0.1, 10.0, PF_DEPTH_STANDARD);
    pf_particle_params p = pf_default_particle_params();
    p.particle_radius = 0.1f;
    const pf_render_target target{t.fbo, 0, 0, 0};
    auto draw = [&](pf_sim* sim) {
        EXPECT_EQ(pf_add_particles(sim, xyz.data(), nullptr, 2), PF_OK);
        t.write_color(std::vector<float>(size_t(t.width) * t.height * 4, 0.0f));
        t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
        EXPECT_EQ(pf_render_particles(sim, &c.cam, &target, &p), PF_OK) << last_log();
        return t.read_color();
    };
    std::vector<float> compiled, loaded;
    uint32_t render_programs = 0;
    {
        SimPtr first = create(desc(&cache));
        ASSERT_TRUE(first);
        cache.reset_counts();
        compiled = draw(first.get());
        render_programs = cache.stores;
        EXPECT_GT(render_programs, 0u) << "the sprites' program was stored";
    }
    SimPtr second = create(desc(&cache));
    ASSERT_TRUE(second);
    cache.reset_counts();
    loaded = draw(second.get());
    EXPECT_EQ(cache.hits, render_programs);
    EXPECT_EQ(cache.stores, 0u);
    EXPECT_EQ(compiled, loaded);
}

TEST_F(ProgramCache, PreparedFeaturesBuildAtCreateAndTurningThemOnBuildsNothing) {
    MemoryCache cache;
    pf_sim_desc d = desc(&cache);
    d.prepared_features = PF_FEATURE_ALL;
    SimPtr prepared = create(d);
    ASSERT_TRUE(prepared);
    const uint32_t with_effects = cache.stores;
    // Off until turned on: the same statistics list (no effect's entries) and passes as without.
    SimPtr plain = create(desc(nullptr));
    ASSERT_TRUE(plain);
    uint32_t features = 1;
    ASSERT_EQ(pf_get_features(prepared.get(), &features), PF_OK);
    EXPECT_EQ(features, 0u);
    const ParticleState off = dam_break(prepared.get());
    expect_identical(off, dam_break(plain.get()));
    EXPECT_EQ(pass_list(prepared.get()).size(), pass_list(plain.get()).size());

    cache.reset_counts();
    ASSERT_EQ(pf_set_features(prepared.get(), PF_FEATURE_ALL), PF_OK) << last_log();
    for (int i = 0; i < 2; ++i) ASSERT_EQ(pf_step(prepared.get(), kDt), PF_OK) << last_log();
    EXPECT_EQ(cache.loads, 0u) << "turning prepared effects on (and stepping) built a program";
    EXPECT_EQ(cache.stores, 0u);

    // Without preparing, the same call builds the effects' programs (what the counts above catch).
    MemoryCache late;
    SimPtr unprepared = create(desc(&late));
    ASSERT_TRUE(unprepared);
    const uint32_t core = late.stores;
    EXPECT_LT(core, with_effects);
    late.reset_counts();
    ASSERT_EQ(pf_set_features(unprepared.get(), PF_FEATURE_ALL), PF_OK) << last_log();
    EXPECT_EQ(late.stores, with_effects - core) << "the effects' programs, built now";
}

TEST_F(ProgramCache, StoringLoadingAndRejectingKeepTheEnginesGlState) {
    ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc)));
    Engine engine(EngineProgram::graphics);
    int v = 0;
    MemoryCache cache;
    pf_sim_desc d = desc(&cache);
    d.prepared_features = PF_FEATURE_OBSTACLES | PF_FEATURE_WHITEWATER;
    auto create_and_destroy = [&](const char* what) {
        pf_sim* sim = nullptr;
        guarded_call(engine, v++, what, [&] { ASSERT_EQ(pf_create(&d, &sim), PF_OK) << last_log(); });
        ASSERT_NE(sim, nullptr);
        guarded_call(engine, v++, "pf_set_features (prepared)", [&] {
            EXPECT_EQ(pf_set_features(sim, PF_FEATURE_OBSTACLES | PF_FEATURE_WHITEWATER), PF_OK) << last_log();
        });
        guarded_call(engine, v++, "pf_destroy", [&] { EXPECT_EQ(pf_destroy(sim), PF_OK); });
    };
    create_and_destroy("pf_create storing");
    EXPECT_GT(cache.stores, 0u);
    cache.reset_counts();
    create_and_destroy("pf_create loading");
    EXPECT_EQ(cache.stores, 0u);
    // Half the blobs refused by the driver, half failing pflip's own checks.
    bool odd = false;
    for (auto& kv : cache.blobs) {
        std::vector<uint8_t>& b = kv.second;
        if ((odd = !odd)) {
            for (size_t j = kHeader; j < b.size(); ++j) b[j] = uint8_t(j * 7u);
            const uint64_t sum = fnv1a64(b.data() + kHeader, b.size() - kHeader);
            std::memcpy(b.data() + kChecksumAt, &sum, 8);
        } else {
            b[b.size() - 1] ^= 1;
        }
    }
    cache.reset_counts();
    create_and_destroy("pf_create rejecting every blob");
    EXPECT_EQ(cache.stores, cache.hits);
    engine.unbind_all();
}

TEST_F(ProgramCache, UnknownPreparedFeatureBitsAreRefused) {
    MemoryCache cache;
    pf_sim_desc d = desc(&cache);
    d.prepared_features = PF_FEATURE_ALL + 1u;  // one past the last bit: unknown
    pf_sim* s = reinterpret_cast<pf_sim*>(uintptr_t(0x1234));
    clear_log();
    EXPECT_EQ(pf_create(&d, &s), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(s, reinterpret_cast<pf_sim*>(uintptr_t(0x1234))) << "out is set only on PF_OK";
    EXPECT_NE(std::string(last_log()).find("prepared_features"), std::string::npos) << last_log();
    EXPECT_EQ(cache.loads + cache.stores, 0u) << "nothing was built";
}

}  // namespace
}  // namespace pf::test
