// The viscosity solve (PF_FEATURE_VISCOSITY) against its definition, in double precision: on
// random grids of liquid, air and solid cells with random face velocities u*, the GPU's result u
// must minimise the energy docs/design.md §9.8 defines,
//   E(u) = 1/2 sum_f m_f (u_f - u*_f)^2 + c/2 (sum_cells w e_aa^2 + sum_edges 2 w e_ab^2),
// written out here from that text (weights from the cell kinds, strains from the face values,
// ghost faces beyond the walls at 0) rather than from the kernels. E is quadratic, so each
// partial derivative is (E(u + e_k) - E(u - e_k)) / 2 exactly; at the minimum every one over
// the faces solved for vanishes. The faces not solved for keep their values bit for bit.
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "api/handle.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

constexpr int kAir = PF_CELL_AIR, kFluid = PF_CELL_FLUID, kSolid = PF_CELL_SOLID;

struct Grid {
    int n[3];
    std::vector<int> kind;  // per cell

    int cell(int i, int j, int k) const {
        if (i < 0 || j < 0 || k < 0 || i >= n[0] || j >= n[1] || k >= n[2]) return kSolid;  // the walls
        return kind[size_t(i + n[0] * (j + n[1] * k))];
    }
    int cell(const int c[3]) const { return cell(c[0], c[1], c[2]); }
    // Faces of axis a: n + e_a samples along a; offsets into the concatenated u, v, w lattices.
    size_t face_count(int a) const {
        size_t s = 1;
        for (int b = 0; b < 3; ++b) s *= size_t(n[b] + (b == a ? 1 : 0));
        return s;
    }
    // Index of face (a, f), or -1 outside the lattice.
    long face(int a, const int f[3]) const {
        int d[3];
        for (int b = 0; b < 3; ++b) {
            d[b] = n[b] + (b == a ? 1 : 0);
            if (f[b] < 0 || f[b] >= d[b]) return -1;
        }
        size_t offset = 0;
        for (int b = 0; b < a; ++b) offset += face_count(b);
        return long(offset + size_t(f[0] + d[0] * (f[1] + d[1] * f[2])));
    }
    // The two cells of face (a, f): below and above along a.
    void sides(int a, const int f[3], int& lo, int& hi) const {
        int c[3] = {f[0], f[1], f[2]};
        hi = cell(c);
        c[a] -= 1;
        lo = cell(c);
    }
    bool solved(int a, const int f[3]) const {
        int lo, hi;
        sides(a, f, lo, hi);
        return lo != kSolid && hi != kSolid && (lo == kFluid || hi == kFluid);
    }
};

