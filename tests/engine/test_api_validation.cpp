// Argument validation of every public entry point, seen from an engine: each bad argument
// gets the documented pf_result, a logged message naming the function (and the field), and
// leaves the simulation exactly as usable as before (pf_step + pf_read_particles still work,
// the particle count is unchanged). Also: zero-means-default fields, the string tables, and
// pf_create's refusal of a GL that is not 4.3.
#include <glad/gl.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kDt = 1.0f / 60.0f;

bool log_mentions(const char* what) { return std::strstr(last_log(), what) != nullptr; }

// Calls `call` with a cleared log; checks the code and that the message names `fn` and `field`.
#define EXPECT_REJECTED(call, code, fn, field)                                                               \
    do {                                                                                                     \
        clear_log();                                                                                         \
        const pf_result r_ = (call);                                                                         \
        EXPECT_EQ(r_, (code)) << #call << " -> " << pf_result_string(r_) << " (log: '" << last_log() << "')"; \
        EXPECT_TRUE(log_mentions(fn)) << #call << ": log does not name " << (fn) << ": '" << last_log() << "'"; \
        EXPECT_TRUE(log_mentions(field)) << #call << ": log does not name '" << (field) << "': '" << last_log() \
                                         << "'";                                                             \
    } while (0)

bool same_params(const pf_sim_params& a, const pf_sim_params& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::string params_str(const pf_sim_params& p) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "g=(%g,%g,%g) flip=%g iters=%u omega=%g cfl=%g substeps=%u layers=%u", p.gravity[0],
                  p.gravity[1], p.gravity[2], p.flip_ratio, p.pressure_iterations, p.jacobi_omega, p.cfl,
                  p.max_substeps, p.extrapolation_layers);
    return buf;
}

// One invalid pf_sim_params field: how to break it and the name the message must carry.
struct ParamCase {
    const char* name;
    const char* field;
    std::function<void(pf_sim_params&)> apply;
};

std::vector<ParamCase> bad_param_cases() {
    return {
        {"flip_ratio -0.1", "flip_ratio", [](pf_sim_params& p) { p.flip_ratio = -0.1f; }},
        {"flip_ratio 1.1", "flip_ratio", [](pf_sim_params& p) { p.flip_ratio = 1.1f; }},
        {"flip_ratio NaN", "flip_ratio", [](pf_sim_params& p) { p.flip_ratio = kNaN; }},
        {"flip_ratio Inf", "flip_ratio", [](pf_sim_params& p) { p.flip_ratio = kInf; }},
        {"pressure_iterations 10001", "pressure_iterations", [](pf_sim_params& p) { p.pressure_iterations = 10001; }},
        {"pressure_iterations UINT32_MAX", "pressure_iterations",
         [](pf_sim_params& p) { p.pressure_iterations = 0xffffffffu; }},
        {"jacobi_omega 1.5", "jacobi_omega", [](pf_sim_params& p) { p.jacobi_omega = 1.5f; }},
        {"jacobi_omega -0.5", "jacobi_omega", [](pf_sim_params& p) { p.jacobi_omega = -0.5f; }},
        {"jacobi_omega NaN", "jacobi_omega", [](pf_sim_params& p) { p.jacobi_omega = kNaN; }},
        {"cfl -1", "cfl", [](pf_sim_params& p) { p.cfl = -1.0f; }},
        {"cfl 17", "cfl", [](pf_sim_params& p) { p.cfl = 17.0f; }},
        {"cfl NaN", "cfl", [](pf_sim_params& p) { p.cfl = kNaN; }},
        {"cfl Inf", "cfl", [](pf_sim_params& p) { p.cfl = kInf; }},
        {"max_substeps 65", "max_substeps", [](pf_sim_params& p) { p.max_substeps = 65; }},
        {"extrapolation_layers 17", "extrapolation_layers", [](pf_sim_params& p) { p.extrapolation_layers = 17; }},
        {"gravity[0] +Inf", "gravity", [](pf_sim_params& p) { p.gravity[0] = kInf; }},
        {"gravity[1] -Inf", "gravity", [](pf_sim_params& p) { p.gravity[1] = -kInf; }},
        {"gravity[2] NaN", "gravity", [](pf_sim_params& p) { p.gravity[2] = kNaN; }},
    };
}

