// Accuracy metrics of pf_stats (docs/design.md §4.11): the GPU's reductions against a
// double-precision CPU computation from the buffers the step leaves behind, the divergence a
// converged solve leaves against what 5 Jacobi sweeps leave, the kinetic energy of a free fall,
// the strain of analytic velocity fields, and their arrival through the readback ring without
// the caller waiting.
#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "api/handle.h"
#include "reference/cpu_reference.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class Metrics : public GpuTest {
protected:
    // The readback of the last step: glFinish only makes its fence signal (pf_get_stats never waits).
    static pf_stats settled_stats(pf_sim* sim) {
        pf::entry(sim)->impl->api().Finish();
        pf_stats st{};
        st.struct_size = sizeof st;  // 0 would give the first layout, without liquid_volume
        EXPECT_EQ(pf_get_stats(sim, &st), PF_OK);
        return st;
    }
};

// A splashing block: particles in the lower half with random velocities (so the grid has AIR,
// FLUID with unequal counts, and a divergence for the solver to remove).
void add_random_block(pf_sim* sim, const pf_sim_desc& d, int count, float speed, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f), uv(-speed, speed);
    std::vector<float> pos, vel;
    for (int i = 0; i < count; ++i) {
        for (int a = 0; a < 3; ++a) pos.push_back(d.cell_size * float(d.grid_size[a]) * (a == 1 ? 0.5f : 1.0f) * u(rng));
        for (int a = 0; a < 3; ++a) vel.push_back(uv(rng));
    }
    ASSERT_EQ(pf_add_particles(sim, pos.data(), vel.data(), uint32_t(count)), PF_OK);
}

TEST_F(Metrics, GpuReductionsMatchTheCpu) {
    pf_sim_desc d = test_desc(16, 12, 14, 0.05f);
    d.params.pressure_solver = PF_PRESSURE_SOLVER_JACOBI;
    d.params.pressure_iterations = 20;  // leaves a clear divergence to measure
    SimPtr handle = create(d);
    ASSERT_TRUE(handle);
    add_random_block(handle.get(), d, 9000, 1.0f, 3);
    for (int f = 0; f < 3; ++f) ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
    const pf_stats st = settled_stats(handle.get());
    ASSERT_EQ(st.metrics_step, st.steps);

    // The same quantities from the buffers the step left (the last substep's grid, the particles now).
    const Simulation& sim = *pf::entry(handle)->impl;
    const ref::Grid g{16, 12, 14, d.cell_size, glm::dvec3(0.0)};
    const std::vector<uint32_t> type_words = sim.read_grid(GridBuffer::cell_type);
    const std::vector<uint32_t> count = sim.read_grid(GridBuffer::cell_count);
    std::vector<uint8_t> type(type_words.size());
    for (size_t c = 0; c < type.size(); ++c) type[c] = uint8_t(PF_CELL_KIND(type_words[c]));
    const std::vector<double> face_vel = words_as_floats(sim.read_grid(GridBuffer::face_vel));
    const std::vector<double> div = ref::divergence(g, type, face_vel);
    double strain_sum = 0, strain_scale = 0;
    for (double p : ref::strain(g, type, face_vel)) strain_sum += p, strain_scale += std::abs(p);
    double sum2 = 0, max_div = 0;
    uint32_t fluid = 0;
    for (size_t c = 0; c < div.size(); ++c) {
        if (type[c] != PF_CELL_FLUID) continue;
        const double dc = div[c] / d.cell_size;
        sum2 += dc * dc;
        max_div = std::max(max_div, std::abs(dc));
        ++fluid;
    }
    const ParticleState p = read_all(handle.get());
    double v2 = 0;
    for (float v : p.vel) v2 += double(v) * v;
    const double mass = d.density * std::pow(double(d.cell_size), 3) / d.fill_particles_per_cell;

    EXPECT_EQ(st.fluid_cells, fluid);
    ASSERT_GT(fluid, 1000u);
    const double l2 = std::sqrt(sum2 / fluid);
    ASSERT_GT(l2, 0.1);  // 20 sweeps on a random field: far from divergence free (measured 2.8 1/s)
    // Float sums of a few thousand terms in a fixed order: a few 1e-7 relative; the divergence
    // itself differs from the double one by the rounding of its 6 face differences.
    EXPECT_NEAR(st.divergence_l2, l2, 1e-5 * l2);
    EXPECT_NEAR(st.divergence_max, max_div, 1e-5 * max_div);
    EXPECT_NEAR(st.kinetic_energy, 0.5 * mass * v2, 1e-5 * 0.5 * mass * v2);
    // The strain's cell values have either sign: its sum is held to the sum of their sizes.
    ASSERT_GT(strain_scale, 0.0);
    EXPECT_NEAR(st.strain, strain_sum / fluid, 1e-5 * strain_scale / fluid);
    EXPECT_NEAR(st.particle_volume, particle_volume_of(count, d), 1e-6 * particle_volume_of(count, d));
    // Interior cells: holding particles, no empty face neighbour (walls count as closed); with no
    // obstacle a cell is FLUID exactly when it holds a particle, so these are the GPU's.
    const Interior interior = interior_of(count, d);
    ASSERT_GT(interior.cells, 100u);  // the random block is 16 x 6 x 14 cells deep
    const double interior_density = interior.density;
    // A random fill holds Poisson(n) particles per cell: near rest density on average, unlike
    // the capped sum of particle_volume (which reads the spread as compression).
    EXPECT_NEAR(st.interior_density, interior_density, 1e-5 * interior_density);
    const double rest_volume = double(p.count()) / d.fill_particles_per_cell * std::pow(double(d.cell_size), 3);
    EXPECT_NEAR(st.liquid_volume, rest_volume / interior_density, 1e-5 * rest_volume);
    RecordProperty("divergence_l2", std::to_string(st.divergence_l2));
    RecordProperty("interior_density", std::to_string(st.interior_density));
}