// E(u) from the definition; u holds every face (fixed and free ones at their given values).
double energy(const Grid& g, const std::vector<double>& u, const std::vector<double>& ustar, double c, bool free_slip) {
    auto value = [&](int a, const int f[3]) {
        const long i = g.face(a, f);
        return i < 0 ? 0.0 : u[size_t(i)];
    };
    double kinetic = 0.0, strain = 0.0;
    for (int a = 0; a < 3; ++a) {
        int f[3];
        for (f[2] = 0; f[2] < g.n[2] + (a == 2); ++f[2])
            for (f[1] = 0; f[1] < g.n[1] + (a == 1); ++f[1])
                for (f[0] = 0; f[0] < g.n[0] + (a == 0); ++f[0]) {
                    if (!g.solved(a, f)) continue;
                    int lo, hi;
                    g.sides(a, f, lo, hi);
                    const double m = 0.5 * ((lo == kFluid) + (hi == kFluid));
                    const double d = u[size_t(g.face(a, f))] - ustar[size_t(g.face(a, f))];
                    kinetic += 0.5 * m * d * d;
                }
    }
    // Normal strain rates at liquid cell centres.
    int c3[3];
    for (c3[2] = 0; c3[2] < g.n[2]; ++c3[2])
        for (c3[1] = 0; c3[1] < g.n[1]; ++c3[1])
            for (c3[0] = 0; c3[0] < g.n[0]; ++c3[0]) {
                if (g.cell(c3) != kFluid) continue;
                for (int a = 0; a < 3; ++a) {
                    int up[3] = {c3[0], c3[1], c3[2]};
                    up[a] += 1;
                    const double e = value(a, up) - value(a, c3);
                    strain += e * e;
                }
            }
    // Shear strain rates on the edges of axes a < b through corner n.
    for (int a = 0; a < 2; ++a)
        for (int b = a + 1; b < 3; ++b) {
            const int t = 3 - a - b;
            int nd[3];
            for (nd[2] = 0; nd[2] <= g.n[2]; ++nd[2])
                for (nd[1] = 0; nd[1] <= g.n[1]; ++nd[1])
                    for (nd[0] = 0; nd[0] <= g.n[0]; ++nd[0]) {
                        if (nd[t] >= g.n[t]) continue;
                        // The four cells around the edge, and its four faces (each between two of them).
                        auto at = [&](int da, int db) {
                            int c[3] = {nd[0], nd[1], nd[2]};
                            c[a] -= da;
                            c[b] -= db;
                            return g.cell(c);
                        };
                        const int k11 = at(0, 0), k01 = at(1, 0), k10 = at(0, 1), k00 = at(1, 1);
                        const int cells[4] = {k00, k10, k01, k11};
                        int fluid = 0, solid = 0;
                        for (int k : cells) fluid += k == kFluid, solid += k == kSolid;
                        auto free_face = [](int x, int y) { return x == kAir && y == kAir; };
                        if (fluid == 0 || (free_slip && solid > 0)) continue;
                        if (free_face(k01, k11) || free_face(k00, k10) || free_face(k10, k11) || free_face(k00, k01)) continue;
                        const double w = 0.25 * (fluid + solid);
                        int na[3] = {nd[0], nd[1], nd[2]}, nb[3] = {nd[0], nd[1], nd[2]};
                        na[b] -= 1;  // u_a(n - e_b)
                        nb[a] -= 1;  // u_b(n - e_a)
                        const double e = 0.5 * ((value(a, nd) - value(a, na)) + (value(b, nd) - value(b, nb)));
                        strain += 2.0 * w * e * e;
                    }
        }
    return kinetic + 0.5 * c * strain;
}

class ViscosityReference : public GpuTest {};

