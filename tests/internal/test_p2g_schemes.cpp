// The particle-to-grid schemes (pf_p2g) against the double-precision reference: fixed point
// (rounding to 2^-20 steps, order independent), float atomics (no rounding grid, but float
// sums in whatever order the atomics land) and the sorted gather (float sums per face sample in
// a fixed order, no atomics on the sums). Prints how far apart they are and whether identical
// runs give the same bits (float atomics: on llvmpipe they may; on a GPU with thousands of
// concurrent atomics they need not — docs/accuracy.md; the gather: always, for any particle order).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <random>
#include <string>
#include <tuple>

#include "api/handle.h"
#include "common/slots.h"
#include "reference/cpu_reference.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

// One substep's P2G (on the 12 x 10 x 8 grid of 0.1 m unless told; max_speed 4 m/s): the face accumulators
// as doubles (momentum, weight per face), the cell counts and the status flags it raised.
struct SplatResult {
    std::vector<double> accum;
    std::vector<uint32_t> count;
    uint32_t flags = 0;
};

// Contributions per face: how many particle stencil nodes land on each face (design.md §3).
std::vector<int> contributions(const ref::Grid& g, const ref::Particles& particles) {
    std::vector<int> n(size_t(g.faces()), 0);
    for (const glm::dvec3& x : particles.pos) {
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
    return n;
}

// Worst ratio over the faces of |float sum - exact| to the float sums' bound (the one
// BothMatchTheReferenceWithinTheirRounding derives): per contribution, the term's own error
// (term_error per unit of `speed`, the largest |addend| of the momentum) and 2^-24 of the sum of
// |terms| per addition.
double worst_float_ratio(const std::vector<double>& got, const ref::P2GResult& exact, const std::vector<int>& n,
                         double speed, double term_error = 3.2e-6) {
    double worst = 0;
    for (size_t f = 0; f < n.size(); ++f) {
        for (int which = 0; which < 2; ++which) {
            const double ref_value = which == 0 ? exact.momentum[f] : exact.weight[f];
            const double sp = which == 0 ? speed : 1.0, mag = exact.weight[f] * sp, term = term_error * sp;
            const double tol = n[f] * (term + 6e-8 * mag) + 1e-12;
            worst = std::max(worst, std::abs(got[2 * f + size_t(which)] - ref_value) / tol);
        }
    }
    return worst;
}

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

    // One substep's P2G of the given particles with `scheme` (affine: 12 floats per particle,
    // APIC only; empty: C = 0).
    SplatResult splat_of(pf_p2g scheme, pf_transfer transfer, const std::vector<float>& pos,
                         const std::vector<float>& vel, const std::vector<float>& affine = {},
                         const ref::Grid& grid = ref::Grid{12, 10, 8, 0.1, glm::dvec3(0.0)}) {
        SplatResult out;
        pf_sim_desc d = test_desc(uint32_t(grid.nx), uint32_t(grid.ny), uint32_t(grid.nz), float(grid.dx));
        d.max_speed = 4.0f;
        d.max_particles = uint32_t(std::max<size_t>(pos.size() / 3, 1));
        d.params.p2g = scheme;
        d.params.transfer = transfer;
        SimPtr handle = create(d);
        EXPECT_TRUE(handle);
        if (!handle) return out;
        EXPECT_EQ(pf_add_particles(handle.get(), pos.data(), vel.data(), uint32_t(pos.size() / 3)), PF_OK);
        Simulation& sim = *pf::entry(handle)->impl;
        if (!affine.empty()) {
            sim.write_affine_for_test(affine);
            // The upload lands over the clear pf_add_particles ran (a shader write: the upload
            // must wait for it) and the P2G reads it.
            const std::vector<float> stored = sim.read_affine();
            EXPECT_EQ(0, std::memcmp(stored.data(), affine.data(), std::min(stored.size(), affine.size()) * 4))
                << "affine vectors read back differ from those written";
        }
        EXPECT_EQ(sim.run_substep_for_test(0.01f), PF_OK);

        EXPECT_EQ(sim.runner().binding_errors(), 0u);
        const std::vector<uint32_t> words = sim.read_grid(GridBuffer::face_accum);
        out.accum.resize(words.size());
        const double s_m = 1048576.0 / d.max_speed, s_w = 1048576.0;
        for (size_t k = 0; k < words.size(); ++k) {
            if (sim.p2g_float_sums()) {
                float f;
                std::memcpy(&f, &words[k], 4);
                out.accum[k] = f;
            } else {
                out.accum[k] = double(int32_t(words[k])) / (k % 2 == 0 ? s_m : s_w);
            }
        }
        out.count = sim.read_grid(GridBuffer::cell_count);
        out.flags = sim.read_grid(GridBuffer::status)[PF_STATUS_FLAGS];
        return out;
    }

    // Face accumulators after one substep's P2G with `scheme`, as doubles: momentum, weight.
    std::vector<double> splat(pf_p2g scheme, pf_transfer transfer = PF_TRANSFER_PIC_FLIP) {
        return splat_of(scheme, transfer, pos_, vel_).accum;
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

TEST_F(P2gSchemes, SortedGatherMatchesTheReferenceWithinItsRounding) {
    const ref::Grid g{12, 10, 8, 0.1, glm::dvec3(0.0)};
    const ref::P2GResult exact = ref::p2g(g, particles_);
    const SplatResult gather = splat_of(PF_P2G_SORTED_GATHER, PF_TRANSFER_PIC_FLIP, pos_, vel_);
    ASSERT_EQ(gather.accum.size(), size_t(2 * g.faces()));
    // The float-sum bound of BothMatchTheReferenceWithinTheirRounding: the same float terms,
    // summed one after another (a fused multiply-add only drops a rounding).
    const double worst = worst_float_ratio(gather.accum, exact, contributions(g, particles_), 2.0);
    EXPECT_LE(worst, 1.0);
    // The counts classification reads are the reference's, exactly.
    EXPECT_EQ(gather.count, exact.count);
    EXPECT_EQ(gather.flags & PF_GPU_FLAG_P2G_OVERFLOW, 0u);
    const std::vector<double> fixed = splat(PF_P2G_FIXED_POINT);
    double gap = 0;
    for (size_t k = 0; k < fixed.size(); ++k) gap = std::max(gap, std::abs(fixed[k] - gather.accum[k]));
    std::printf("sorted-gather P2G against the double reference: %.3f of its rounding bound; largest difference "
                "from fixed point %.3g\n", worst, gap);
    RecordProperty("gather_vs_bound", std::to_string(worst));
}

TEST_F(P2gSchemes, SortedGatherIsBitIdenticalRunToRunAndForAnyParticleOrder) {
    // A random permutation of the particle array (positions, velocities and affine vectors move
    // together): the sort orders each cell by the particles' bits, not their indices, so the
    // gather sums every face in the same order and the accumulators keep every bit.
    std::vector<uint32_t> order(kParticles);
    std::iota(order.begin(), order.end(), 0u);
    std::shuffle(order.begin(), order.end(), std::mt19937(11));
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> uc(-5.0f, 5.0f);
    std::vector<float> affine(size_t(kParticles) * 12, 0.0f);
    for (int i = 0; i < kParticles; ++i)
        for (int a = 0; a < 3; ++a)
            for (int c = 0; c < 3; ++c) affine[size_t(i) * 12 + size_t(a) * 4 + size_t(c)] = uc(rng);
    std::vector<float> pos(pos_.size()), vel(vel_.size()), aff(affine.size());
    for (size_t i = 0; i < order.size(); ++i) {
        std::copy_n(&pos_[order[i] * 3], 3, &pos[i * 3]);
        std::copy_n(&vel_[order[i] * 3], 3, &vel[i * 3]);
        std::copy_n(&affine[order[i] * 12], 12, &aff[i * 12]);
    }
    // Particles 0 and 1 made equal in every bit (position, velocity, affine vectors): the order
    // ties and falls back to the index; their terms are equal, so swapping them changes nothing.
    std::vector<float> pos_dup = pos, vel_dup = vel, aff_dup = aff;
    std::copy_n(&pos[0], 3, &pos_dup[3]);
    std::copy_n(&vel[0], 3, &vel_dup[3]);
    std::copy_n(&aff[0], 12, &aff_dup[12]);
    std::vector<float> pos_swapped = pos_dup, vel_swapped = vel_dup;
    std::swap_ranges(pos_swapped.begin(), pos_swapped.begin() + 3, pos_swapped.begin() + 3);
    std::swap_ranges(vel_swapped.begin(), vel_swapped.begin() + 3, vel_swapped.begin() + 3);
    for (pf_transfer transfer : {PF_TRANSFER_PIC_FLIP, PF_TRANSFER_APIC}) {
        const bool apic = transfer == PF_TRANSFER_APIC;
        const std::vector<float> no_affine;
        const SplatResult a = splat_of(PF_P2G_SORTED_GATHER, transfer, pos_, vel_, apic ? affine : no_affine),
                          b = splat_of(PF_P2G_SORTED_GATHER, transfer, pos_, vel_, apic ? affine : no_affine),
                          c = splat_of(PF_P2G_SORTED_GATHER, transfer, pos, vel, apic ? aff : no_affine);
        ASSERT_EQ(a.accum.size(), b.accum.size());
        ASSERT_EQ(a.accum.size(), c.accum.size());
        size_t run_to_run = 0, permuted = 0;
        for (size_t k = 0; k < a.accum.size(); ++k) {
            run_to_run += std::memcmp(&a.accum[k], &b.accum[k], sizeof(double)) != 0;
            permuted += std::memcmp(&a.accum[k], &c.accum[k], sizeof(double)) != 0;
        }
        EXPECT_EQ(run_to_run, 0u) << (apic ? "APIC" : "PIC/FLIP");
        EXPECT_EQ(permuted, 0u) << (apic ? "APIC" : "PIC/FLIP");
        EXPECT_EQ(a.count, c.count);
        // The duplicated pair, in either order: the same bits.
        const SplatResult d = splat_of(PF_P2G_SORTED_GATHER, transfer, pos_swapped, vel_swapped, apic ? aff_dup : no_affine),
                          e = splat_of(PF_P2G_SORTED_GATHER, transfer, pos_dup, vel_dup, apic ? aff_dup : no_affine);
        EXPECT_EQ(0, std::memcmp(d.accum.data(), e.accum.data(), d.accum.size() * sizeof(double)));
        std::printf("sorted-gather P2G (%s): %zu of %zu accumulators differ run to run, %zu under a permutation of "
                    "the particles\n", apic ? "APIC" : "PIC/FLIP", run_to_run, a.accum.size(), permuted);
    }
}

TEST_F(P2gSchemes, ApicSortedGatherWithAffineVectorsMatchesTheReference) {
    // Random affine vectors (|c| <= 5 1/s per entry): each addend is w·(v_a + c_a·(x_i - x_p)).
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> uc(-5.0f, 5.0f);
    std::vector<float> affine(size_t(kParticles) * 12, 0.0f);
    ref::Particles particles = particles_;
    for (int i = 0; i < kParticles; ++i) {
        ref::Affine c{};
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < 3; ++k) c[size_t(a)][k] = affine[size_t(i) * 12 + size_t(a) * 4 + size_t(k)] = uc(rng);
        particles.affine.push_back(c);
    }
    const ref::Grid g{12, 10, 8, 0.1, glm::dvec3(0.0)};
    const ref::P2GResult exact = ref::p2g_apic(g, particles);
    const SplatResult gather = splat_of(PF_P2G_SORTED_GATHER, PF_TRANSFER_APIC, pos_, vel_, affine),
                      floats = splat_of(PF_P2G_FLOAT_ATOMIC, PF_TRANSFER_APIC, pos_, vel_, affine);
    // |v_a + c_a·(x_i - x_p)| <= 2 + 3 · 5 · 0.1 m/s = 3.5 m/s (|x_i - x_p| <= dx per axis). The
    // affine term adds to the term's error: c·dx per grid unit (one rounding) times node offsets
    // that err like g (<= 1.6e-6 cells), three products and two sums: <= 3e-6 m/s, 0.9e-6 per
    // unit of the 3.5 m/s, on top of the weight's 3.2e-6.
    const std::vector<int> n = contributions(g, particles);
    const double worst = worst_float_ratio(gather.accum, exact, n, 3.5, 4.1e-6),
                 worst_float = worst_float_ratio(floats.accum, exact, n, 3.5, 4.1e-6);
    {  // where they differ (printed): the faces over the bound, and fixed point's distance
        const SplatResult fixed = splat_of(PF_P2G_FIXED_POINT, PF_TRANSFER_APIC, pos_, vel_, affine);
        double fixed_vs_float = 0.0;
        for (size_t k = 0; k < fixed.accum.size() && k < floats.accum.size(); ++k)
            fixed_vs_float = std::max(fixed_vs_float, std::abs(fixed.accum[k] - floats.accum[k]));
        std::printf("APIC with affine vectors: fixed point and float atomics differ by at most %.3g\n", fixed_vs_float);
    }
    EXPECT_LE(worst, 1.0);
    EXPECT_LE(worst_float, 1.0);
    std::printf("APIC with affine vectors against the double reference (1 = the bound): sorted gather %.3f, "
                "float atomics %.3f\n", worst, worst_float);
    RecordProperty("gather_apic_vs_bound", std::to_string(worst));
}

TEST_F(P2gSchemes, AHotCellOverflowsFixedPointButNotTheGather) {
    // 6,000 particles within 0.1 cells of the centre of cell (5, 4, 3), moving at ~(1.5, -1, 0.5)
    // m/s: the u samples at x = 5 and 6 (y = 4, z = 3) each get a weight of about 0.5 · 0.95² from
    // every particle, some 2,700 in all, beyond the 2,047 full weights a 31-bit fixed-point sum
    // holds at the initial range.
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> jitter(-0.01f, 0.01f), dv(-0.2f, 0.2f);
    std::vector<float> pos, vel;
    ref::Particles particles;
    for (int i = 0; i < 6000; ++i) {
        const float p[3] = {0.55f + jitter(rng), 0.45f + jitter(rng), 0.35f + jitter(rng)};
        const float v[3] = {1.5f + dv(rng), -1.0f + dv(rng), 0.5f + dv(rng)};
        for (int a = 0; a < 3; ++a) pos.push_back(p[a]), vel.push_back(v[a]);
        particles.pos.emplace_back(p[0], p[1], p[2]);
        particles.vel.emplace_back(v[0], v[1], v[2]);
    }
    const ref::Grid g{12, 10, 8, 0.1, glm::dvec3(0.0)};
    const ref::P2GResult exact = ref::p2g(g, particles);
    const std::vector<int> n = contributions(g, particles);
    const SplatResult fixed = splat_of(PF_P2G_FIXED_POINT, PF_TRANSFER_PIC_FLIP, pos, vel),
                      gather = splat_of(PF_P2G_SORTED_GATHER, PF_TRANSFER_PIC_FLIP, pos, vel),
                      floats = splat_of(PF_P2G_FLOAT_ATOMIC, PF_TRANSFER_PIC_FLIP, pos, vel);
    EXPECT_EQ(exact.count[size_t(g.cell_index(5, 4, 3))], 6000u);
    EXPECT_NE(fixed.flags & PF_GPU_FLAG_P2G_OVERFLOW, 0u) << "the fixed-point sums were expected to overflow";
    EXPECT_EQ(gather.flags & PF_GPU_FLAG_P2G_OVERFLOW, 0u);
    const double worst = worst_float_ratio(gather.accum, exact, n, 1.7),
                 worst_float = worst_float_ratio(floats.accum, exact, n, 1.7);
    EXPECT_LE(worst, 1.0);
    EXPECT_LE(worst_float, 1.0);
    EXPECT_EQ(gather.count, exact.count);
    // The hottest u sample's velocity (momentum / weight) by each scheme.
    const size_t u = size_t(g.face_index(0, 5, 4, 3));
    const double exact_u = exact.momentum[u] / exact.weight[u];
    std::printf("hot cell (6,000 particles): u at its face exact %.6f m/s, fixed point %.6f (overflow flag %s), "
                "sorted gather %.6f (%.3f of its bound), float atomics %.6f (%.3f)\n",
                exact_u, fixed.accum[2 * u] / fixed.accum[2 * u + 1], (fixed.flags & PF_GPU_FLAG_P2G_OVERFLOW) ? "set" : "clear",
                gather.accum[2 * u] / gather.accum[2 * u + 1], worst, floats.accum[2 * u] / floats.accum[2 * u + 1],
                worst_float);
    RecordProperty("gather_hot_cell_vs_bound", std::to_string(worst));
}

// A small dam break (a 0.6 x 0.8 x 0.4 m column in a 2.4 x 1.2 x 0.4 m box, 8 particles per
// cell, 20 frames of 1/60 s: the front is still running) with each scheme. The float schemes round differently from fixed
// point, and the splash amplifies rounding-level differences, so particles do not match one by
// one; the liquid as a whole must: centre of mass within a quarter cell (2.5 cm), the front (the
// 99th percentile of x) within one cell, mean kinetic energy within 10%.
struct DamBreak {
    double com[3] = {0, 0, 0}, front = 0, kinetic = 0;
    ParticleState state;
};

TEST_F(P2gSchemes, DamBreakIsPhysicallyTheSameWithEveryScheme) {
    auto run = [&](pf_p2g scheme) {
        DamBreak out;
        pf_sim_desc d = test_desc(24, 12, 4, 0.1f);
        d.max_particles = 1u << 13;
        d.params.p2g = scheme;
        SimPtr sim = create(d);
        EXPECT_TRUE(sim);
        if (!sim) return out;
        const float lo[3] = {0, 0, 0}, hi[3] = {0.6f, 0.8f, 0.4f};
        EXPECT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
        for (int f = 0; f < 20; ++f) EXPECT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        out.state = read_all(sim.get());
        const size_t np = out.state.count();
        std::vector<double> xs(np);
        for (size_t i = 0; i < np; ++i) {
            double v2 = 0;
            for (int a = 0; a < 3; ++a) {
                out.com[a] += out.state.pos[i * 3 + size_t(a)] / double(np);
                v2 += double(out.state.vel[i * 3 + size_t(a)]) * out.state.vel[i * 3 + size_t(a)];
            }
            out.kinetic += 0.5 * v2 / double(np);
            xs[i] = out.state.pos[i * 3];
        }
        std::sort(xs.begin(), xs.end());
        out.front = np ? xs[np * 99 / 100] : 0.0;
        EXPECT_EQ(pf::entry(sim)->impl->runner().binding_errors(), 0u);
        return out;
    };
    const DamBreak fixed = run(PF_P2G_FIXED_POINT), floats = run(PF_P2G_FLOAT_ATOMIC),
                   gather = run(PF_P2G_SORTED_GATHER), gather_again = run(PF_P2G_SORTED_GATHER);
    ASSERT_EQ(fixed.state.count(), 1536u);
    EXPECT_GT(fixed.front, 1.0);  // the front has moved...
    EXPECT_LT(fixed.front, 2.3);  // ...and not yet reached the far wall
    ASSERT_EQ(gather.state.count(), fixed.state.count());
    for (const DamBreak* other : {&floats, &gather}) {
        const char* name = other == &floats ? "float atomics" : "sorted gather";
        double com_gap = 0;
        for (int a = 0; a < 3; ++a) com_gap = std::max(com_gap, std::abs(other->com[a] - fixed.com[a]));
        const double front_gap = std::abs(other->front - fixed.front);
        const double kinetic_gap = std::abs(other->kinetic - fixed.kinetic) / fixed.kinetic;
        EXPECT_LE(com_gap, 0.025) << name;
        EXPECT_LE(front_gap, 0.1) << name;
        EXPECT_LE(kinetic_gap, 0.10) << name;
        std::printf("dam break, %s against fixed point: centre of mass %.2e m apart, front %.2e m, mean kinetic "
                    "energy %.3f%% (fixed point: centre of mass (%.4f, %.4f, %.4f), front %.3f m, %.4f J/kg)\n",
                    name, com_gap, front_gap, 100.0 * kinetic_gap, fixed.com[0], fixed.com[1], fixed.com[2],
                    fixed.front, fixed.kinetic);
    }
    // The whole step is deterministic with the gather, as with fixed point: every particle's bits.
    EXPECT_EQ(gather.state.pos, gather_again.state.pos);
    EXPECT_EQ(gather.state.vel, gather_again.state.vel);
}

// The gather's passes are listed under PF_PASS_P2G ("p2g_sort": count, prefix sum, scatter and
// order; "p2g_gather") once the scheme is first selected, and not before (nothing is built or
// allocated for a scheme never used).
TEST_F(P2gSchemes, SortedGatherPassesAreListedUnderP2gOnceSelected) {
    pf_sim_desc d = test_desc(12, 10, 8, 0.1f);
    d.params.p2g = PF_P2G_FIXED_POINT;  // no sort built yet (the tiled default shares its prefix sum)
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.4f, 0.5f, 0.4f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    auto entries = [&] {
        std::vector<pf_pass_stats> out;
        uint32_t count = 0;
        EXPECT_EQ(pf_get_pass_count(sim.get(), &count), PF_OK);
        for (uint32_t i = 0; i < count; ++i) {
            pf_pass_stats st{};
            EXPECT_EQ(pf_get_pass_stats(sim.get(), i, &st), PF_OK);
            out.push_back(st);
        }
        return out;
    };
    auto find = [](const std::vector<pf_pass_stats>& list, const std::string& name) -> const pf_pass_stats* {
        for (const pf_pass_stats& st : list)
            if (name == st.name) return &st;
        return nullptr;
    };
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    std::vector<pf_pass_stats> list = entries();
    EXPECT_EQ(find(list, "p2g_sort"), nullptr);
    EXPECT_EQ(find(list, "p2g_gather"), nullptr);
    const uint32_t programs_before = pf::entry(sim)->impl->runner().programs_built();

    pf_sim_params p = sized_params();
    ASSERT_EQ(pf_get_params(sim.get(), &p), PF_OK);
    p.p2g = PF_P2G_SORTED_GATHER;
    ASSERT_EQ(pf_set_params(sim.get(), &p), PF_OK) << last_log();
    // Count, two prefix-sum kernels, scatter, order, gather (PIC/FLIP's), and grid_forces' float
    // permutation.
    EXPECT_EQ(pf::entry(sim)->impl->runner().programs_built(), programs_before + 7);
    pf_stats stats{};
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    ASSERT_EQ(pf_get_stats(sim.get(), &stats), PF_OK);
    list = entries();
    const pf_pass_stats *sort = find(list, "p2g_sort"), *gather = find(list, "p2g_gather"), *atomics = find(list, "p2g");
    ASSERT_NE(sort, nullptr);
    ASSERT_NE(gather, nullptr);
    ASSERT_NE(atomics, nullptr);
    EXPECT_EQ(sort->group, PF_PASS_P2G);
    EXPECT_EQ(gather->group, PF_PASS_P2G);
    // Per substep: count, the prefix sum (7,681 half-cell counts: 8 blocks of 1,024, so two levels up and one down),
    // scatter and order, 6 dispatches; then one gather.
    EXPECT_EQ(sort->dispatches, 6u * stats.substeps);
    EXPECT_EQ(gather->dispatches, stats.substeps);
    EXPECT_EQ(atomics->dispatches, 0u);
    EXPECT_EQ(pf::entry(sim)->impl->runner().binding_errors(), 0u);
}

// A grid of 147,456 cells: the prefix sum over the 1,179,649 half-cell counts takes three levels
// (1,153 blocks of 1,024, then 2 blocks, then one), and every particle must still land in its
// segment.
TEST_F(P2gSchemes, SortedGatherOnAGridWhosePrefixSumTakesThreeLevels) {
    const ref::Grid g{64, 48, 48, 0.01875, glm::dvec3(0.0)};
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f), uv(-2.0f, 2.0f);
    std::vector<float> pos, vel;
    ref::Particles particles;
    for (int i = 0; i < 20000; ++i) {
        const float p[3] = {1.2f * u01(rng), 0.9f * u01(rng), 0.9f * u01(rng)};
        const float v[3] = {uv(rng), uv(rng), uv(rng)};
        for (int a = 0; a < 3; ++a) pos.push_back(p[a]), vel.push_back(v[a]);
        particles.pos.emplace_back(p[0], p[1], p[2]);
        particles.vel.emplace_back(v[0], v[1], v[2]);
    }
    const ref::P2GResult exact = ref::p2g(g, particles);
    const SplatResult gather = splat_of(PF_P2G_SORTED_GATHER, PF_TRANSFER_PIC_FLIP, pos, vel, {}, g);
    ASSERT_EQ(gather.accum.size(), size_t(2 * g.faces()));
    EXPECT_EQ(gather.count, exact.count);
    // g <= 64 here: the grid coordinate errs by up to 64/12 times the 12-cell case's 1e-6, and so
    // does each weight factor (a term by <= 64/12 x 3.2e-6 per m/s).
    const double worst = worst_float_ratio(gather.accum, exact, contributions(g, particles), 2.0, 64.0 / 12.0 * 3.2e-6);
    EXPECT_LE(worst, 1.0);
    std::printf("sorted-gather P2G on 64 x 48 x 48 cells (three prefix-sum levels): %.3f of its rounding bound\n", worst);
}