// What accuracy costs: a converged MGPCG solve (tolerance 1e-5) leaves almost no divergence,
// 5 Jacobi sweeps leave most of it. Separation off, so every FLUID cell is held divergence free.
TEST_F(Metrics, ConvergedSolveLeavesLittleDivergenceFiveJacobiSweepsMuch) {
    auto measure = [&](pf_pressure_solver solver, uint32_t iterations, float tolerance) {
        pf_sim_desc d = test_desc(16, 16, 16, 0.05f);
        d.params.pressure_solver = solver;
        d.params.pressure_iterations = iterations;
        d.params.pressure_tolerance = tolerance;
        d.params.separation = 0;
        d.params.volume_correction = 0;  // what the solve leaves of a divergence-free target
        SimPtr sim = create(d);
        EXPECT_TRUE(sim);
        add_random_block(sim.get(), d, 12000, 1.0f, 11);
        EXPECT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        const pf_stats st = settled_stats(sim.get());
        EXPECT_EQ(st.metrics_step, 1u);
        return st;
    };
    const pf_stats mg = measure(PF_PRESSURE_SOLVER_MGPCG, 200, 1e-5f);
    const pf_stats jacobi = measure(PF_PRESSURE_SOLVER_JACOBI, 5, 1e-5f);
    RecordProperty("mgpcg_l2", std::to_string(mg.divergence_l2));
    RecordProperty("mgpcg_max", std::to_string(mg.divergence_max));
    RecordProperty("jacobi5_l2", std::to_string(jacobi.divergence_l2));
    RecordProperty("jacobi5_max", std::to_string(jacobi.divergence_max));
    EXPECT_LE(mg.solver_residual, 1e-5f);
    // Random velocities up to 1 m/s on 5 cm cells. Measured on llvmpipe (1/s): MGPCG l2 3.9e-5,
    // max 3.6e-4; 5 Jacobi sweeps l2 0.88, max 2.9. Bounds: 25x above MGPCG's, 3x below Jacobi's.
    EXPECT_LT(mg.divergence_l2, 1e-3f);
    EXPECT_GT(jacobi.divergence_l2, 0.3f);
    EXPECT_LT(100.0f * mg.divergence_l2, jacobi.divergence_l2);
    EXPECT_LT(mg.divergence_max, jacobi.divergence_max);
}

// A blob in free fall gains kinetic energy 0.5 M (g t)^2 (no pressure acts in the air; the
// grid adds g dt per substep exactly, and FLIP carries it to every particle).
TEST_F(Metrics, KineticEnergyOfAFreeFallGrowsWithTimeSquared) {
    // Far from every wall: a valid wall face within the extrapolation band (0 m/s) would slow
    // the blob's rim (the lid 1 cell above the blob costs 1% of the energy in the first frame).
    pf_sim_desc d = test_desc(16, 24, 16, 0.05f);
    d.params.volume_correction = 0;  // a free fall: no pressure may act (cells change counts as they fall)
    // The sorted gather's float sums give every face the blob's velocity to float rounding. The
    // default fixed-point P2G rounds each face's momentum (max_speed / 2^21 over the face's
    // weight, large on the rim's barely reached faces); a converged projection (the default
    // MGPCG) then acts on that rounding: measured 1.3e-4 of the energy too much at frame 3, 2e-7
    // with the gather (docs/notes/2026-11-23-p2g-schemes.md).
    d.params.p2g = PF_P2G_SORTED_GATHER;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.25f, 0.7f, 0.25f}, hi[3] = {0.55f, 0.9f, 0.55f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const double g = 9.81, frame = 1.0 / 60.0;
    pf_stats st{};
    ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
    const double mass = d.density * std::pow(double(d.cell_size), 3) / d.fill_particles_per_cell * st.particle_count;
    for (int f = 1; f <= 15; ++f) {
        ASSERT_EQ(pf_step(sim.get(), float(frame)), PF_OK);
        st = settled_stats(sim.get());
        ASSERT_EQ(st.metrics_step, uint64_t(f));
        const double t = f * frame, expected = 0.5 * mass * (g * t) * (g * t);
        // Float velocities summed over 1152 particles: rounding is ~1e-6 relative (measured at
        // most 2.1e-7 in 15 frames).
        EXPECT_NEAR(st.kinetic_energy, expected, 1e-5 * expected) << "frame " << f;
    }
}