// A small live simulation (8^3 cells of 0.1 m, 512 particles in the lower corner) that every
// rejected call must leave usable.
class ApiValidation : public GpuTest {
protected:
    static constexpr uint32_t kFilled = 4 * 4 * 4 * 8;  // [0, 0.4]^3 at 8 particles per cell

    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc)));
        desc_ = test_desc(8, 8, 8);
        desc_.max_speed = 10.0f;
        sim_ = create(desc_);
        ASSERT_TRUE(sim_);
        const float lo[3] = {0, 0, 0}, hi[3] = {0.4f, 0.4f, 0.4f};
        ASSERT_EQ(pf_fill_box(sim_.get(), lo, hi, nullptr), PF_OK) << last_log();
        ASSERT_EQ(count(), kFilled);
        while (glGetError() != GL_NO_ERROR) {
        }
    }

    uint32_t count() const {
        pf_stats st{};
        EXPECT_EQ(pf_get_stats(sim_.get(), &st), PF_OK);
        return st.particle_count;
    }
    uint64_t steps() const {
        pf_stats st{};
        EXPECT_EQ(pf_get_stats(sim_.get(), &st), PF_OK);
        return st.steps;
    }

    // The simulation still steps, reads back `expected` finite in-domain particles, and the GL
    // reports no error.
    void expect_usable(uint32_t expected, const char* after) {
        SCOPED_TRACE(std::string("after ") + after);
        EXPECT_EQ(count(), expected);
        EXPECT_EQ(pf_step(sim_.get(), kDt), PF_OK) << last_log();
        ParticleState p = read_all(sim_.get());
        ASSERT_EQ(p.count(), size_t(expected));
        const float hi = desc_.cell_size * 8.0f;
        for (size_t i = 0; i < p.pos.size(); ++i) {
            ASSERT_TRUE(std::isfinite(p.pos[i]) && std::isfinite(p.vel[i])) << "component " << i;
            ASSERT_GE(p.pos[i], 0.0f) << "component " << i;
            ASSERT_LE(p.pos[i], hi) << "component " << i;
        }
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }

    pf_sim_desc desc_{};
    SimPtr sim_;
};

// ---------------------------------------------------------------------------------------------
// Tables and version

TEST(ApiStrings, ResultStringsNonEmptyAndDistinct) {
    const pf_result codes[] = {PF_OK,           PF_ERROR_INVALID_ARGUMENT, PF_ERROR_GL_UNSUPPORTED,
                               PF_ERROR_SHADER_COMPILE, PF_ERROR_OUT_OF_MEMORY, PF_ERROR_CAPACITY,
                               PF_ERROR_INVALID_STATE,  PF_ERROR_GL};
    std::set<std::string> seen;
    for (pf_result c : codes) {
        const char* s = pf_result_string(c);
        ASSERT_NE(s, nullptr) << "code " << int(c);
        EXPECT_GT(std::strlen(s), 0u) << "code " << int(c);
        EXPECT_TRUE(seen.insert(s).second) << "code " << int(c) << " repeats '" << s << "'";
    }
    // Unknown codes still get a non-empty string, distinct from every real code's.
    for (int bogus : {8, 99, -1, 0x7ffffffe}) {
        const char* s = pf_result_string(pf_result(bogus));
        ASSERT_NE(s, nullptr) << bogus;
        EXPECT_GT(std::strlen(s), 0u) << bogus;
        EXPECT_EQ(seen.count(s), 0u) << bogus << " reads like a real code: '" << s << "'";
    }
}

TEST(ApiStrings, PassNamesDistinctAndUnknownOutOfRange) {
    std::set<std::string> seen;
    for (int p = 0; p < PF_PASS_COUNT; ++p) {
        const char* s = pf_pass_name(pf_pass(p));
        ASSERT_NE(s, nullptr) << p;
        EXPECT_GT(std::strlen(s), 0u) << p;
        EXPECT_STRNE(s, "unknown") << p;
        EXPECT_TRUE(seen.insert(s).second) << "pass " << p << " repeats '" << s << "'";
    }
    EXPECT_EQ(seen.size(), size_t(PF_PASS_COUNT));
    // The examples pf.h gives are the stable names.
    EXPECT_STREQ(pf_pass_name(PF_PASS_P2G), "p2g");
    EXPECT_STREQ(pf_pass_name(PF_PASS_PRESSURE_SOLVE), "pressure_solve");
    for (int bogus : {int(PF_PASS_COUNT), PF_PASS_COUNT + 1, -1, 1000, 0x7fffffff}) {
        ASSERT_NE(pf_pass_name(pf_pass(bogus)), nullptr) << bogus;
        EXPECT_STREQ(pf_pass_name(pf_pass(bogus)), "unknown") << bogus;
    }
}

TEST(ApiStrings, VersionMatchesHeader) {
    EXPECT_EQ(pf_version(), uint32_t(PF_VERSION));
    EXPECT_EQ(uint32_t(PF_VERSION), uint32_t(PF_VERSION_MAJOR * 10000 + PF_VERSION_MINOR * 100 + PF_VERSION_PATCH));
}

// ---------------------------------------------------------------------------------------------
// pf_create

class CreateValidation : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc)));
        while (glGetError() != GL_NO_ERROR) {
        }
    }
    // pf_create must fail with `code`, log a message naming pf_create and `field`, leave *out
    // untouched and leave no GL error behind.
    void expect_create_fails(const pf_sim_desc& d, pf_result code, const char* field, const std::string& what) {
        SCOPED_TRACE(what);
        alignas(16) static unsigned char sentinel_bytes[16];  // never dereferenced
        pf_sim* const sentinel = reinterpret_cast<pf_sim*>(sentinel_bytes);
        pf_sim* s = sentinel;
        clear_log();
        const pf_result r = pf_create(&d, &s);
        EXPECT_EQ(r, code) << pf_result_string(r) << " (log: '" << last_log() << "')";
        EXPECT_TRUE(log_mentions("pf_create")) << "log: '" << last_log() << "'";
        EXPECT_TRUE(log_mentions(field)) << "log does not name '" << field << "': '" << last_log() << "'";
        EXPECT_EQ(s, sentinel) << "*out was written on failure";
        if (r == PF_OK && s != sentinel) pf_destroy(s);
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
};