// Particles exactly on every half-cell boundary of a grid of 1/8 m cells (positions k/16 m, exact
// in float: g = k/2), walls included (g = 0 and g = n): the stencil clamps, the cell and half-cell
// clamps and the gather's half-cell ranges all meet their edge cases here.
TEST_F(P2gSchemes, SortedGatherWithParticlesOnEveryHalfCellBoundaryAndTheWalls) {
    const ref::Grid g{12, 10, 8, 0.125, glm::dvec3(0.0)};
    std::mt19937 rng(19);
    std::uniform_real_distribution<float> uv(-2.0f, 2.0f);
    std::vector<float> pos, vel;
    ref::Particles particles;
    for (int k = 0; k <= 2 * g.nz; ++k)
        for (int j = 0; j <= 2 * g.ny; ++j)
            for (int i = 0; i <= 2 * g.nx; ++i) {
                const float p[3] = {float(i) / 16.0f, float(j) / 16.0f, float(k) / 16.0f};
                const float v[3] = {uv(rng), uv(rng), uv(rng)};
                for (int a = 0; a < 3; ++a) pos.push_back(p[a]), vel.push_back(v[a]);
                particles.pos.emplace_back(p[0], p[1], p[2]);
                particles.vel.emplace_back(v[0], v[1], v[2]);
            }
    const ref::P2GResult exact = ref::p2g(g, particles);
    const SplatResult gather = splat_of(PF_P2G_SORTED_GATHER, PF_TRANSFER_PIC_FLIP, pos, vel, {}, g),
                      fixed = splat_of(PF_P2G_FIXED_POINT, PF_TRANSFER_PIC_FLIP, pos, vel, {}, g);
    ASSERT_EQ(gather.accum.size(), size_t(2 * g.faces()));
    EXPECT_EQ(gather.count, exact.count);
    EXPECT_EQ(fixed.count, exact.count);
    // Exact positions and dx: g and the weights (products of 0, 1/2, 1) are exact, so the only
    // error left is the float sums'; the bound is the usual one with the term error dropped.
    const double worst = worst_float_ratio(gather.accum, exact, contributions(g, particles), 2.0, 0.0);
    EXPECT_LE(worst, 1.0);
    std::printf("sorted-gather P2G, %zu particles on half-cell boundaries and walls: %.3f of the float-sum bound\n",
                particles.pos.size(), worst);
}

