// The volume correction (docs/design.md §4.5) against the double-precision CPU reference: its
// potential solves the reference's problem to the correction's tolerance, the particles move
// by the reference's displacement of that potential, and velocities are not touched.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "api/handle.h"
#include "reference/cpu_reference.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class VolumeCorrectionPass : public GpuTest {};

double norm(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return std::sqrt(s);
}

// Random particles filling the lower 60% of a 12 x 10 x 8 grid at about 10 per cell: cells
// above and below the rest count of 8, a free surface above. With each surface: the marker
// cell, and the ghost fluid with theta per face drawn from {1/4, 1/2, 1} (exact in the type
// word's fixed point), where a cell beside AIR spreads only a surplus beyond a quarter of the rest
// count and FLUID-AIR faces divide by theta.
TEST_F(VolumeCorrectionPass, MovesPositionsByTheReferenceDisplacementAndLeavesVelocities) {
    for (const auto [surface, solver] : {std::pair{PF_FREE_SURFACE_MARKER_CELL, PF_PRESSURE_SOLVER_JACOBI},
                                         std::pair{PF_FREE_SURFACE_MARKER_CELL, PF_PRESSURE_SOLVER_MGPCG},
                                         std::pair{PF_FREE_SURFACE_GHOST_FLUID, PF_PRESSURE_SOLVER_JACOBI},
                                         std::pair{PF_FREE_SURFACE_GHOST_FLUID, PF_PRESSURE_SOLVER_MGPCG}}) {
        SCOPED_TRACE("surface " + std::to_string(int(surface)) + " solver " + std::to_string(int(solver)));
        const bool ghost = surface == PF_FREE_SURFACE_GHOST_FLUID;
        pf_sim_desc d = test_desc(12, 10, 8, 0.1f);
        d.params.pressure_solver = solver;
        d.params.free_surface = surface;
        // Jacobi with separation (walls without pressure count as open: only a surplus is
        // corrected beside them), MGPCG without; the correction's own solve never imposes
        // p >= 0 either way.
        d.params.separation = solver == PF_PRESSURE_SOLVER_JACOBI ? 1 : 0;
        d.params.volume_correction = 0.5f;
        const ref::Grid g{12, 10, 8, 0.1, glm::dvec3(0.0)};
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> u01(0.0f, 1.0f), uv(-1.0f, 1.0f);
        const int n = 12 * 6 * 8 * 10;
        std::vector<float> pos, vel;
        for (int i = 0; i < n; ++i) {
            pos.insert(pos.end(), {1.2f * u01(rng), 0.6f * u01(rng), 0.8f * u01(rng)});
            vel.insert(vel.end(), {uv(rng), uv(rng), uv(rng)});
        }
        SimPtr handle = create(d);
        ASSERT_TRUE(handle);
        ASSERT_EQ(pf_add_particles(handle.get(), pos.data(), vel.data(), uint32_t(n)), PF_OK);
        Simulation& sim = *pf::entry(handle)->impl;
        const std::vector<uint32_t> count = cell_counts_of(ParticleState{pos, vel}, d);
        const std::vector<uint8_t> type = ref::classify(g, count);
        std::vector<double> theta;  // empty: the marker cell
        std::vector<uint32_t> type_words(type.begin(), type.end());
        if (ghost) {
            std::uniform_int_distribution<int> pick(0, 2);
            for (int f = 0; f < g.faces(); ++f) theta.push_back(1.0 / double(1 << pick(rng)));
            const std::vector<double> extra = ref::surface_extra_diagonal(g, type, theta);
            size_t surface_cells = 0;
            for (int c = 0; c < g.cells(); ++c) {
                type_words[size_t(c)] |= uint32_t(extra[size_t(c)] * PF_CELL_SURFACE_ONE + 0.5) << PF_CELL_SURFACE_SHIFT;
                surface_cells += extra[size_t(c)] > 0.0;
            }
            ASSERT_GT(surface_cells, 0u);
            sim.write_grid_for_test(GridBuffer::face_fraction, floats_as_words(theta));
        }
        sim.write_grid_for_test(GridBuffer::cell_count, count);
        sim.write_grid_for_test(GridBuffer::cell_type, type_words);
        // The last solve's pressure: positive in the lower half (liquid pressed against the
        // walls), 0 above (with separation, liquid there may leave the walls).
        std::vector<double> pressure(size_t(g.cells()), 0.0);
        for (int k = 0; k < g.nz; ++k)
            for (int j = 0; j < g.ny / 4; ++j)
                for (int i = 0; i < g.nx; ++i) pressure[size_t(g.cell_index(i, j, k))] = 100.0;
        sim.write_grid_for_test(GridBuffer::pressure, floats_as_words(pressure));
        ASSERT_EQ(sim.run_volume_correction_for_test(), PF_OK);

        // The potential: MGPCG solves A q = b to the correction's tolerance; Jacobi's sweeps from
        // q = 0 (no sign constraint, whatever the preset's separation) match the reference's.
        const std::vector<double> b = ref::volume_correction_rhs(g, type, count, d.fill_particles_per_cell, 0.5,
                                                                 d.params.separation != 0, pressure, ghost);
        ASSERT_GT(norm(b), 0.0);
        const std::vector<float> qf = sim.read_volume_potential();
        const std::vector<double> q(qf.begin(), qf.end());
        if (solver == PF_PRESSURE_SOLVER_MGPCG) {
            const std::vector<double> aq = ref::laplacian(g, type, q, theta);
            std::vector<double> r(b.size());
            for (size_t c = 0; c < b.size(); ++c) r[c] = type[c] == ref::FLUID ? b[c] - aq[c] : 0.0;
            EXPECT_LE(norm(r) / norm(b), 1.01 * VolumeCorrection::kTolerance);
        } else {
            const std::vector<double> q_ref = ref::jacobi(g, type, b, std::vector<double>(b.size(), 0.0),
                                                          int(d.params.pressure_iterations), d.params.jacobi_omega,
                                                          false, theta);
            double scale = 0, worst = 0;
            for (size_t c = 0; c < b.size(); ++c) {
                scale = std::max(scale, std::abs(q_ref[c]));
                worst = std::max(worst, std::abs(q[c] - q_ref[c]));
            }
            ASSERT_GT(scale, 0.0);
            EXPECT_LE(worst, 1e-5 * scale);
        }

        // Particles move by the reference displacement of the GPU's potential; velocities stay.
        ref::Particles expected;
        for (int i = 0; i < n; ++i) {
            expected.pos.emplace_back(pos[size_t(i) * 3], pos[size_t(i) * 3 + 1], pos[size_t(i) * 3 + 2]);
            expected.vel.emplace_back(0.0);
        }
        ref::volume_correction_move(g, type, q, expected, theta);
        const ParticleState after = read_all(handle.get());
        ASSERT_EQ(after.count(), size_t(n));
        double moved = 0, worst = 0;
        for (int i = 0; i < n; ++i)
            for (int a = 0; a < 3; ++a) {
                const size_t k = size_t(i) * 3 + size_t(a);
                worst = std::max(worst, std::abs(after.pos[k] - expected.pos[size_t(i)][a]));
                moved = std::max(moved, std::abs(after.pos[k] - double(pos[k])));
                ASSERT_EQ(after.vel[k], vel[k]) << "particle " << i;
            }
        EXPECT_GT(moved, 1e-3 * g.dx) << "the correction moved nothing";
        EXPECT_LE(worst, 1e-5 * g.dx);
    }
}

