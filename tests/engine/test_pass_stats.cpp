// The runtime per-pass statistics list (pf_get_pass_count / pf_get_pass_stats): it names the
// core passes and the active solver's, its dispatch counts add up to pf_stats' fixed arrays,
// and bad arguments are refused.
#include <algorithm>
#include <map>
#include <set>
#include <string>

#include <glad/gl.h>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class PassStats : public GpuTest {};

// The list by name; every name once.
std::map<std::string, pf_pass_stats> pass_map(pf_sim* sim) {
    std::map<std::string, pf_pass_stats> out;
    for (const pf_pass_stats& s : pass_list(sim))
        EXPECT_TRUE(out.emplace(s.name, s).second) << "name repeats: " << s.name;
    return out;
}

TEST_F(PassStats, ListsCorePassesAndAddsUpToTheFixedArrays) {
    pf_sim_desc d = test_desc(16, 16, 16, 0.05f);
    d.params.pressure_solver = PF_PRESSURE_SOLVER_JACOBI;  // the fast preset's: its dispatches are counted below
    d.params.pressure_iterations = 12;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.8f, 0.4f, 0.8f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    pf_stats st{};
    ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);

    const auto list = pass_map(sim.get());
    const std::set<std::string> core = {"clear",           "p2g",         "grid_forces", "classify", "pressure_setup",
                                        "velocity_update", "extrapolate", "g2p",         "advect",   "jacobi"};
    for (const std::string& name : core) EXPECT_EQ(list.count(name), 1u) << name;
    EXPECT_EQ(list.at("jacobi").group, PF_PASS_PRESSURE_SOLVE);
    // Per substep: 12 sweeps, residual checks (2 dispatches each) after sweep 4 and at the end,
    // the start (2) and the final report (2).
    EXPECT_EQ(list.at("jacobi").dispatches, st.substeps * (12 + 2 * 2 + 4));
    EXPECT_EQ(list.at("p2g").dispatches, st.substeps);
    uint32_t per_group[PF_PASS_COUNT] = {};
    for (const auto& [name, s] : list) {
        ASSERT_GE(int(s.group), 0) << name;
        ASSERT_LT(int(s.group), PF_PASS_COUNT) << name;
        per_group[s.group] += s.dispatches;
        EXPECT_GE(s.gpu_ms, 0.0f) << name;
    }
    for (int p = 0; p < PF_PASS_COUNT; ++p) EXPECT_EQ(per_group[p], st.dispatches[p]) << pf_pass_name(pf_pass(p));
}

// pf_stats reports the pressure solve of the last measured step: iterations and final residual.
// A tolerance the solver reaches gives a residual at or below it in fewer iterations than the
// cap; a cap it cannot reach in gives exactly the cap and a residual above the tolerance. With
// separation, PCG's iterations add up over its active-set rounds and the residual is that of
// the complementarity problem.
TEST_F(PassStats, SolverIterationsAndResidualAreReported) {
    struct Case {
        uint32_t cap, separation;
        bool reachable;
    };
    for (const Case& c : {Case{400, 0, true}, Case{3, 0, false}, Case{400, 1, true}}) {
        const uint32_t cap = c.cap;
        const bool reachable = c.reachable;
        pf_sim_desc d = test_desc(12, 12, 12, 0.05f);
        d.params.pressure_solver = PF_PRESSURE_SOLVER_PCG;
        d.params.pressure_tolerance = 1e-4f;
        d.params.pressure_iterations = cap;
        d.params.separation = c.separation;
        SimPtr sim = create(d);
        ASSERT_TRUE(sim);
        const float lo[3] = {0, 0, 0}, hi[3] = {0.6f, 0.3f, 0.6f}, v[3] = {1.0f, 0.0f, 0.0f};
        ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, v), PF_OK);
        ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        glFinish();  // the readback is a few frames late; finishing makes it available
        pf_stats st{};
        ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
        ASSERT_EQ(st.gpu_step, st.steps);
        if (reachable) {
            EXPECT_GT(st.solver_iterations, 0u);
            EXPECT_LT(st.solver_iterations, cap * (c.separation ? 5u : 1u));
            EXPECT_LE(st.solver_residual, 1e-4f);
        } else {
            EXPECT_EQ(st.solver_iterations, cap);
            EXPECT_GT(st.solver_residual, 1e-4f);
        }
        EXPECT_TRUE(std::isfinite(st.solver_residual));
    }
}

// Issued iterations follow what the solver needed a few steps ago: once that is read back,
// a solve with a cap of 400 issues a few dozen CG iterations (5 dispatches each), not 400,
// and still meets its tolerance.
TEST_F(PassStats, IssuedIterationsFollowTheReadBackNeed) {
    pf_sim_desc d = test_desc(12, 12, 12, 0.05f);
    d.params.pressure_solver = PF_PRESSURE_SOLVER_PCG;
    d.params.pressure_tolerance = 1e-4f;
    d.params.pressure_iterations = 400;
    d.params.separation = 0;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.6f, 0.3f, 0.6f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    // A PCG iteration is two passes: direction with A p (its last workgroup forms alpha), and
    // the update (its last workgroup forms beta and tests the tolerance).
    constexpr double kPassesPerIteration = 2.0;
    auto pcg_dispatches_per_substep = [&] {
        const auto list = pass_map(sim.get());
        pf_stats st{};
        EXPECT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
        return double(list.at("pcg").dispatches) / st.substeps;
    };
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    const double first = pcg_dispatches_per_substep();
    EXPECT_GT(first, kPassesPerIteration * 400) << "nothing read back yet: the whole cap is issued";
    for (int i = 0; i < 6; ++i) {
        glFinish();  // lets the status readback of the previous step arrive
        ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    }
    const double later = pcg_dispatches_per_substep();
    glFinish();
    pf_stats st{};
    ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
    EXPECT_LT(later, kPassesPerIteration * (1.5 * st.solver_iterations + 4) + 30);
    EXPECT_LT(later, first / 4);
    EXPECT_LE(st.solver_residual, 1e-4f);
    RecordProperty("dispatches_first", std::to_string(first));
    RecordProperty("dispatches_later", std::to_string(later));
}

