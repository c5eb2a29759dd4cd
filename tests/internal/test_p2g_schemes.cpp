// The particle-to-grid schemes (pf_p2g) against the double-precision reference: fixed point
// (rounding to 2^-20 steps, order independent) and float atomics (no rounding grid, but float
// sums in whatever order the atomics land). Prints how far apart they are and whether two
// identical runs of the float scheme give the same bits (on llvmpipe they may; on a GPU with
// thousands of concurrent atomics they need not — docs/accuracy.md).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

#include "api/handle.h"
#include "reference/cpu_reference.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class P2gSchemes : public GpuTest {
protected:
    static constexpr int kParticles = 3000;

    void SetUp() override {
        GpuTest::SetUp();
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> u01(0.0f, 1.0f), uv(-2.0f, 2.0f);
        for (int i = 0; i < kParticles; ++i) {
            const float p[3] = {1.2f * u01(rng), 0.6f * u01(rng), 0.8f * u01(rng)};
            const float v[3] = {uv(rng), uv(rng), uv(rng)};
            for (int a = 0; a < 3; ++a) pos_.push_back(p[a]), vel_.push_back(v[a]);
            particles_.pos.emplace_back(p[0], p[1], p[2]);
            particles_.vel.emplace_back(v[0], v[1], v[2]);
        }
    }

    // Face accumulators after one substep's P2G with `scheme`, as doubles: momentum, weight.
    std::vector<double> splat(pf_p2g scheme, pf_transfer transfer = PF_TRANSFER_PIC_FLIP) {
        pf_sim_desc d = test_desc(12, 10, 8, 0.1f);
        d.max_speed = 4.0f;
        d.params.p2g = scheme;
        d.params.transfer = transfer;
        SimPtr handle = create(d);
        EXPECT_TRUE(handle);
        if (!handle) return {};
        EXPECT_EQ(pf_add_particles(handle.get(), pos_.data(), vel_.data(), kParticles), PF_OK);
        Simulation& sim = *pf::entry(handle)->impl;
        EXPECT_EQ(sim.run_substep_for_test(0.01f), PF_OK);
        EXPECT_EQ(sim.runner().binding_errors(), 0u);
        const std::vector<uint32_t> words = sim.read_grid(GridBuffer::face_accum);
        std::vector<double> out(words.size());
        const double s_m = 1048576.0 / d.max_speed, s_w = 1048576.0;
        for (size_t k = 0; k < words.size(); ++k) {
            if (scheme == PF_P2G_FLOAT_ATOMIC) {
                float f;
                std::memcpy(&f, &words[k], 4);
                out[k] = f;
            } else {
                out[k] = double(int32_t(words[k])) / (k % 2 == 0 ? s_m : s_w);
            }
        }
        return out;
    }

    std::vector<float> pos_, vel_;
    ref::Particles particles_;
};