// The gather's largest buffer, the half-cell starts, takes 32 bytes per cell where pf_create's
// largest takes about 24 (the face accumulators): a grid between the two against this GL's
// GL_MAX_SHADER_STORAGE_BLOCK_SIZE is created, but refused the gather with PF_ERROR_CAPACITY —
// by pf_set_params, which then changes nothing, and by pf_create.
TEST_F(P2gSchemes, SortedGatherRefusesAGridBeyondTheStorageBlockLimit) {
    SimPtr probe = create(test_desc(4, 4, 4));
    ASSERT_TRUE(probe);
    GLint64 max_block = 0;
    pf::entry(probe)->impl->api().GetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
    probe.reset();
    // 1024 x 64 x nz cells with 28 bytes per cell at the limit.
    const uint64_t nz = uint64_t(max_block) / 28u / (1024u * 64u);
    if (nz < 2 || nz > 1024 || 1024u * 64u * nz > (1u << 26))
        GTEST_SKIP() << "GL_MAX_SHADER_STORAGE_BLOCK_SIZE " << max_block << " needs a grid pflip does not take";
    pf_sim_desc d = test_desc(1024, 64, uint32_t(nz), 0.01f);
    d.max_particles = 16;
    const uint64_t cells = 1024u * 64u * nz;
    const uint64_t faces = 1025u * 64u * nz + 1024u * 65u * nz + 1024u * 64u * (nz + 1);
    ASSERT_LE(faces * 8, uint64_t(max_block));
    ASSERT_GT(cells * 32, uint64_t(max_block));
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    pf_sim_params p = sized_params();
    ASSERT_EQ(pf_get_params(sim.get(), &p), PF_OK);
    p.p2g = PF_P2G_SORTED_GATHER;
    EXPECT_EQ(pf_set_params(sim.get(), &p), PF_ERROR_CAPACITY);
    EXPECT_NE(std::string(last_log()).find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE"), std::string::npos) << last_log();
    pf_sim_params now = sized_params();
    ASSERT_EQ(pf_get_params(sim.get(), &now), PF_OK);
    EXPECT_EQ(now.p2g, d.params.p2g) << "the refused scheme was kept";
    sim.reset();
    d.params.p2g = PF_P2G_SORTED_GATHER;
    pf_sim* raw = nullptr;
    EXPECT_EQ(pf_create(&d, &raw), PF_ERROR_CAPACITY);
    EXPECT_EQ(raw, nullptr);
}

// The tiled scheme adds p2g.comp's rounded terms in another grouping (per tile in shared memory,
// then once per window sample): integer sums wrap alike in any grouping, so its accumulators and
// counts are fixed point's, bit for bit. On the 12 x 10 x 8 grid the tiles of 4^3 cells leave
// partial tiles along y; particles also lie on half-cell boundaries and on the walls, with
// PIC/FLIP and APIC (affine vectors set).
TEST_F(P2gSchemes, TiledIsFixedPointBitForBit) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> uv(-2.0f, 2.0f), uc(-1.0f, 1.0f);
    std::vector<float> pos = pos_, vel = vel_;
    const ref::Grid g{12, 10, 8, 0.125, glm::dvec3(0.0)};  // exact half-cell positions i / 16
    for (int k = 0; k <= 2 * g.nz; ++k)
        for (int j = 0; j <= 2 * g.ny; ++j)
            for (int i = 0; i <= 2 * g.nx; i += 3) {
                const float p[3] = {float(i) / 16.0f, float(j) / 16.0f, float(k) / 16.0f};
                for (int a = 0; a < 3; ++a) pos.push_back(p[a]), vel.push_back(uv(rng));
            }
    std::vector<float> affine(pos.size() / 3 * 12);
    for (float& c : affine) c = uc(rng);
    for (pf_transfer transfer : {PF_TRANSFER_PIC_FLIP, PF_TRANSFER_APIC}) {
        const std::vector<float> no_affine, &a = transfer == PF_TRANSFER_APIC ? affine : no_affine;
        const SplatResult fixed = splat_of(PF_P2G_FIXED_POINT, transfer, pos, vel, a, g),
                          tiled = splat_of(PF_P2G_TILED, transfer, pos, vel, a, g);
        ASSERT_EQ(tiled.accum.size(), fixed.accum.size());
        size_t differ = 0;
        for (size_t k = 0; k < fixed.accum.size(); ++k) {
            if (fixed.accum[k] != tiled.accum[k] && differ < 8)
                std::printf("word %zu: fixed %.9g tiled %.9g\n", k, fixed.accum[k], tiled.accum[k]);
            differ += fixed.accum[k] != tiled.accum[k];
        }
        EXPECT_EQ(differ, 0u) << "accumulator words that differ from fixed point, transfer " << int(transfer);
        EXPECT_EQ(tiled.count, fixed.count);
        EXPECT_EQ(tiled.flags & PF_GPU_FLAG_P2G_OVERFLOW, 0u);
    }
}

