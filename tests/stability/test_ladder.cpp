// Case 10 (docs/stability.md): every combination of the accuracy ladder — pressure solver x
// transfer x advection, with fixed-point P2G; and the other P2G schemes (float atomics, sorted
// gather) with both transfers on the cheapest and the most accurate solver — on cases 1 (a dam break at 0.5 s frames), 5 (a closed full box) and 6
// (liquid in two mirrored corners), and a 1 x 16 x 1 shaft at rest, each small and short. Every run must be sound; the closed
// box at rest and the two corners mirror images.
#include <cmath>
#include <string>
#include <tuple>

#include "stability/stability.h"

namespace pf::test {
namespace {

using Combination = std::tuple<pf_pressure_solver, pf_transfer, pf_advection, pf_p2g>;

class Ladder : public GpuTest, public ::testing::WithParamInterface<Combination> {
protected:
    pf_sim_desc ladder_desc(uint32_t nx, uint32_t ny, uint32_t nz) const {
        pf_sim_desc d = test_desc(nx, ny, nz, 0.1f);
        d.params.pressure_solver = std::get<0>(GetParam());
        d.params.transfer = std::get<1>(GetParam());
        d.params.advection = std::get<2>(GetParam());
        d.params.p2g = std::get<3>(GetParam());
        return d;
    }
    static void expect_sound(pf_sim* sim, const pf_sim_desc& d, size_t n, const char* when) {
        const ParticleState p = read_all(sim);
        ASSERT_EQ(p.count(), n) << when;
        for (size_t i = 0; i < p.count(); ++i)
            for (int a = 0; a < 3; ++a) {
                ASSERT_TRUE(std::isfinite(p.pos[i * 3 + a]) && std::isfinite(p.vel[i * 3 + a])) << when << " particle " << i;
                ASSERT_GE(p.pos[i * 3 + a], d.origin[a]) << when;
                ASSERT_LE(p.pos[i * 3 + a], d.origin[a] + d.cell_size * float(d.grid_size[a])) << when;
            }
    }
};

TEST_P(Ladder, DamBreakAtHalfSecondFrames) {
    const pf_sim_desc d = ladder_desc(12, 6, 4);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.4f, 0.5f, 0.4f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    pf_stats st{};
    pf_get_stats(sim.get(), &st);
    for (int f = 0; f < 4; ++f) ASSERT_EQ(pf_step(sim.get(), 0.5f), PF_OK);
    expect_sound(sim.get(), d, st.particle_count, "dam break");
}

TEST_P(Ladder, ClosedFullBoxStaysAtRest) {
    const pf_sim_desc d = ladder_desc(4, 4, 4);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.4f, 0.4f, 0.4f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    for (int f = 0; f < 30; ++f) ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    expect_sound(sim.get(), d, 4 * 4 * 4 * 8, "closed box");
    EXPECT_LT(max_speed_of(read_all(sim.get())), 1e-3 * std::sqrt(9.81 * d.cell_size));
}

// A one-cell-wide shaft (1 x 16 x 1), half full, with every solver: at rest, nothing moves.
TEST_P(Ladder, OneCellWideShaftStaysAtRest) {
    const pf_sim_desc d = ladder_desc(1, 16, 1);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.1f, 0.8f, 0.1f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    for (int f = 0; f < 30; ++f) ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    expect_sound(sim.get(), d, 8 * 8, "shaft");
    EXPECT_LT(max_speed_of(read_all(sim.get())), 1e-3 * std::sqrt(9.81 * d.cell_size));
}

// Liquid in the (-,-,-) corner and, mirrored, in the (+,-,+) corner with gravity into each.
TEST_P(Ladder, TwoMirroredCornersAgree) {
    pf_sim_desc d = ladder_desc(6, 6, 6);
    std::vector<float> pos;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            for (int k = 0; k < 6; ++k)
                if (i + j + k <= 7) pos.insert(pos.end(), {0.05f * float(i) + 0.025f, 0.05f * float(j) + 0.025f, 0.05f * float(k) + 0.025f});
    const uint32_t n = uint32_t(pos.size() / 3);
    const float g = 9.81f / std::sqrt(3.0f);
    double com[2][3] = {};
    for (int run = 0; run < 2; ++run) {
        std::vector<float> p = pos;
        const bool flip[3] = {run == 1, false, run == 1};
        for (int a = 0; a < 3; ++a) {
            d.params.gravity[a] = flip[a] ? g : -g;
            if (flip[a])
                for (size_t i = a; i < p.size(); i += 3) p[i] = 0.6f - p[i];
        }
        SimPtr sim = create(d);
        ASSERT_TRUE(sim);
        ASSERT_EQ(pf_add_particles(sim.get(), p.data(), nullptr, n), PF_OK);
        for (int f = 0; f < 15; ++f) ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        expect_sound(sim.get(), d, n, "corner");
        const ParticleState s = read_all(sim.get());
        for (size_t i = 0; i < s.count(); ++i)
            for (int a = 0; a < 3; ++a) com[run][a] += (flip[a] ? 0.6 - s.pos[i * 3 + a] : s.pos[i * 3 + a]) / n;
    }
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(com[0][a], com[1][a], 1e-3 * d.cell_size) << "axis " << a;
}

std::string combination_name(const ::testing::TestParamInfo<Combination>& info) {
    static const char* solvers[] = {"jacobi", "rbgs", "cg", "pcg", "mgpcg", "mgpcg_galerkin"};
    static const char* transfers[] = {"flip", "apic"};
    static const char* advections[] = {"euler", "rk2", "rk3", "leapfrog"};
    static const char* p2g[] = {"", "_float_atomic", "_sorted_gather"};  // fixed point: the names of old
    return std::string(solvers[std::get<0>(info.param)]) + "_" + transfers[std::get<1>(info.param)] + "_" +
           advections[std::get<2>(info.param)] + p2g[std::get<3>(info.param)];
}

INSTANTIATE_TEST_SUITE_P(
    Every, Ladder,
    ::testing::Combine(::testing::Values(PF_PRESSURE_SOLVER_JACOBI, PF_PRESSURE_SOLVER_RBGS, PF_PRESSURE_SOLVER_CG,
                                         PF_PRESSURE_SOLVER_PCG, PF_PRESSURE_SOLVER_MGPCG, PF_PRESSURE_SOLVER_MGPCG_GALERKIN),
                       ::testing::Values(PF_TRANSFER_PIC_FLIP, PF_TRANSFER_APIC),
                       ::testing::Values(PF_ADVECTION_EULER, PF_ADVECTION_RK2, PF_ADVECTION_RK3, PF_ADVECTION_LEAPFROG),
                       ::testing::Values(PF_P2G_FIXED_POINT)),
    combination_name);

INSTANTIATE_TEST_SUITE_P(
    P2g, Ladder,
    ::testing::Combine(::testing::Values(PF_PRESSURE_SOLVER_JACOBI, PF_PRESSURE_SOLVER_MGPCG),
                       ::testing::Values(PF_TRANSFER_PIC_FLIP, PF_TRANSFER_APIC), ::testing::Values(PF_ADVECTION_EULER),
                       ::testing::Values(PF_P2G_FLOAT_ATOMIC, PF_P2G_SORTED_GATHER)),
    combination_name);

}  // namespace
}  // namespace pf::test
