// pf_set_gpu_timing: each mode times what pf.h says — every pass group, the step as a whole
// (pf_stats.gpu_total_ms only), or nothing — while the dispatch counts stay; switching forgets
// the old times; every kernel may be counted and timed apart; unknown modes are refused with
// nothing changed.
#include <string>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class GpuTiming : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        pf_sim_desc d = test_desc(16, 8, 8, 0.1f);
        sim_ = create(d);
        ASSERT_TRUE(sim_);
        const float lo[3] = {0, 0, 0}, hi[3] = {0.6f, 0.6f, 0.8f};
        ASSERT_EQ(pf_fill_box(sim_.get(), lo, hi, nullptr), PF_OK);
    }
    // Steps until a step of the current mode has been read back (the timer ring lags a few
    // steps), at most 40; the stats then.
    pf_stats step_until_measured() {
        pf_stats st{};
        st.struct_size = sizeof st;
        for (int i = 0; i < 40; ++i) {
            EXPECT_EQ(pf_step(sim_.get(), 1.0f / 60.0f), PF_OK);
            pass_times();  // polls the timers
            EXPECT_EQ(pf_get_stats(sim_.get(), &st), PF_OK);
            if (i >= 4 && st.gpu_step > 0) break;
        }
        return st;
    }
    // Sum of the pass list's gpu_ms, and whether any entry dispatched.
    std::pair<double, bool> pass_times() {
        double sum = 0;
        bool dispatched = false;
        for (const pf_pass_stats& s : pass_list(sim_.get())) {
            sum += s.gpu_ms;
            dispatched = dispatched || s.dispatches > 0;
        }
        return {sum, dispatched};
    }
    static double group_sum(const pf_stats& st) {
        double sum = 0;
        for (int k = 0; k < PF_PASS_COUNT; ++k) sum += st.gpu_ms[k];
        return sum;
    }
    SimPtr sim_;
};

TEST_F(GpuTiming, EachModeTimesWhatItSays) {
    pf_gpu_timing mode = PF_GPU_TIMING_OFF;
    ASSERT_EQ(pf_get_gpu_timing(sim_.get(), &mode), PF_OK);
    EXPECT_EQ(mode, PF_GPU_TIMING_PASSES) << "the default";
    const pf_stats passes = step_until_measured();
    if (passes.gpu_step == 0) GTEST_SKIP() << "this GL reports no GL_TIMESTAMP bits";
    EXPECT_GT(passes.gpu_total_ms, 0.0f);
    EXPECT_NEAR(group_sum(passes), passes.gpu_total_ms, 1e-3 * passes.gpu_total_ms);
    EXPECT_GT(pass_times().first, 0.0);

    // The whole step: the total only.
    ASSERT_EQ(pf_set_gpu_timing(sim_.get(), PF_GPU_TIMING_STEP), PF_OK);
    pf_stats st{};
    st.struct_size = sizeof st;
    ASSERT_EQ(pf_get_stats(sim_.get(), &st), PF_OK);
    EXPECT_EQ(st.gpu_step, 0u) << "the per-pass times are forgotten";
    EXPECT_EQ(st.gpu_total_ms, 0.0f);
    const pf_stats step = step_until_measured();
    ASSERT_GT(step.gpu_step, passes.gpu_step);
    EXPECT_GT(step.gpu_total_ms, 0.0f);
    EXPECT_EQ(group_sum(step), 0.0);
    const auto [step_pass_sum, step_dispatched] = pass_times();
    EXPECT_EQ(step_pass_sum, 0.0);
    EXPECT_TRUE(step_dispatched);
    EXPECT_GT(step.dispatches[PF_PASS_PRESSURE_SOLVE], 0u);

    // Nothing timed: every GPU time 0, the dispatches still counted.
    ASSERT_EQ(pf_set_gpu_timing(sim_.get(), PF_GPU_TIMING_OFF), PF_OK);
    const pf_stats off = step_until_measured();
    EXPECT_EQ(off.gpu_step, 0u);
    EXPECT_EQ(off.gpu_total_ms, 0.0f);
    EXPECT_EQ(group_sum(off), 0.0);
    EXPECT_EQ(pass_times().first, 0.0);
    EXPECT_TRUE(pass_times().second);
    EXPECT_GT(off.dispatches[PF_PASS_PRESSURE_SOLVE], 0u);

    // And back: per pass again.
    ASSERT_EQ(pf_set_gpu_timing(sim_.get(), PF_GPU_TIMING_PASSES), PF_OK);
    const pf_stats again = step_until_measured();
    EXPECT_GT(again.gpu_step, step.gpu_step);
    EXPECT_NEAR(group_sum(again), again.gpu_total_ms, 1e-3 * again.gpu_total_ms);
    EXPECT_GT(again.gpu_total_ms, 0.0f);
}

