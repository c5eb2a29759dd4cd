// KHR_debug markers seen from an engine (src/gl/debug.h): every GL object a simulation and its
// renderer make carries a "pflip/<name>" label, every pass runs in a "pflip/<pass>" debug group
// (balanced: the engine's group stack is unchanged after each call), and a loader without the
// KHR_debug entry points still gives a working simulation, unlabelled.
#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "support/engine_state.h"
#include "support/render_fixture.h"

namespace pf::test {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr GLuint kMaxName = 8192;  // names enumerated (a fresh test process makes far fewer)

struct Kind {
    const char* what;
    GLenum identifier;
    std::function<bool(GLuint)> is;
};

const std::vector<Kind>& kinds() {
    static const std::vector<Kind> k = {
        {"buffer", GL_BUFFER, [](GLuint n) { return glIsBuffer(n) == GL_TRUE; }},
        {"program", GL_PROGRAM, [](GLuint n) { return glIsProgram(n) == GL_TRUE; }},
        {"texture", GL_TEXTURE, [](GLuint n) { return glIsTexture(n) == GL_TRUE; }},
        {"framebuffer", GL_FRAMEBUFFER, [](GLuint n) { return glIsFramebuffer(n) == GL_TRUE; }},
        {"vertex array", GL_VERTEX_ARRAY, [](GLuint n) { return glIsVertexArray(n) == GL_TRUE; }},
        {"sampler", GL_SAMPLER, [](GLuint n) { return glIsSampler(n) == GL_TRUE; }},
    };
    return k;
}

// Every live object name of each kind (index as kinds()).
std::vector<std::set<GLuint>> live_objects() {
    std::vector<std::set<GLuint>> out(kinds().size());
    for (size_t k = 0; k < kinds().size(); ++k)
        for (GLuint n = 1; n <= kMaxName; ++n)
            if (kinds()[k].is(n)) out[k].insert(n);
    return out;
}

std::string label_of(GLenum identifier, GLuint name) {
    char buf[512] = {};
    GLsizei length = 0;
    glGetObjectLabel(identifier, name, GLsizei(sizeof buf), &length, buf);
    return std::string(buf, size_t(length));
}

// The debug messages of group pushes and pops the GL reports while `call` runs.
struct GroupLog {
    std::vector<std::string> pushed;
    int depth = 0, deepest = 0, pops = 0;
};

void GLAD_API_PTR record_group(GLenum source, GLenum type, GLuint, GLenum, GLsizei length, const GLchar* message,
                               const void* user) {
    auto* log = static_cast<GroupLog*>(const_cast<void*>(user));
    if (source != GL_DEBUG_SOURCE_APPLICATION) return;
    if (type == GL_DEBUG_TYPE_PUSH_GROUP) {
        log->pushed.emplace_back(message, length >= 0 ? size_t(length) : std::strlen(message));
        log->deepest = std::max(log->deepest, ++log->depth);
    } else if (type == GL_DEBUG_TYPE_POP_GROUP) {
        --log->depth;
        ++log->pops;
    }
}

template <typename Fn>
GroupLog groups_during(Fn&& call) {
    GroupLog log;
    glDebugMessageCallback(record_group, &log);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glEnable(GL_DEBUG_OUTPUT);
    call();
    glDisable(GL_DEBUG_OUTPUT);
    glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(nullptr, nullptr);
    return log;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

class DebugLabels : public RenderTest {};

// Every object of every kind made between "before" (nothing of pflip's) and "after" (a
// simulation with every feature, every solver and transfer built, both render paths run)
// is labelled "pflip/...".
TEST_F(DebugLabels, EveryObjectThePflipMadeIsLabelled) {
    sim_.reset();
    const auto before = live_objects();
    pf_sim_desc d = test_desc(16, 16, 16, 0.1f);
    d.features = PF_FEATURE_ALL;
    sim_ = create(d);
    ASSERT_TRUE(sim_);
    pf_sim* s = sim_.get();
    const float lo[3] = {0.2f, 0.2f, 0.2f}, hi[3] = {0.8f, 0.8f, 0.8f};
    ASSERT_EQ(pf_fill_box(s, lo, hi, nullptr), PF_OK) << last_log();
    pf_force_field f = pf_default_force_field();
    f.vector[0] = 1.0f;
    ASSERT_EQ(pf_add_force_field(s, &f, nullptr), PF_OK);
    pf_obstacle o = pf_default_obstacle();
    o.position[0] = o.position[1] = o.position[2] = 1.2f;
    ASSERT_EQ(pf_add_obstacle(s, &o, nullptr), PF_OK);
    for (pf_pressure_solver solver : {PF_PRESSURE_SOLVER_JACOBI, PF_PRESSURE_SOLVER_RBGS, PF_PRESSURE_SOLVER_CG,
                                      PF_PRESSURE_SOLVER_PCG, PF_PRESSURE_SOLVER_MGPCG}) {
        pf_sim_params p = pf_default_sim_params();
        p.pressure_solver = solver;
        p.transfer = solver == PF_PRESSURE_SOLVER_MGPCG ? PF_TRANSFER_APIC : PF_TRANSFER_PIC_FLIP;
        ASSERT_EQ(pf_set_params(s, &p), PF_OK) << last_log();
        ASSERT_EQ(pf_step(s, kDt), PF_OK) << last_log();
    }
    EngineTarget t(64, 48, GL_RGBA8);
    const int vp[4] = {0, 0, 64, 48};
    const TestCamera c = camera(vp);
    const pf_render_target target{t.fbo, t.color, t.depth, 0};
    for (pf_ssf_path path : {PF_SSF_PATH_COMPUTE, PF_SSF_PATH_RASTER}) {
        pf_ssf_params p = pf_default_ssf_params();
        p.path = path;
        ASSERT_EQ(pf_render_ssf(s, &c.cam, &target, &p), PF_OK) << last_log();
    }
    ASSERT_EQ(pf_render_particles(s, &c.cam, &target, nullptr), PF_OK) << last_log();
    const auto after = live_objects();

    size_t made = 0;
    std::set<std::string> labels;
    for (size_t k = 0; k < kinds().size(); ++k) {
        for (GLuint n : after[k]) {
            if (before[k].count(n)) continue;
            if (kinds()[k].identifier == GL_TEXTURE && (n == t.color || n == t.depth)) continue;  // the engine's
            if (kinds()[k].identifier == GL_FRAMEBUFFER && n == t.fbo) continue;
            ++made;
            const std::string label = label_of(kinds()[k].identifier, n);
            EXPECT_EQ(label.rfind("pflip/", 0), 0u) << kinds()[k].what << " " << n << " is labelled \"" << label << "\"";
            labels.insert(label);
        }
    }
    EXPECT_GT(made, 60u) << "too few objects found: the enumeration is broken";
    pf_gl_buffers b{};
    ASSERT_EQ(pf_get_gl_buffers(s, &b), PF_OK);
    EXPECT_EQ(label_of(GL_BUFFER, b.positions), "pflip/particle_pos");
    EXPECT_EQ(label_of(GL_BUFFER, b.velocities), "pflip/particle_vel");
    for (const char* expected : {"pflip/p2g_tile_splat", "pflip/pressure_setup", "pflip/cg_r", "pflip/mg_r", "pflip/particle_affine",
                                 "pflip/obstacles", "pflip/force_fields", "pflip/ssf_thickness", "pflip/ssf_shade_fb",
                                 "pflip/particle_sprites", "pflip/sampler_linear"})
        EXPECT_TRUE(labels.count(expected)) << expected << " not among the labels";
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Debug groups: a step is "pflip/step" around one group per pass, a render call one per render
// pass, and every push is popped before the call returns.
TEST_F(DebugLabels, PassesRunInBalancedDebugGroups) {
    pf_sim* s = sim_.get();
    const float lo[3] = {0.2f, 0.2f, 0.2f}, hi[3] = {0.8f, 0.8f, 0.8f};
    ASSERT_EQ(pf_fill_box(s, lo, hi, nullptr), PF_OK) << last_log();
    // The engine has a group of its own open: pflip's nest inside it and leave it open.
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 7, -1, "engine/frame");
    const GLint depth0 = geti(GL_DEBUG_GROUP_STACK_DEPTH);
    const GroupLog step = groups_during([&] { ASSERT_EQ(pf_step(s, kDt), PF_OK) << last_log(); });
    EXPECT_EQ(geti(GL_DEBUG_GROUP_STACK_DEPTH), depth0);
    ASSERT_FALSE(step.pushed.empty()) << "no debug group messages reported: the GL lacks KHR_debug output";
    EXPECT_EQ(step.pushed.front(), "pflip/step");
    EXPECT_EQ(step.depth, 0);
    EXPECT_EQ(size_t(step.pops), step.pushed.size());
    EXPECT_EQ(step.deepest, 2) << "pass groups nest directly inside pflip/step";
    for (const char* pass : {"pflip/clear", "pflip/p2g", "pflip/grid_forces", "pflip/classify", "pflip/pressure_setup",
                             "pflip/mgpcg", "pflip/velocity_update", "pflip/extrapolate", "pflip/g2p", "pflip/advect",
                             "pflip/metrics"})
        EXPECT_TRUE(contains(step.pushed, pass)) << pass;
    for (const std::string& g : step.pushed) EXPECT_EQ(g.rfind("pflip/", 0), 0u) << g;

    EngineTarget t(64, 48, GL_RGBA8);
    const int vp[4] = {0, 0, 64, 48};
    const TestCamera c = camera(vp);
    const pf_render_target target{t.fbo, t.color, t.depth, 0};
    const GroupLog render = groups_during([&] { ASSERT_EQ(pf_render_ssf(s, &c.cam, &target, nullptr), PF_OK) << last_log(); });
    EXPECT_EQ(geti(GL_DEBUG_GROUP_STACK_DEPTH), depth0);
    ASSERT_FALSE(render.pushed.empty());
    EXPECT_EQ(render.pushed.front(), "pflip/render_ssf");
    EXPECT_EQ(render.depth, 0);
    for (int p = 0; p < PF_RENDER_PASS_PARTICLES; ++p)
        EXPECT_TRUE(contains(render.pushed, std::string("pflip/") + pf_render_pass_name(pf_render_pass(p))))
            << pf_render_pass_name(pf_render_pass(p));
    glPopDebugGroup();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A loader without KHR_debug's entry points (an engine on a GL that lacks it): pflip runs,
// labels nothing, pushes no group, and the particles are bit-identical to a run with markers.
pf_gl_proc without_debug(const char* name) {
    for (const char* hidden : {"glObjectLabel", "glPushDebugGroup", "glPopDebugGroup"})
        if (std::strcmp(name, hidden) == 0) return nullptr;
    return get_proc(name);
}

TEST_F(DebugLabels, LoaderWithoutKhrDebugRunsUnlabelledAndIdentical) {
    sim_.reset();
    auto run = [&](pf_gl_get_proc_address_fn loader, std::vector<float>& xyz, double& cpu_ms_per_step,
                   std::vector<std::string>& groups, std::string& pos_label) {
        pf_sim_desc d = test_desc(24, 24, 24, 0.05f);
        d.gl_get_proc_address = loader;
        SimPtr sim = create(d);
        ASSERT_TRUE(sim);
        const float lo[3] = {0.1f, 0.1f, 0.1f}, hi[3] = {0.6f, 0.9f, 0.6f};
        ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK) << last_log();
        groups = groups_during([&] { ASSERT_EQ(pf_step(sim.get(), kDt), PF_OK) << last_log(); }).pushed;
        double total = 0.0;
        uint32_t dispatches = 0;
        for (int i = 0; i < 20; ++i) {
            ASSERT_EQ(pf_step(sim.get(), kDt), PF_OK) << last_log();
            pf_stats st{};
            ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
            total += st.cpu_ms;
            for (uint32_t n : st.dispatches) dispatches += n;
        }
        cpu_ms_per_step = total / 20.0;
        std::printf("  %s: %.3f ms CPU per step, %.2f us per dispatch\n", loader == get_proc ? "markers" : "no markers",
                    cpu_ms_per_step, 1000.0 * total / std::max(1u, dispatches));
        pf_gl_buffers b{};
        ASSERT_EQ(pf_get_gl_buffers(sim.get(), &b), PF_OK);
        pos_label = label_of(GL_BUFFER, b.positions);
        xyz.resize(size_t(b.count) * 3);
        ASSERT_EQ(pf_read_particles(sim.get(), 0, b.count, xyz.data(), nullptr), PF_OK);
    };
    std::vector<float> with, without;
    double ms_with = 0, ms_without = 0;
    std::vector<std::string> groups_with, groups_without;
    std::string label_with, label_without;
    run(without_debug, without, ms_without, groups_without, label_without);
    run(get_proc, with, ms_with, groups_with, label_with);
    // What the markers add per dispatch on this GL: one push and one pop (printed, not asserted).
    {
        constexpr int kPairs = 20000;
        const auto t0 = std::chrono::steady_clock::now();
        for (int i = 0; i < kPairs; ++i) {
            glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "pflip/p2g");
            glPopDebugGroup();
        }
        const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
        std::printf("  one debug group push + pop: %.3f us\n", us / kPairs);
    }
    EXPECT_TRUE(groups_without.empty()) << groups_without.size() << " groups pushed without the entry points";
    EXPECT_EQ(label_without, "");
    EXPECT_FALSE(groups_with.empty());
    EXPECT_EQ(label_with, "pflip/particle_pos");
    ASSERT_FALSE(with.empty());
    EXPECT_EQ(0, std::memcmp(with.data(), without.data(), with.size() * sizeof(float)))
        << "debug markers changed the simulation";
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pf::test
