// Handles are generation-checked ids (src/api/handle.h): a destroyed handle, a handle whose slot
// was reused by a later simulation, NULL or any stray value gives PF_ERROR_INVALID_ARGUMENT from
// every entry point, with a message to the global logger (pf_set_global_logger), and never
// reaches a live simulation. Run under ASan (scripts/test_sanitizers.sh) these calls also show
// that no freed memory is read.
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

constexpr float kDt = 1.0f / 60.0f;

struct GlobalLog {
    std::mutex mutex;
    std::vector<std::string> messages;
    std::vector<pf_result> codes;
    int errors = 0;
};

void record_global(void* user, pf_log_level level, pf_result code, const char* message) {
    auto* log = static_cast<GlobalLog*>(user);
    std::lock_guard<std::mutex> lock(log->mutex);
    log->messages.emplace_back(message);
    log->codes.push_back(code);
    if (level == PF_LOG_ERROR) ++log->errors;
}

class Handles : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        const pf_logger logger{record_global, &log_};
        pf_set_global_logger(&logger);
    }
    void TearDown() override { pf_set_global_logger(nullptr); }

    // Every entry point taking a handle, called on `h` with otherwise valid arguments.
    std::vector<std::pair<const char*, std::function<pf_result(pf_sim*)>>> calls() {
        static float xyz[3] = {0.2f, 0.2f, 0.2f}, lo[3] = {0.1f, 0.1f, 0.1f}, hi[3] = {0.3f, 0.3f, 0.3f};
        static float out[3];
        static pf_sim_params params = pf_default_sim_params();
        static pf_stats stats;
        static pf_gl_buffers buffers;
        static pf_pass_stats pass;
        static uint32_t u;
        static pf_force_field field = pf_default_force_field();
        static pf_obstacle obstacle = pf_default_obstacle();
        static pf_camera camera;
        static pf_render_target target;
        return {
            {"pf_add_particles", [](pf_sim* h) { return pf_add_particles(h, xyz, nullptr, 1); }},
            {"pf_fill_box", [](pf_sim* h) { return pf_fill_box(h, lo, hi, nullptr); }},
            {"pf_clear_particles", [](pf_sim* h) { return pf_clear_particles(h); }},
            {"pf_step", [](pf_sim* h) { return pf_step(h, kDt); }},
            {"pf_get_params", [](pf_sim* h) { return pf_get_params(h, &params); }},
            {"pf_set_params", [](pf_sim* h) { return pf_set_params(h, &params); }},
            {"pf_read_particles", [](pf_sim* h) { return pf_read_particles(h, 0, 1, out, out); }},
            {"pf_get_gl_buffers", [](pf_sim* h) { return pf_get_gl_buffers(h, &buffers); }},
            {"pf_get_stats", [](pf_sim* h) { return pf_get_stats(h, &stats); }},
            {"pf_clear_flags", [](pf_sim* h) { return pf_clear_flags(h); }},
            {"pf_get_pass_count", [](pf_sim* h) { return pf_get_pass_count(h, &u); }},
            {"pf_get_pass_stats", [](pf_sim* h) { return pf_get_pass_stats(h, 0, &pass); }},
            {"pf_set_features", [](pf_sim* h) { return pf_set_features(h, 0); }},
            {"pf_get_features", [](pf_sim* h) { return pf_get_features(h, &u); }},
            {"pf_add_force_field", [](pf_sim* h) { return pf_add_force_field(h, &field, &u); }},
            {"pf_set_force_field", [](pf_sim* h) { return pf_set_force_field(h, 1, &field); }},
            {"pf_remove_force_field", [](pf_sim* h) { return pf_remove_force_field(h, 1); }},
            {"pf_add_obstacle", [](pf_sim* h) { return pf_add_obstacle(h, &obstacle, &u); }},
            {"pf_set_obstacle", [](pf_sim* h) { return pf_set_obstacle(h, 1, &obstacle); }},
            {"pf_remove_obstacle", [](pf_sim* h) { return pf_remove_obstacle(h, 1); }},
            {"pf_render_ssf", [](pf_sim* h) { return pf_render_ssf(h, &camera, &target, nullptr); }},
            {"pf_render_particles", [](pf_sim* h) { return pf_render_particles(h, &camera, &target, nullptr); }},
            {"pf_push", [](pf_sim* h) { return pf_push(h, xyz, 0.1f, xyz); }},
            {"pf_destroy", [](pf_sim* h) { return pf_destroy(h); }},
        };
    }

    // Every call on `h` is refused with PF_ERROR_INVALID_ARGUMENT and one global error naming it.
    void expect_refused_everywhere(pf_sim* h, const char* what) {
        for (auto& [name, call] : calls()) {
            if (!h && std::string(name) == "pf_destroy") continue;  // NULL is ignored: PF_OK
            SCOPED_TRACE(std::string(what) + ": " + name);
            const size_t before = log_.messages.size();
            clear_log();
            EXPECT_EQ(call(h), PF_ERROR_INVALID_ARGUMENT);
            ASSERT_EQ(log_.messages.size(), before + 1) << "no message reached the global logger";
            EXPECT_EQ(log_.codes.back(), PF_ERROR_INVALID_ARGUMENT);
            EXPECT_NE(log_.messages.back().find(name), std::string::npos) << log_.messages.back();
            EXPECT_NE(log_.messages.back().find(h ? "invalid pf_sim" : "must not be NULL"), std::string::npos)
                << log_.messages.back();
            EXPECT_STREQ(last_log(), "") << "a simulation's own logger heard of another handle";
        }
    }

    SimPtr filled(uint32_t n = 8) {
        SimPtr s = create(test_desc(n, n, n));
        const float lo[3] = {0.1f, 0.1f, 0.1f}, hi[3] = {0.5f, 0.5f, 0.5f};
        EXPECT_EQ(pf_fill_box(s.get(), lo, hi, nullptr), PF_OK) << last_log();
        return s;
    }

    GlobalLog log_;
};