// The tiled splat writes every cell's count (nothing clears them between steps): cells whose
// tile the particles have left count 0 again, also where no particle is left in the tile.
TEST_F(P2gSchemes, TiledCountsReturnToZeroWhereParticlesLeft) {
    pf_sim_desc d = test_desc(12, 10, 8, 0.1f);
    d.max_particles = 4096;
    d.params.p2g = PF_P2G_TILED;
    SimPtr handle = create(d);
    ASSERT_TRUE(handle);
    Simulation& sim = *pf::entry(handle)->impl;
    auto block = [&](float x0) {
        std::vector<float> pos, vel;
        for (int k = 0; k < 8; ++k)
            for (int j = 0; j < 8; ++j)
                for (int i = 0; i < 8; ++i) {
                    const float p[3] = {x0 + 0.025f + 0.05f * float(i), 0.025f + 0.05f * float(j), 0.025f + 0.05f * float(k)};
                    for (int a = 0; a < 3; ++a) pos.push_back(p[a]), vel.push_back(0.0f);
                }
        EXPECT_EQ(pf_add_particles(handle.get(), pos.data(), vel.data(), uint32_t(pos.size() / 3)), PF_OK);
    };
    auto count_in_x = [&](float lo, float hi) {
        const std::vector<uint32_t> count = sim.read_grid(GridBuffer::cell_count);
        uint64_t n = 0;
        for (int k = 0; k < 8; ++k)
            for (int j = 0; j < 10; ++j)
                for (int i = 0; i < 12; ++i)
                    if ((float(i) + 0.5f) * 0.1f > lo && (float(i) + 0.5f) * 0.1f < hi) n += count[size_t(i + 12 * (j + 10 * k))];
        return n;
    };
    block(0.0f);  // cells 0-3 along x: the first tile column
    ASSERT_EQ(sim.run_substep_for_test(0.001f), PF_OK);
    EXPECT_EQ(count_in_x(0.0f, 0.4f), 512u);
    ASSERT_EQ(pf_clear_particles(handle.get()), PF_OK);
    block(0.8f);  // cells 8-11: the third tile column; the first holds no particle now
    ASSERT_EQ(sim.run_substep_for_test(0.001f), PF_OK);
    EXPECT_EQ(count_in_x(0.0f, 0.4f), 0u) << "cells the particles left keep their old counts";
    EXPECT_EQ(count_in_x(0.8f, 1.2f), 512u);
}