// Per kernel: every dispatch is counted (and timed) under "<entry>:<kernel>", added to the pass
// list on first use; the entries' dispatches add up to the step's, names handed out before stay
// valid while the list grows, and switching back counts per entry again.
TEST_F(GpuTiming, KernelsAreCountedApart) {
    ASSERT_EQ(pf_step(sim_.get(), 1.0f / 60.0f), PF_OK);
    const std::vector<pf_pass_stats> before = pass_list(sim_.get());
    ASSERT_FALSE(before.empty());
    const char* first_name = before.front().name;
    const std::string first = first_name;

    ASSERT_EQ(pf_set_gpu_timing(sim_.get(), PF_GPU_TIMING_KERNELS), PF_OK);
    pf_gpu_timing mode = PF_GPU_TIMING_PASSES;
    ASSERT_EQ(pf_get_gpu_timing(sim_.get(), &mode), PF_OK);
    EXPECT_EQ(mode, PF_GPU_TIMING_KERNELS);
    ASSERT_EQ(pf_step(sim_.get(), 1.0f / 60.0f), PF_OK);
    pf_stats st{};
    st.struct_size = sizeof st;
    ASSERT_EQ(pf_get_stats(sim_.get(), &st), PF_OK);
    uint64_t step_dispatches = 0;
    for (int k = 0; k < PF_PASS_COUNT; ++k) step_dispatches += st.dispatches[k];
    ASSERT_GT(step_dispatches, 0u);

    const std::vector<pf_pass_stats> list = pass_list(sim_.get());
    EXPECT_GT(list.size(), before.size());
    EXPECT_EQ(std::string(first_name), first) << "a name handed out before the list grew";
    uint64_t kernel_dispatches = 0, entry_dispatches = 0;
    bool saw_solver_kernel = false;
    for (const pf_pass_stats& s : list) {
        const std::string name = s.name;
        const size_t colon = name.find(':');
        if (colon == std::string::npos) {
            entry_dispatches += s.dispatches;
            continue;
        }
        kernel_dispatches += s.dispatches;
        // The entry it belongs to is in the list, in the same group.
        bool parent = false;
        for (const pf_pass_stats& p : list) parent = parent || (name.compare(0, colon, p.name) == 0 && p.group == s.group && std::string(p.name).size() == colon);
        EXPECT_TRUE(parent) << name;
        saw_solver_kernel = saw_solver_kernel || (s.group == PF_PASS_PRESSURE_SOLVE && s.dispatches > 0);
    }
    EXPECT_EQ(entry_dispatches, 0u) << "every dispatch is counted under its kernel";
    EXPECT_EQ(kernel_dispatches, step_dispatches);
    EXPECT_TRUE(saw_solver_kernel);

    // Back to pass groups: the kernel entries stay listed but dispatch nothing.
    ASSERT_EQ(pf_set_gpu_timing(sim_.get(), PF_GPU_TIMING_PASSES), PF_OK);
    ASSERT_EQ(pf_step(sim_.get(), 1.0f / 60.0f), PF_OK);
    for (const pf_pass_stats& s : pass_list(sim_.get())) {
        if (std::string(s.name).find(':') != std::string::npos) EXPECT_EQ(s.dispatches, 0u) << s.name;
    }
}

// The bits a C caller passes (engine/api_c_compile.c: C converts any bits to the enum, where C++
// may not load a value beyond its range).
extern "C" pf_result pf_test_c_set_gpu_timing_bits(pf_sim* sim, unsigned bits);

TEST_F(GpuTiming, UnknownModesAreRefusedAndChangeNothing) {
    ASSERT_EQ(pf_set_gpu_timing(sim_.get(), PF_GPU_TIMING_STEP), PF_OK);
    for (uint32_t bits : {4u, 0x7fffffffu, 0xffffffffu}) {
        clear_log();
        EXPECT_EQ(pf_test_c_set_gpu_timing_bits(sim_.get(), bits), PF_ERROR_INVALID_ARGUMENT) << bits;
        EXPECT_NE(std::string(last_log()).find("not a pf_gpu_timing"), std::string::npos) << last_log();
        pf_gpu_timing now = PF_GPU_TIMING_PASSES;
        ASSERT_EQ(pf_get_gpu_timing(sim_.get(), &now), PF_OK);
        EXPECT_EQ(now, PF_GPU_TIMING_STEP);
    }
    EXPECT_EQ(pf_get_gpu_timing(sim_.get(), nullptr), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_set_gpu_timing(nullptr, PF_GPU_TIMING_OFF), PF_ERROR_INVALID_ARGUMENT);
    ASSERT_EQ(pf_step(sim_.get(), 1.0f / 60.0f), PF_OK);
}

}  // namespace
}  // namespace pf::test