TEST_F(ViscosityReference, GpuSolveMinimisesTheEnergyItDefines) {
    const int n[3] = {9, 7, 6};
    constexpr float kDx = 0.05f, kDt = 0.01f;
    for (uint32_t seed : {1u, 2u}) {
        for (float mu : {5.0f, 500.0f}) {  // c = 2 nu dt / dx^2 = 0.04 and 4
            for (uint32_t free_slip : {0u, 1u}) {
                SCOPED_TRACE(testing::Message() << "seed " << seed << ", mu " << mu << ", free_slip " << free_slip);
                pf_sim_desc d = test_desc(uint32_t(n[0]), uint32_t(n[1]), uint32_t(n[2]), kDx);
                d.features = PF_FEATURE_VISCOSITY;
                SimPtr handle = create(d);
                ASSERT_TRUE(handle);
                pf_viscosity v = pf_default_viscosity();
                v.viscosity = mu;
                v.iterations = 1000;
                v.tolerance = 1e-6f;
                v.free_slip = free_slip;
                ASSERT_EQ(pf_set_viscosity(handle.get(), &v), PF_OK);
                Simulation& sim = *pf::entry(handle)->impl;

                Grid g{{n[0], n[1], n[2]}, {}};
                std::mt19937 rng(seed);
                std::uniform_real_distribution<float> u01(0.0f, 1.0f), speed(-1.0f, 1.0f);
                std::vector<uint32_t> type_words;
                for (int i = 0; i < n[0] * n[1] * n[2]; ++i) {
                    const float r = u01(rng);
                    g.kind.push_back(r < 0.6f ? kFluid : (r < 0.7f ? kSolid : kAir));
                    type_words.push_back(uint32_t(g.kind.back()));
                }
                const size_t faces = g.face_count(0) + g.face_count(1) + g.face_count(2);
                std::vector<float> ustar_f(faces);
                for (float& x : ustar_f) x = speed(rng);
                // The walls' faces are 0 (the core sets them so); obstacles' faces any velocity.
                for (int a = 0; a < 3; ++a) {
                    int f[3];
                    for (f[2] = 0; f[2] < n[2] + (a == 2); ++f[2])
                        for (f[1] = 0; f[1] < n[1] + (a == 1); ++f[1])
                            for (f[0] = 0; f[0] < n[0] + (a == 0); ++f[0])
                                if (f[a] == 0 || f[a] == n[a]) ustar_f[size_t(g.face(a, f))] = 0.0f;
                }
                std::vector<uint32_t> words(faces);
                std::memcpy(words.data(), ustar_f.data(), faces * 4);
                sim.write_grid_for_test(GridBuffer::cell_type, type_words);
                sim.write_grid_for_test(GridBuffer::face_vel, words);
                ASSERT_EQ(sim.run_effect_stages_for_test({EffectStage::after_classify, EffectStage::after_velocity_update}, kDt),
                          PF_OK);
                const std::vector<uint32_t> out = sim.read_grid(GridBuffer::face_vel);
                ASSERT_EQ(out.size(), faces);
                std::vector<float> u_f(faces);
                std::memcpy(u_f.data(), out.data(), faces * 4);

                const double c = 2.0 * (double(mu) / 1000.0) * kDt / (double(kDx) * kDx);
                std::vector<double> ustar(ustar_f.begin(), ustar_f.end()), u(u_f.begin(), u_f.end());
                // Largest partial derivative over the faces solved for, at u* and at the GPU's u.
                auto worst_gradient = [&](std::vector<double> at) {
                    double worst = 0.0;
                    size_t solved = 0;
                    for (int a = 0; a < 3; ++a) {
                        int f[3];
                        for (f[2] = 0; f[2] < n[2] + (a == 2); ++f[2])
                            for (f[1] = 0; f[1] < n[1] + (a == 1); ++f[1])
                                for (f[0] = 0; f[0] < n[0] + (a == 0); ++f[0]) {
                                    if (!g.solved(a, f)) continue;
                                    const size_t i = size_t(g.face(a, f));
                                    const double keep = at[i];
                                    at[i] = keep + 1.0;
                                    const double up = energy(g, at, ustar, c, free_slip != 0);
                                    at[i] = keep - 1.0;
                                    const double down = energy(g, at, ustar, c, free_slip != 0);
                                    at[i] = keep;
                                    worst = std::max(worst, std::abs(up - down) / 2.0);
                                    ++solved;
                                }
                    }
                    EXPECT_GT(solved, faces / 3);
                    return worst;
                };
                const double before = worst_gradient(ustar), after = worst_gradient(u);
                ASSERT_GT(before, 1e-3);
                EXPECT_LT(after, 1e-4 * before) << "largest dE/du_f: " << before << " at u*, " << after << " at the GPU's u";
                EXPECT_LT(energy(g, u, ustar, c, free_slip != 0), energy(g, ustar, ustar, c, free_slip != 0));
                // Faces not solved for are left exactly as they were.
                for (int a = 0; a < 3; ++a) {
                    int f[3];
                    for (f[2] = 0; f[2] < n[2] + (a == 2); ++f[2])
                        for (f[1] = 0; f[1] < n[1] + (a == 1); ++f[1])
                            for (f[0] = 0; f[0] < n[0] + (a == 0); ++f[0]) {
                                if (g.solved(a, f)) continue;
                                const size_t i = size_t(g.face(a, f));
                                ASSERT_EQ(u_f[i], ustar_f[i]) << "axis " << a << " face " << f[0] << "," << f[1] << "," << f[2];
                            }
                }
            }
        }
    }
}

}  // namespace
}  // namespace pf::test