// G2P in the tiled P2G's order (large grids only, so forced here by the test hook) computes every
// particle as in slot order: 30 frames of a dam break, PIC/FLIP and pure PIC, bit-identical with
// and without it, and the ordered kernel is the one that ran (counted per kernel).
// RK2_OFFSET's trace walks the same order (its reads of the faces are gathers too).
TEST_F(P2gSchemes, OrderedG2pGivesBitIdenticalParticles) {
    const std::pair<float, pf_advection> cases[] = {
        {0.95f, PF_ADVECTION_EULER}, {0.0f, PF_ADVECTION_EULER}, {0.95f, PF_ADVECTION_RK2_OFFSET}};
    for (const auto& [flip_ratio, advection] : cases) {
        ParticleState result[2];
        for (int ordered = 0; ordered < 2; ++ordered) {
            pf_sim_desc d = test_desc(32, 16, 16, 1.0f / 16.0f);
            ASSERT_EQ(pf_quality_params(PF_QUALITY_BALANCED, &d.params), PF_OK);
            d.params.flip_ratio = flip_ratio;
            d.params.advection = advection;
            SimPtr handle = create(d);
            ASSERT_TRUE(handle);
            Simulation& sim = *pf::entry(handle)->impl;
            ASSERT_EQ(sim.set_ordered_g2p_face_bytes_for_test(ordered ? 0 : UINT64_MAX), PF_OK);
            ASSERT_EQ(pf_set_gpu_timing(handle.get(), PF_GPU_TIMING_KERNELS), PF_OK);
            const float lo[3] = {0, 0, 0}, hi[3] = {0.75f, 0.75f, 1.0f};
            ASSERT_EQ(pf_fill_box(handle.get(), lo, hi, nullptr), PF_OK);
            for (int f = 0; f < 30; ++f) ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
            result[ordered] = read_all(handle.get());
            EXPECT_EQ(sim.runner().binding_errors(), 0u) << last_log();  // the order bound where it is read
            std::vector<std::string> kernels{flip_ratio > 0.0f ? "g2p:g2p_flip_ordered" : "g2p:g2p_pic_ordered",
                                             "volume_correction_move:volume_correction_move_ordered"};
            if (advection == PF_ADVECTION_RK2_OFFSET) kernels.push_back("advect:advect_rk2_offset_ordered");
            for (const std::string& kernel : kernels) {
                uint32_t dispatches = 0;
                for (const pf_pass_stats& st : pass_list(handle.get()))
                    if (kernel == st.name) dispatches += st.dispatches;
                if (ordered)
                    EXPECT_GT(dispatches, 0u) << kernel << " never ran";
                else
                    EXPECT_EQ(dispatches, 0u) << kernel << " ran below its threshold";
            }
        }
        ASSERT_EQ(result[0].count(), result[1].count());
        EXPECT_TRUE(result[0].pos == result[1].pos) << "positions differ, flip ratio " << flip_ratio << ", advection " << advection;
        EXPECT_TRUE(result[0].vel == result[1].vel) << "velocities differ, flip ratio " << flip_ratio << ", advection " << advection;
    }
}