// Off (volume_correction 0): nothing moves.
TEST_F(VolumeCorrectionPass, OffMovesNothing) {
    pf_sim_desc d = test_desc(8, 8, 8, 0.1f);
    d.params.volume_correction = 0.0f;
    SimPtr handle = create(d);
    ASSERT_TRUE(handle);
    std::vector<float> pos, vel;
    for (int i = 0; i < 2000; ++i) pos.insert(pos.end(), {0.05f + 0.0003f * float(i), 0.2f, 0.3f}), vel.insert(vel.end(), {0, 0, 0});
    ASSERT_EQ(pf_add_particles(handle.get(), pos.data(), vel.data(), 2000), PF_OK);
    Simulation& sim = *pf::entry(handle)->impl;
    ASSERT_EQ(sim.run_volume_correction_for_test(), PF_OK);
    const ParticleState after = read_all(handle.get());
    for (size_t k = 0; k < pos.size(); ++k) ASSERT_EQ(after.pos[k], pos[k]);
}

// With MGPCG and no separation (the balanced and fast presets) the correction's solve goes in
// the same passes as the projection's (a pair solve): a dam break's particles stay those of the
// two solves issued in turn within rounding (the solves agree within 3.1e-7 of
// their largest value, test_solvers.cpp's PairSolve), and the pair issues fewer passes.
// Measured on llvmpipe: the largest difference in position is 2.1e-6 m after 10 frames; it
// grows with the flow (against the two solves on separate instances: 6e-8 m after one frame,
// 1.5e-3 m after 20, where one run's rounding had sent a particle into another cell), so the
// comparison stops at 10. The last step's solver passes: 69 against 69 + 69.
TEST_F(VolumeCorrectionPass, PairedWithTheProjectionMatchesItsOwnSolve) {
    std::vector<float> pos[2];
    uint64_t solve_dispatches[2] = {0, 0}, correction_dispatches[2] = {0, 0};
    for (int paired = 0; paired < 2; ++paired) {
        pf_sim_desc d = test_desc(16, 12, 8, 0.1f);
        d.params.pressure_solver = PF_PRESSURE_SOLVER_MGPCG;
        d.params.separation = 0;
        d.params.volume_correction = 0.5f;
        SimPtr handle = create(d);
        ASSERT_TRUE(handle) << last_log();
        Simulation& sim = *pf::entry(handle)->impl;
        sim.set_paired_correction_for_test(paired == 1);
        const float lo[3] = {0, 0, 0}, hi[3] = {0.6f, 0.8f, 0.8f};
        ASSERT_EQ(pf_fill_box(handle.get(), lo, hi, nullptr), PF_OK);
        for (int f = 0; f < 10; ++f) ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
        pos[paired] = read_all(handle.get()).pos;
        for (const pf_pass_stats& ps : pass_list(handle.get())) {
            const std::string name = ps.name;
            if (name.rfind("mgpcg", 0) == 0) solve_dispatches[paired] += ps.dispatches;
            if (name == "volume_correction_solve") correction_dispatches[paired] += ps.dispatches;
        }
        EXPECT_EQ(sim.runner().binding_errors(), 0u);
    }
    ASSERT_EQ(pos[0].size(), pos[1].size());
    double worst = 0;
    for (size_t i = 0; i < pos[0].size(); ++i) worst = std::max(worst, double(std::abs(pos[1][i] - pos[0][i])));
    EXPECT_LT(worst, 2e-5);  // metres; the cells are 0.1 m
    char text[32];
    std::snprintf(text, sizeof text, "%.2e", worst);
    RecordProperty("largest_position_difference_m", text);
    EXPECT_GT(correction_dispatches[0], 0u);
    EXPECT_EQ(correction_dispatches[1], 0u) << "the pair's passes count as the projection's";
    EXPECT_LT(solve_dispatches[1], solve_dispatches[0] + correction_dispatches[0]);
}

}  // namespace
}  // namespace pf::test