// The volume correction's solve, paired with the projection's (MGPCG without separation), issues
// what it needed in the step before too: both problems' needs read back, the pair issues the
// larger plus a margin. Before its need was read back the pair issued the correction's whole cap,
// 10 iterations (src/sim/volume_correction.h, kMaxKrylovIterations), in every projection the
// correction ran: leapfrog's, here, where it runs in each. An MGPCG solve's "mgpcg" entry is two
// passes an iteration (A p, the update) and five a solve besides (begin, right-hand side, start,
// final residual, report); measured over the last 5 of 15 steps.
TEST_F(PassStats, TheVolumeCorrectionsSolveIssuesWhatItNeeded) {
    pf_sim_desc d = test_desc(16, 16, 16, 0.05f);
    d.params.pressure_solver = PF_PRESSURE_SOLVER_MGPCG;
    d.params.separation = 0;
    d.params.volume_correction = 0.5f;
    d.params.advection = PF_ADVECTION_LEAPFROG;
    d.params.cfl = 8.0f;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.4f, 0.6f, 0.8f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    constexpr double kPassesPerIteration = 2.0, kPassesPerSolve = 5.0, kCorrectionCap = 10.0;
    double dispatches = 0, projections = 0;
    uint32_t most_iterations = 0;
    for (int i = 0; i < 15; ++i) {
        ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        if (i < 10) continue;
        pf_stats st{};
        ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
        const auto list = pass_map(sim.get());
        // Paired (the correction's own solve issues nothing) and run in every projection.
        EXPECT_EQ(list.at("volume_correction_solve").dispatches, 0u);
        EXPECT_EQ(list.at("volume_correction_move").dispatches, st.substeps);
        dispatches += double(list.at("mgpcg").dispatches);
        projections += st.substeps;
        most_iterations = std::max(most_iterations, st.solver_iterations);
    }
    const double per_projection = dispatches / projections;
    // The projection's own issue (its need plus 2) stays below the correction's cap.
    ASSERT_LE(most_iterations, 7u) << "a projection that needs this many would issue the cap by itself";
    EXPECT_LT(per_projection, kPassesPerIteration * kCorrectionCap + kPassesPerSolve) << most_iterations << " iterations";
    RecordProperty("mgpcg_dispatches_per_projection", std::to_string(per_projection));
}

// A stationary solver far from its tolerance skips its intermediate convergence checks: once a
// residual more than ten times the tolerance has been read back, 12 Jacobi sweeps cost 12 +
// start (2) + final check and report (4) dispatches per substep instead of 12 + 2 + 2 + 4.
TEST_F(PassStats, JacobiFarFromItsToleranceSkipsIntermediateChecks) {
    pf_sim_desc d = test_desc(16, 16, 16, 0.05f);
    d.params.pressure_solver = PF_PRESSURE_SOLVER_JACOBI;
    d.params.pressure_iterations = 12;
    d.params.pressure_tolerance = 1e-6f;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.8f, 0.4f, 0.8f}, v[3] = {2.0f, 0.0f, 1.0f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, v), PF_OK);
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    pf_stats st{};
    ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
    EXPECT_EQ(pass_map(sim.get()).at("jacobi").dispatches, st.substeps * (12 + 2 + 2 + 4)) << "nothing read back yet";
    glFinish();
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);
    ASSERT_GT(st.solver_residual, 10 * 1e-6f);
    EXPECT_EQ(pass_map(sim.get()).at("jacobi").dispatches, st.substeps * (12 + 2 + 4));
}

TEST_F(PassStats, BadArgumentsAreRefused) {
    SimPtr sim = create(test_desc(8, 8, 8));
    ASSERT_TRUE(sim);
    uint32_t n = 0;
    EXPECT_EQ(pf_get_pass_count(nullptr, &n), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_get_pass_count(sim.get(), nullptr), PF_ERROR_INVALID_ARGUMENT);
    ASSERT_EQ(pf_get_pass_count(sim.get(), &n), PF_OK);
    pf_pass_stats s{};
    EXPECT_EQ(pf_get_pass_stats(sim.get(), n, &s), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_get_pass_stats(sim.get(), 0xffffffffu, &s), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_get_pass_stats(sim.get(), 0, nullptr), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_get_pass_stats(nullptr, 0, &s), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_get_pass_stats(sim.get(), 0, &s), PF_OK);
    EXPECT_EQ(s.dispatches, 0u) << "no step yet";
}

}  // namespace
}  // namespace pf::test