// The hot cell of AHotCellOverflowsFixedPointButNotTheGather overflows the tiled scheme's sums
// too (in shared memory first), and the flag says so.
TEST_F(P2gSchemes, TiledFlagsTheOverflowFixedPointFlags) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> jitter(-0.01f, 0.01f), dv(-0.2f, 0.2f);
    std::vector<float> pos, vel;
    for (int i = 0; i < 6000; ++i) {
        const float p[3] = {0.55f + jitter(rng), 0.45f + jitter(rng), 0.35f + jitter(rng)};
        const float v[3] = {1.5f + dv(rng), -1.0f + dv(rng), 0.5f + dv(rng)};
        for (int a = 0; a < 3; ++a) pos.push_back(p[a]), vel.push_back(v[a]);
    }
    const SplatResult fixed = splat_of(PF_P2G_FIXED_POINT, PF_TRANSFER_PIC_FLIP, pos, vel),
                      tiled = splat_of(PF_P2G_TILED, PF_TRANSFER_PIC_FLIP, pos, vel);
    EXPECT_NE(fixed.flags & PF_GPU_FLAG_P2G_OVERFLOW, 0u);
    EXPECT_NE(tiled.flags & PF_GPU_FLAG_P2G_OVERFLOW, 0u);
    EXPECT_EQ(tiled.count, fixed.count);
}