TEST_F(Handles, DestroyTwiceIsRefusedAndLogged) {
    pf_sim* s = nullptr;
    const pf_sim_desc d = test_desc(8, 8, 8);
    ASSERT_EQ(pf_create(&d, &s), PF_OK) << last_log();
    EXPECT_EQ(pf_destroy(s), PF_OK);
    EXPECT_EQ(log_.errors, 0);
    EXPECT_EQ(pf_destroy(s), PF_ERROR_INVALID_ARGUMENT);
    ASSERT_EQ(log_.errors, 1);
    EXPECT_NE(log_.messages.back().find("pf_destroy: invalid pf_sim"), std::string::npos) << log_.messages.back();
    EXPECT_EQ(pf_destroy(nullptr), PF_OK) << "NULL is ignored, as free(NULL)";
    EXPECT_EQ(log_.errors, 1);
}

TEST_F(Handles, EveryCallOnADestroyedHandleIsRefused) {
    SimPtr keep = filled();  // a live simulation beside it, which the stale calls must not reach
    pf_sim* stale = nullptr;
    const pf_sim_desc d = test_desc(8, 8, 8);
    ASSERT_EQ(pf_create(&d, &stale), PF_OK) << last_log();
    ASSERT_EQ(pf_destroy(stale), PF_OK);
    pf_stats before{};
    ASSERT_EQ(pf_get_stats(keep.get(), &before), PF_OK);
    expect_refused_everywhere(stale, "destroyed");
    expect_refused_everywhere(nullptr, "NULL");
    pf_stats after{};
    ASSERT_EQ(pf_get_stats(keep.get(), &after), PF_OK);
    EXPECT_EQ(after.particle_count, before.particle_count);
    EXPECT_EQ(after.steps, before.steps);
    EXPECT_EQ(pf_step(keep.get(), kDt), PF_OK) << last_log();
}

// A slot freed by pf_destroy and reused by the next pf_create gets a new generation: the old
// handle neither equals the new one nor reaches its simulation.
TEST_F(Handles, ReusedSlotDoesNotReviveAnOldHandle) {
    std::vector<pf_sim*> old;
    for (int i = 0; i < 3; ++i) {
        pf_sim* s = nullptr;
        const pf_sim_desc d = test_desc(8, 8, 8);
        ASSERT_EQ(pf_create(&d, &s), PF_OK) << last_log();
        old.push_back(s);
    }
    for (pf_sim* s : old) ASSERT_EQ(pf_destroy(s), PF_OK);
    std::vector<SimPtr> fresh;
    for (int i = 0; i < 3; ++i) fresh.push_back(filled());
    pf_stats first{};
    ASSERT_EQ(pf_get_stats(fresh[0].get(), &first), PF_OK);
    ASSERT_GT(first.particle_count, 0u);
    for (pf_sim* s : old) {
        for (const SimPtr& f : fresh) EXPECT_NE(s, f.get()) << "a new simulation got an old handle back";
        uint32_t features = 0;
        EXPECT_EQ(pf_get_features(s, &features), PF_ERROR_INVALID_ARGUMENT);
        const float lo[3] = {0.1f, 0.1f, 0.1f}, hi[3] = {0.2f, 0.2f, 0.2f};
        EXPECT_EQ(pf_fill_box(s, lo, hi, nullptr), PF_ERROR_INVALID_ARGUMENT);
    }
    for (const SimPtr& f : fresh) {
        pf_stats st{};
        ASSERT_EQ(pf_get_stats(f.get(), &st), PF_OK);
        EXPECT_EQ(st.particle_count, first.particle_count) << "a call on an old handle reached a new simulation";
    }
}