// The strain P = (tr(G^2) - tr(G)^2) / 2 that the step clock limits for straight moves
// (src/sim/step_clock.h), on linear fields set on the faces: a straight move of dt through
// u = (s x, -s y, 0) maps a patch by (1 + s dt, 1 - s dt), area factor 1 - s^2 dt^2 (P = s^2);
// through a rotation of w by 1 + w^2 dt^2 (P = -w^2); a shear moves no area (P = 0). The cells
// of the top layer are AIR, so the layer below is FLUID but not interior: it counts in the mean
// as unstrained (P summed over interior cells, divided by every FLUID cell).
TEST_F(Metrics, StrainOfLinearFieldsIsWhatAStraightMoveCompresses) {
    const int n[3] = {12, 10, 8};
    pf_sim_desc d = test_desc(n[0], n[1], n[2], 0.1f);
    SimPtr handle = create(d);
    ASSERT_TRUE(handle);
    Simulation& sim = *pf::entry(handle)->impl;
    std::vector<uint32_t> types(size_t(n[0]) * n[1] * n[2], PF_CELL_FLUID);
    for (int k = 0; k < n[2]; ++k)
        for (int i = 0; i < n[0]; ++i) types[(size_t(k) * n[1] + (n[1] - 1)) * n[0] + i] = PF_CELL_AIR;
    sim.write_grid_for_test(GridBuffer::cell_type, types);
    const double fluid = double(n[0]) * (n[1] - 1) * n[2], interior = double(n[0]) * (n[1] - 2) * n[2];

    // Face velocities of u(x) = A x (world coordinates from the grid's corner, x = g dx).
    const ref::Grid grid{n[0], n[1], n[2], d.cell_size, glm::dvec3(0.0)};
    const auto strain_of = [&](const double (&A)[3][3]) {
        const std::vector<uint32_t> words = floats_as_words(ref::sample_faces(grid, [&](int axis, const glm::dvec3& g) {
            double u = 0;
            for (int b = 0; b < 3; ++b) u += A[axis][b] * (g[b] - 4.0) * d.cell_size;
            return u;
        }));
        sim.write_grid_for_test(GridBuffer::face_vel, words);
        EXPECT_EQ(sim.run_metrics_for_test(), PF_OK);
        const std::vector<uint32_t> status = sim.read_grid(GridBuffer::status);
        float p = 0;
        std::memcpy(&p, &status[PF_STATUS_STRAIN], 4);
        EXPECT_EQ(status[PF_STATUS_FLUID_CELLS], uint32_t(fluid));
        return double(p);
    };
    const double s = 3.0, w = 2.0, shear = 5.0, share = interior / fluid;
    // Float face values up to ~40 cells x 5 /s: rounding a few 1e-7 of them, differenced over a cell.
    const double tol = 1e-4;
    EXPECT_NEAR(strain_of({{s, 0, 0}, {0, -s, 0}, {0, 0, 0}}), s * s * share, tol * s * s);
    EXPECT_NEAR(strain_of({{0, -w, 0}, {w, 0, 0}, {0, 0, 0}}), -w * w * share, tol * w * w);
    EXPECT_NEAR(strain_of({{0, shear, 0}, {0, 0, 0}, {0, 0, 0}}), 0.0, tol * shear * shear);
    // Strain in one plane and rotation in another add: P = s^2 - w^2.
    EXPECT_NEAR(strain_of({{s, 0, 0}, {0, -s, -w}, {0, w, 0}}), (s * s - w * w) * share, tol * s * s);
    // A uniform expansion G = c I (not divergence free): P = (3 c^2 - 9 c^2) / 2 = -3 c^2 (the volume
    // grows by dt tr G to first order; P is the second-order term).
    EXPECT_NEAR(strain_of({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), -3.0 * share, tol);
}

// The metrics come through the readback ring: pf_get_stats never waits, so they arrive some
// steps late, each labelled with its step; the drifts start at 0 on the first measured step.
TEST_F(Metrics, ArriveLateWithoutWaiting) {
    pf_sim_desc d = test_desc(12, 12, 12, 0.05f);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.6f, 0.3f, 0.6f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    pf_stats st{};
    ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
    EXPECT_EQ(st.metrics_step, 0u) << "nothing measured before the first step";
    uint64_t first = 0;
    for (int f = 0; f < 200 && first == 0; ++f) {
        ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
        EXPECT_LE(st.metrics_step, st.steps);
        if (st.metrics_step != 0) first = st.metrics_step;
    }
    ASSERT_NE(first, 0u) << "no metrics after 200 steps without a wait";
    EXPECT_EQ(st.fluid_cells, 12u * 6u * 12u);  // the filled block, 8 particles in each of its cells
    EXPECT_FLOAT_EQ(st.particle_volume, 0.6f * 0.3f * 0.6f);
    EXPECT_EQ(st.fluid_cell_drift, 0.0f);
    EXPECT_EQ(st.particle_volume_drift, 0.0f);
    RecordProperty("steps_until_first_metrics", std::to_string(st.steps));
}

}  // namespace
}  // namespace pf::test