// Every scheme below PF_P2G_COUNT, with the programs of both transfers (C = 0 here, so APIC's
// terms are FLIP's): counts exactly the reference's, sums within the float-sum bound widened by
// half a fixed-point step per contribution (so that one bound serves every scheme; the tests
// above hold each to its own, tighter one), no overflow. A scheme added to the registry
// (src/sim/transfer/registry.cpp) is held to it at once.
class EveryP2gScheme : public P2gSchemes, public ::testing::WithParamInterface<std::tuple<int, int>> {};

TEST_P(EveryP2gScheme, MatchesTheReference) {
    const pf_p2g scheme = pf_p2g(std::get<0>(GetParam()));
    const pf_transfer transfer = pf_transfer(std::get<1>(GetParam()));
    const ref::Grid g{12, 10, 8, 0.1, glm::dvec3(0.0)};
    const ref::P2GResult exact = ref::p2g(g, particles_);
    const SplatResult got = splat_of(scheme, transfer, pos_, vel_);
    ASSERT_EQ(got.accum.size(), size_t(2 * g.faces()));
    const std::vector<int> n = contributions(g, particles_);
    double worst = 0;
    for (int f = 0; f < g.faces(); ++f) {
        for (int which = 0; which < 2; ++which) {
            const double ref_value = which == 0 ? exact.momentum[size_t(f)] : exact.weight[size_t(f)];
            const double speed = which == 0 ? 2.0 : 1.0, mag = exact.weight[size_t(f)] * speed;
            const double half_step = 0.5 * (which == 0 ? 4.0 : 1.0) / 1048576.0;
            const double tol = n[size_t(f)] * (3.2e-6 * speed + 6e-8 * mag + half_step) + 1e-12;
            worst = std::max(worst, std::abs(got.accum[size_t(2 * f + which)] - ref_value) / tol);
        }
    }
    EXPECT_LE(worst, 1.0);
    EXPECT_EQ(got.count, exact.count);
    EXPECT_EQ(got.flags & PF_GPU_FLAG_P2G_OVERFLOW, 0u);
    RecordProperty("vs_bound", std::to_string(worst));
}

std::string every_p2g_name(const ::testing::TestParamInfo<std::tuple<int, int>>& info) {
    static const char* const names[] = {"fixed_point", "float_atomic", "sorted_gather", "tiled"};
    static_assert(sizeof(names) / sizeof(names[0]) == PF_P2G_COUNT, "a name per scheme");
    return std::string(names[std::get<0>(info.param)]) + (std::get<1>(info.param) == PF_TRANSFER_APIC ? "_apic" : "_flip");
}

INSTANTIATE_TEST_SUITE_P(AllP2g, EveryP2gScheme,
                         ::testing::Combine(::testing::Range(0, int(PF_P2G_COUNT)),
                                            ::testing::Values(int(PF_TRANSFER_PIC_FLIP), int(PF_TRANSFER_APIC))),
                         every_p2g_name);

}  // namespace
}  // namespace pf::test