// Values pf_create never returned: small integers, a pointer to the caller's own memory,
// all bits set. None is dereferenced (a stack object read as a simulation would be UB).
TEST_F(Handles, StrayValuesAreRefused) {
    SimPtr keep = filled();
    uint64_t on_stack[8] = {};
    const uintptr_t live = reinterpret_cast<uintptr_t>(keep.get());
    for (uintptr_t v : {uintptr_t(1), uintptr_t(0x1ffff) /* slot 65535: never made here */, reinterpret_cast<uintptr_t>(&on_stack[0]), ~uintptr_t(0),
                        live + (uintptr_t(1) << 16)}) {  // the last: its slot's next generation
        SCOPED_TRACE(v);
        expect_refused_everywhere(reinterpret_cast<pf_sim*>(v), "stray");
    }
    for (uint64_t w : on_stack) EXPECT_EQ(w, 0u);
    EXPECT_EQ(pf_step(keep.get(), kDt), PF_OK) << last_log();
}

// The registry is shared by every thread: lookups of invalid handles on other threads while
// this one (the GL thread) creates and destroys simulations. No call may crash or succeed.
TEST_F(Handles, LookupsFromOtherThreadsWhileCreatingAndDestroying) {
    pf_set_global_logger(nullptr);  // the recorder is not what this test is about
    std::atomic<bool> stop{false};
    std::atomic<int> wrong{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 2; ++t) {
        threads.emplace_back([&, t] {
            uint32_t f = 0;
            for (uintptr_t i = 0; !stop.load(); ++i) {
                // Never-issued values (generation 0 is never used) and NULL.
                pf_sim* h = reinterpret_cast<pf_sim*>((i % 64) + 1 + uintptr_t(t));
                if (pf_get_features(h, &f) != PF_ERROR_INVALID_ARGUMENT) ++wrong;
                if (pf_get_features(nullptr, &f) != PF_ERROR_INVALID_ARGUMENT) ++wrong;
            }
        });
    }
    for (int i = 0; i < 20; ++i) {
        pf_sim* s = nullptr;
        const pf_sim_desc d = test_desc(4, 4, 4);
        ASSERT_EQ(pf_create(&d, &s), PF_OK) << last_log();
        uint32_t f = 1;
        EXPECT_EQ(pf_get_features(s, &f), PF_OK);
        EXPECT_EQ(pf_destroy(s), PF_OK);
        EXPECT_EQ(pf_destroy(s), PF_ERROR_INVALID_ARGUMENT);
    }
    stop = true;
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(wrong.load(), 0);
}

// Messages that belong to no simulation go to the global logger; none without one.
TEST_F(Handles, GlobalLoggerGetsCallsWithoutASimulation) {
    pf_sim* s = nullptr;
    EXPECT_EQ(pf_create(nullptr, &s), PF_ERROR_INVALID_ARGUMENT);
    ASSERT_EQ(log_.messages.size(), 1u);
    EXPECT_NE(log_.messages.back().find("pf_create"), std::string::npos);
    EXPECT_EQ(pf_quality_params(PF_QUALITY_COUNT, nullptr), PF_ERROR_INVALID_ARGUMENT);
    ASSERT_EQ(log_.messages.size(), 2u);
    EXPECT_NE(log_.messages.back().find("pf_quality_params"), std::string::npos);
    pf_set_global_logger(nullptr);
    EXPECT_EQ(pf_step(nullptr, kDt), PF_ERROR_INVALID_ARGUMENT);  // dropped, no crash
    EXPECT_EQ(log_.messages.size(), 2u);
}

}  // namespace
}  // namespace pf::test
