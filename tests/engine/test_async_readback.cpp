// Asynchronous readback (pf_request_particles / pf_poll_particles): many requests in flight over
// many steps, each equal bit for bit to the blocking pf_read_particles of its step; polls never
// wait (a loader whose glClientWaitSync reports "not yet" shows every poll returns at once with
// PF_NOT_READY and asks with timeout 0); both the persistently mapped path (GL 4.4 /
// ARB_buffer_storage) and the glGetBufferSubData path; bad tickets, ranges and a full queue are
// refused with a logged error and change nothing.
#include <glad/gl.h>

#include <cstring>
#include <string>
#include <vector>

#include "support/engine_state.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

constexpr float kDt = 1.0f / 60.0f;

// Loader stand-ins: glClientWaitSync that can be held at "not signalled" and records the largest
// timeout asked for; a loader without glBufferStorage (a GL 4.3 driver).
bool g_hold_fences = false;
uint64_t g_largest_timeout = 0;
uint32_t g_wait_calls = 0;
PFNGLCLIENTWAITSYNCPROC g_real_wait = nullptr;

GLenum GLAD_API_PTR held_wait(GLsync sync, GLbitfield flags, GLuint64 timeout) {
    ++g_wait_calls;
    g_largest_timeout = std::max<uint64_t>(g_largest_timeout, timeout);
    if (g_hold_fences) return GL_TIMEOUT_EXPIRED;
    return g_real_wait(sync, flags, timeout);
}

pf_gl_proc holding_loader(const char* name) {
    if (std::strcmp(name, "glClientWaitSync") == 0) {
        g_real_wait = reinterpret_cast<PFNGLCLIENTWAITSYNCPROC>(get_proc(name));
        return reinterpret_cast<pf_gl_proc>(held_wait);
    }
    return get_proc(name);
}

pf_gl_proc gl43_loader(const char* name) {
    if (std::strcmp(name, "glBufferStorage") == 0) return nullptr;
    return get_proc(name);
}

class AsyncReadback : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc)));
        drain_gl_errors();
    }

    SimPtr dam(pf_gl_get_proc_address_fn loader = get_proc) {
        pf_sim_desc d = test_desc(16, 16, 16, 0.05f);
        d.gl_get_proc_address = loader;
        SimPtr s = create(d);
        const float lo[3] = {0.05f, 0.05f, 0.05f}, hi[3] = {0.35f, 0.6f, 0.4f}, v[3] = {0.5f, 0.0f, -0.2f};
        EXPECT_EQ(pf_fill_box(s.get(), lo, hi, v), PF_OK) << last_log();
        return s;
    }

    static uint32_t count_of(pf_sim* s) {
        pf_stats st{};
        EXPECT_EQ(pf_get_stats(s, &st), PF_OK);
        return st.particle_count;
    }

    // Polls until ready; the engine's glFinish after many tries only bounds the test's time.
    static pf_result collect(pf_sim* s, uint32_t ticket, std::vector<float>& xyz, std::vector<float>& vel,
                             int* not_ready = nullptr) {
        for (int i = 0; i < 100000; ++i) {
            const pf_result r = pf_poll_particles(s, ticket, xyz.data(), vel.data());
            if (r != PF_NOT_READY) return r;
            if (not_ready) ++*not_ready;
            if (i == 1000) glFinish();
        }
        return PF_NOT_READY;
    }

    // Buffers labelled pflip/particle_request and whether each is mapped.
    static std::vector<bool> request_buffers_mapped() {
        std::vector<bool> out;
        for (GLuint n = 1; n < 4096; ++n) {
            if (!glIsBuffer(n)) continue;
            char label[64] = {};
            GLsizei len = 0;
            glGetObjectLabel(GL_BUFFER, n, sizeof label, &len, label);
            if (std::string(label, size_t(len)) != "pflip/particle_request") continue;
            GLint mapped = 0;
            glBindBuffer(GL_COPY_READ_BUFFER, n);
            glGetBufferParameteriv(GL_COPY_READ_BUFFER, GL_BUFFER_MAPPED, &mapped);
            glBindBuffer(GL_COPY_READ_BUFFER, 0);
            out.push_back(mapped != 0);
        }
        return out;
    }

    void many_in_flight(pf_gl_get_proc_address_fn loader, bool expect_mapped);
};

