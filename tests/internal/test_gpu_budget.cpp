// pf_set_gpu_budget with an injected time source (llvmpipe's timer queries read 0): the step
// takes the substeps that fit the budget and says so with PF_FLAG_BUDGET_LIMITED, caps the
// solver's iterations when one substep does not fit, and with no budget runs as before.
#include "api/handle.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class GpuBudget : public GpuTest {
protected:
    // A dam break fast enough at frame 10 for the CFL to want several substeps of 1/30 s.
    SimPtr dam_break() {
        pf_sim_desc d = test_desc(24, 16, 8, 0.05f);
        d.params.cfl = 1.0f;  // several projections a frame at this speed
        SimPtr sim = create(d);
        const float lo[3] = {0, 0, 0}, hi[3] = {0.4f, 0.6f, 0.4f};
        EXPECT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
        for (int f = 0; f < 10; ++f) EXPECT_EQ(pf_step(sim.get(), kFrame), PF_OK);
        return sim;
    }
    static pf_stats stats(pf_sim* sim) {
        pf_stats st{};
        st.struct_size = sizeof st;
        EXPECT_EQ(pf_get_stats(sim, &st), PF_OK);
        return st;
    }
    static void inject(pf_sim* sim, MeasuredStep m) {
        pf::entry(sim)->impl->set_step_time_source_for_test([m] { return m; });
    }
    static constexpr float kFrame = 1.0f / 30.0f;
};

TEST_F(GpuBudget, TakesTheSubstepsThatFitAndSaysSo) {
    SimPtr sim = dam_break();
    ASSERT_TRUE(sim);
    const uint32_t wanted = pf::entry(sim.get())->impl->substeps_for(kFrame).count;
    ASSERT_GE(wanted, 3u) << "the scene must want several substeps";
    // 2 ms a substep measured; a 4 ms budget fits two.
    inject(sim.get(), MeasuredStep{5, 2, 4.0f, 2.0f, 8});
    ASSERT_EQ(pf_set_gpu_budget(sim.get(), 4.0f), PF_OK);
    float got = 0;
    ASSERT_EQ(pf_get_gpu_budget(sim.get(), &got), PF_OK);
    EXPECT_EQ(got, 4.0f);
    ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    const pf_stats st = stats(sim.get());
    EXPECT_EQ(st.substeps, 2u);
    EXPECT_TRUE(st.flags & PF_FLAG_BUDGET_LIMITED);
    EXPECT_FALSE(st.flags & PF_FLAG_SUBSTEPS_CLAMPED) << "the physics did not ask for more than max_substeps";

    // A budget that fits everything: the CFL's substeps, no new flag.
    ASSERT_EQ(pf_clear_flags(sim.get()), PF_OK);
    ASSERT_EQ(pf_set_gpu_budget(sim.get(), 100.0f), PF_OK);
    ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    EXPECT_GE(stats(sim.get()).substeps, 3u);
    EXPECT_FALSE(stats(sim.get()).flags & PF_FLAG_BUDGET_LIMITED);
}

TEST_F(GpuBudget, NoBudgetStepsAsBefore) {
    SimPtr a = dam_break(), b = dam_break();
    ASSERT_TRUE(a && b);
    inject(b.get(), MeasuredStep{5, 2, 40.0f, 20.0f, 8});  // times that a budget would act on
    ASSERT_EQ(pf_set_gpu_budget(b.get(), 0.0f), PF_OK);
    for (int f = 0; f < 3; ++f) {
        ASSERT_EQ(pf_step(a.get(), kFrame), PF_OK);
        ASSERT_EQ(pf_step(b.get(), kFrame), PF_OK);
    }
    const ParticleState pa = read_all(a.get()), pb = read_all(b.get());
    EXPECT_EQ(pa.pos, pb.pos) << "without a budget the injected times change nothing";
    EXPECT_FALSE(stats(b.get()).flags & PF_FLAG_BUDGET_LIMITED);
}

TEST_F(GpuBudget, WhenOneSubstepDoesNotFitTheSolveIsCapped) {
    SimPtr sim = dam_break();
    ASSERT_TRUE(sim);
    pf_sim_params p = sized_params();
    ASSERT_EQ(pf_get_params(sim.get(), &p), PF_OK);
    p.pressure_tolerance = 1e-6f;  // more iterations than the cap leaves, whatever the flow
    ASSERT_EQ(pf_set_params(sim.get(), &p), PF_OK);
    // A substep: 2 ms, its solve 1.5 ms over 10 iterations; 1 ms leaves the solve 3 iterations.
    inject(sim.get(), MeasuredStep{5, 1, 2.0f, 1.5f, 10});
    ASSERT_EQ(pf_set_gpu_budget(sim.get(), 1.0f), PF_OK);
    ASSERT_EQ(pf_clear_flags(sim.get()), PF_OK);
    for (int f = 0; f < 3; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    const pf_stats st = settled_stats(sim.get());
    EXPECT_EQ(st.substeps, 1u);
    EXPECT_LE(st.solver_iterations, 3u);
    EXPECT_GT(st.solver_residual, p.pressure_tolerance);
    EXPECT_TRUE(st.flags & PF_FLAG_BUDGET_LIMITED);
}

TEST_F(GpuBudget, BadBudgetsAreRefusedAndChangeNothing) {
    SimPtr sim = dam_break();
    ASSERT_TRUE(sim);
    ASSERT_EQ(pf_set_gpu_budget(sim.get(), 3.0f), PF_OK);
    for (float bad : {-1.0f, NAN, INFINITY, 2e4f}) {
        clear_log();
        EXPECT_EQ(pf_set_gpu_budget(sim.get(), bad), PF_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(std::string(last_log()).find("pf_set_gpu_budget"), std::string::npos);
    }
    float got = 0;
    ASSERT_EQ(pf_get_gpu_budget(sim.get(), &got), PF_OK);
    EXPECT_EQ(got, 3.0f);
    EXPECT_EQ(pf_get_gpu_budget(sim.get(), nullptr), PF_ERROR_INVALID_ARGUMENT);
    // The budget needs the step's times: timing cannot go off under it, nor a budget start without it.
    EXPECT_EQ(pf_set_gpu_timing(sim.get(), PF_GPU_TIMING_OFF), PF_ERROR_INVALID_ARGUMENT);
    ASSERT_EQ(pf_set_gpu_budget(sim.get(), 0.0f), PF_OK);
    ASSERT_EQ(pf_set_gpu_timing(sim.get(), PF_GPU_TIMING_OFF), PF_OK);
    EXPECT_EQ(pf_set_gpu_budget(sim.get(), 2.0f), PF_ERROR_INVALID_ARGUMENT);
    ASSERT_EQ(pf_get_gpu_budget(sim.get(), &got), PF_OK);
    EXPECT_EQ(got, 0.0f);
    EXPECT_EQ(pf_step(sim.get(), kFrame), PF_OK) << "the simulation stays usable";
}

}  // namespace
}  // namespace pf::test