TEST_F(P2gSchemes, BothMatchTheReferenceWithinTheirRounding) {
    const ref::Grid g{12, 10, 8, 0.1, glm::dvec3(0.0)};
    const ref::P2GResult exact = ref::p2g(g, particles_);
    const std::vector<double> fixed = splat(PF_P2G_FIXED_POINT), floats = splat(PF_P2G_FLOAT_ATOMIC);
    ASSERT_EQ(fixed.size(), size_t(2 * g.faces()));
    ASSERT_EQ(floats.size(), fixed.size());
    // Bounds per face, per contribution: both schemes compute each term w * v in float from a
    // float grid coordinate g = x / dx (g <= 12 here: error <= 1e-6), so each of the weight's
    // three factors errs by ~1e-6 and a term by <= 3.2e-6 * |v| (|v_a| <= 2 here). Fixed point
    // then rounds the term by at most half a step (2^-20 / S); a float sum errs by at most
    // 2^-24 * sum|terms| per addition (sum|terms| <= the weight sum times 2 for momentum).
    std::vector<int> n(size_t(g.faces()), 0);
    for (const glm::dvec3& x : particles_.pos) {
        const glm::dvec3 gc = g.to_grid(x);
        for (int c = 0; c < 3; ++c) {
            const glm::dvec3 dims = glm::dvec3(g.face_dims(c));
            const glm::dvec3 s = glm::clamp(gc - ref::Grid::face_offset_g(c), glm::dvec3(0.0), dims - 1.0);
            const glm::ivec3 b = glm::ivec3(glm::min(glm::floor(s), dims - 2.0));
            for (int k = 0; k < 2; ++k)
                for (int j = 0; j < 2; ++j)
                    for (int i = 0; i < 2; ++i) ++n[size_t(g.face_index(c, b.x + i, b.y + j, b.z + k))];
        }
    }
    double worst_fixed = 0, worst_float = 0, max_gap = 0;
    for (int f = 0; f < g.faces(); ++f) {
        for (int which = 0; which < 2; ++which) {
            const double ref_value = which == 0 ? exact.momentum[f] : exact.weight[f];
            const double scale = which == 0 ? 4.0 / 1048576.0 : 1.0 / 1048576.0;  // one fixed-point step
            const double speed = which == 0 ? 2.0 : 1.0, mag = exact.weight[f] * speed, term = 3.2e-6 * speed;
            const double tol_fixed = n[f] * (term + 0.5 * scale) + 1e-12;
            const double tol_float = n[f] * (term + 6e-8 * mag) + 1e-12;
            const size_t k = size_t(2 * f + which);
            worst_fixed = std::max(worst_fixed, std::abs(fixed[k] - ref_value) / tol_fixed);
            worst_float = std::max(worst_float, std::abs(floats[k] - ref_value) / tol_float);
            max_gap = std::max(max_gap, std::abs(floats[k] - fixed[k]));
        }
    }
    EXPECT_LE(worst_fixed, 1.0);
    EXPECT_LE(worst_float, 1.0);
    std::printf("P2G against the double reference (1 = the rounding bound): fixed point %.3f, float atomics %.3f; "
                "largest difference between the schemes %.3g\n",
                worst_fixed, worst_float, max_gap);
    RecordProperty("fixed_vs_bound", std::to_string(worst_fixed));
    RecordProperty("float_vs_bound", std::to_string(worst_float));
}

TEST_F(P2gSchemes, FixedPointIsBitIdenticalRunToRunAndFloatIsReported) {
    const std::vector<double> a = splat(PF_P2G_FIXED_POINT), b = splat(PF_P2G_FIXED_POINT);
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(double)));
    size_t differ = 0;
    const std::vector<double> fa = splat(PF_P2G_FLOAT_ATOMIC), fb = splat(PF_P2G_FLOAT_ATOMIC);
    ASSERT_EQ(fa.size(), fb.size());
    for (size_t k = 0; k < fa.size(); ++k) differ += fa[k] != fb[k];
    // Which path the float scheme took here: native atomics if the GL has the extension.
    SimPtr probe = create(test_desc(4, 4, 4));
    ASSERT_TRUE(probe);
    const gl::Api& gl = pf::entry(probe)->impl->api();
    GLint count = 0;
    gl.GetIntegerv(GL_NUM_EXTENSIONS, &count);
    bool native = false;
    for (GLint i = 0; i < count; ++i)
        native = native || std::strcmp(reinterpret_cast<const char*>(gl.GetStringi(GL_EXTENSIONS, GLuint(i))),
                                       "GL_NV_shader_atomic_float") == 0;
    std::printf("float-atomic P2G (%s): %zu of %zu accumulators differ between two identical runs\n",
                native ? "GL_NV_shader_atomic_float" : "compare-and-swap", differ, fa.size());
    RecordProperty("float_words_differing", int(differ));
}

TEST_F(P2gSchemes, ApicFloatMatchesApicFixedPoint) {
    // APIC's affine term through the float path: both schemes splat the same sums.
    const std::vector<double> fixed = splat(PF_P2G_FIXED_POINT, PF_TRANSFER_APIC),
                              floats = splat(PF_P2G_FLOAT_ATOMIC, PF_TRANSFER_APIC);
    ASSERT_EQ(fixed.size(), floats.size());
    double worst = 0;
    for (size_t k = 0; k < fixed.size(); ++k) worst = std::max(worst, std::abs(fixed[k] - floats[k]));
    // New particles have C = 0, so this is plain P2G through the APIC kernels: within the
    // fixed-point rounding of ~40 contributions per face.
    EXPECT_LT(worst, 1e-3);
}

}  // namespace
}  // namespace pf::test