void AsyncReadback::many_in_flight(pf_gl_get_proc_address_fn loader, bool expect_mapped) {
    SimPtr sim = dam(loader);
    pf_sim* s = sim.get();
    const uint32_t n = count_of(s);
    ASSERT_GT(n, 1000u);
    constexpr int kSteps = 8;
    std::vector<uint32_t> tickets;
    std::vector<uint32_t> firsts, counts;
    std::vector<std::vector<float>> want_xyz, want_vel;
    for (int i = 0; i < kSteps; ++i) {
        ASSERT_EQ(pf_step(s, kDt), PF_OK) << last_log();
        // Whole set on even steps, a range in the middle on odd ones.
        const uint32_t first = (i % 2) ? 17u * uint32_t(i) : 0u, count = (i % 2) ? n / 3 : n;
        uint32_t t = 0;
        ASSERT_EQ(pf_request_particles(s, first, count, &t), PF_OK) << last_log();
        EXPECT_NE(t, 0u);
        for (uint32_t earlier : tickets) EXPECT_NE(t, earlier);
        tickets.push_back(t);
        firsts.push_back(first);
        counts.push_back(count);
        want_xyz.emplace_back(size_t(count) * 3);
        want_vel.emplace_back(size_t(count) * 3);
        ASSERT_EQ(pf_read_particles(s, first, count, want_xyz.back().data(), want_vel.back().data()), PF_OK);
    }
    // The particles moved between the requests: each request must hold its own step's state.
    EXPECT_NE(0, std::memcmp(want_xyz[0].data(), want_xyz[2].data(), want_xyz[0].size() * 4));
    const std::vector<bool> mapped = request_buffers_mapped();
    EXPECT_EQ(mapped.size(), size_t(kSteps)) << "one readback buffer per request in flight";
    for (bool m : mapped) EXPECT_EQ(m, expect_mapped) << "persistently mapped readback buffers";
    // Collected newest first: order does not matter.
    for (int i = kSteps - 1; i >= 0; --i) {
        SCOPED_TRACE("request of step " + std::to_string(i + 1));
        std::vector<float> xyz(size_t(counts[size_t(i)]) * 3, -1.0f), vel(size_t(counts[size_t(i)]) * 3, -1.0f);
        ASSERT_EQ(collect(s, tickets[size_t(i)], xyz, vel), PF_OK) << last_log();
        EXPECT_EQ(0, std::memcmp(xyz.data(), want_xyz[size_t(i)].data(), xyz.size() * 4)) << "positions differ";
        EXPECT_EQ(0, std::memcmp(vel.data(), want_vel[size_t(i)].data(), vel.size() * 4)) << "velocities differ";
        // Collected: the ticket is released.
        EXPECT_EQ(pf_poll_particles(s, tickets[size_t(i)], xyz.data(), vel.data()), PF_ERROR_INVALID_ARGUMENT);
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(AsyncReadback, EightInFlightOverEightStepsEqualTheBlockingReads) { many_in_flight(get_proc, GLAD_GL_ARB_buffer_storage != 0);
}

TEST_F(AsyncReadback, WithoutBufferStorageTheFencedCopyIsReadTheSame) { many_in_flight(gl43_loader, false); }

TEST_F(AsyncReadback, PollsNeverWait) {
    g_hold_fences = true;
    g_largest_timeout = 0;
    SimPtr sim = dam(holding_loader);
    pf_sim* s = sim.get();
    ASSERT_EQ(pf_step(s, kDt), PF_OK) << last_log();
    const uint32_t n = count_of(s);
    std::vector<float> want(size_t(n) * 3);
    uint32_t t = 0;
    ASSERT_EQ(pf_request_particles(s, 0, n, &t), PF_OK) << last_log();
    ASSERT_EQ(pf_read_particles(s, 0, n, want.data(), nullptr), PF_OK);
    glFinish();  // the copy is certainly done: only the fence test says "not yet"
    std::vector<float> xyz(size_t(n) * 3, -1.0f);
    const std::vector<float> untouched = xyz;
    g_wait_calls = 0;
    for (int i = 0; i < 50; ++i) EXPECT_EQ(pf_poll_particles(s, t, xyz.data(), nullptr), PF_NOT_READY);
    EXPECT_GE(g_wait_calls, 50u) << "polls must test the fence";
    EXPECT_EQ(g_largest_timeout, 0u) << "a poll asked glClientWaitSync to wait";
    EXPECT_EQ(xyz, untouched) << "PF_NOT_READY wrote data";
    g_hold_fences = false;
    EXPECT_EQ(pf_poll_particles(s, t, xyz.data(), nullptr), PF_OK) << last_log();
    EXPECT_EQ(0, std::memcmp(xyz.data(), want.data(), xyz.size() * 4));
    EXPECT_EQ(g_largest_timeout, 0u);
}

TEST_F(AsyncReadback, BadRequestsAndTicketsAreRefusedAndChangeNothing) {
    SimPtr sim = dam();
    SimPtr other = dam();
    pf_sim* s = sim.get();
    const uint32_t n = count_of(s);
    std::vector<float> xyz(size_t(n) * 3), vel(size_t(n) * 3);
    uint32_t t = 12345;
    clear_log();
    EXPECT_EQ(pf_request_particles(s, 0, n, nullptr), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(last_log()).find("out_ticket"), std::string::npos) << last_log();
    for (auto [first, count] : {std::pair{0u, n + 1}, std::pair{n, 1u}, std::pair{UINT32_MAX, 2u}}) {
        clear_log();
        EXPECT_EQ(pf_request_particles(s, first, count, &t), PF_ERROR_INVALID_ARGUMENT);
        EXPECT_EQ(t, 12345u) << "out_ticket written on error";
        EXPECT_NE(std::string(last_log()).find("exceeds"), std::string::npos) << last_log();
    }
    // A full queue: the 17th request is refused; the 16 in flight stay collectable.
    std::vector<uint32_t> tickets(PF_MAX_PARTICLE_REQUESTS);
    for (uint32_t& k : tickets) ASSERT_EQ(pf_request_particles(s, 0, 10, &k), PF_OK) << last_log();
    clear_log();
    EXPECT_EQ(pf_request_particles(s, 0, 10, &t), PF_ERROR_CAPACITY);
    EXPECT_EQ(t, 12345u);
    EXPECT_NE(std::string(last_log()).find("PF_MAX_PARTICLE_REQUESTS"), std::string::npos) << last_log();
    // Tickets that are not in flight here: 0, never issued, another simulation's.
    uint32_t theirs = 0;
    ASSERT_EQ(pf_request_particles(other.get(), 0, 10, &theirs), PF_OK);
    for (uint32_t bad : {0u, tickets.back() + 1000u, theirs}) {
        clear_log();
        const std::vector<float> before = xyz;
        EXPECT_EQ(pf_poll_particles(s, bad, xyz.data(), vel.data()), PF_ERROR_INVALID_ARGUMENT) << bad;
        EXPECT_NE(std::string(last_log()).find("not in flight"), std::string::npos) << last_log();
        EXPECT_EQ(xyz, before);
    }
    for (uint32_t k : tickets) {
        std::vector<float> a(30), b(30);
        EXPECT_EQ(collect(s, k, a, b), PF_OK) << last_log();
    }
    std::vector<float> a(30), b(30);
    EXPECT_EQ(collect(other.get(), theirs, a, b), PF_OK) << last_log();
    // Room again; a request may be dropped unread (both outputs NULL) and an empty one is ready at once.
    ASSERT_EQ(pf_request_particles(s, 0, n, &t), PF_OK);
    for (int i = 0; i < 100000; ++i) {
        const pf_result r = pf_poll_particles(s, t, nullptr, nullptr);
        if (r == PF_OK) break;
        ASSERT_EQ(r, PF_NOT_READY);
        if (i == 1000) glFinish();
    }
    ASSERT_EQ(pf_request_particles(s, 0, 0, &t), PF_OK);
    EXPECT_EQ(collect(s, t, a, b), PF_OK);
    // A simulation destroyed with requests in flight frees them (ASan / LSan stages check it).
    ASSERT_EQ(pf_request_particles(other.get(), 0, 10, &theirs), PF_OK);
    other.reset();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// The GL state promise holds for both calls.
TEST_F(AsyncReadback, LeavesTheEngineStateAlone) {
    SimPtr sim = dam();
    pf_sim* s = sim.get();
    Engine engine(EngineProgram::compute);
    uint32_t t = 0;
    guarded_call(engine, 0, "pf_request_particles", [&] { ASSERT_EQ(pf_request_particles(s, 0, 100, &t), PF_OK); });
    std::vector<float> a(300), b(300);
    guarded_call(engine, 1, "pf_poll_particles", [&] { ASSERT_EQ(collect(s, t, a, b), PF_OK); });
}

}  // namespace
}  // namespace pf::test
