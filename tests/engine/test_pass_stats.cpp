// The runtime per-pass statistics list (pf_get_pass_count / pf_get_pass_stats): it names the
// core passes and the active solver's, its dispatch counts add up to pf_stats' fixed arrays,
// and bad arguments are refused.
#include <map>
#include <set>
#include <string>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class PassStats : public GpuTest {};

std::map<std::string, pf_pass_stats> pass_list(pf_sim* sim) {
    uint32_t n = 0;
    EXPECT_EQ(pf_get_pass_count(sim, &n), PF_OK);
    std::map<std::string, pf_pass_stats> out;
    for (uint32_t i = 0; i < n; ++i) {
        pf_pass_stats s{};
        EXPECT_EQ(pf_get_pass_stats(sim, i, &s), PF_OK);
        EXPECT_TRUE(out.emplace(s.name, s).second) << "name repeats: " << s.name;
    }
    return out;
}

TEST_F(PassStats, ListsCorePassesAndAddsUpToTheFixedArrays) {
    pf_sim_desc d = test_desc(16, 16, 16, 0.05f);
    d.params.pressure_iterations = 12;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.8f, 0.4f, 0.8f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    pf_stats st{};
    ASSERT_EQ(pf_get_stats(sim.get(), &st), PF_OK);

    const auto list = pass_list(sim.get());
    const std::set<std::string> core = {"clear",           "p2g",         "grid_forces", "classify", "pressure_setup",
                                        "velocity_update", "extrapolate", "g2p",         "advect",   "jacobi"};
    for (const std::string& name : core) EXPECT_EQ(list.count(name), 1u) << name;
    EXPECT_EQ(list.at("jacobi").group, PF_PASS_PRESSURE_SOLVE);
    EXPECT_EQ(list.at("jacobi").dispatches, st.substeps * d.params.pressure_iterations);
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
