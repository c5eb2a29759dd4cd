// The APIC affine vectors as particle state: allocated only when APIC is first used, zero for
// every particle added (C = 0 is plain PIC for its first transfer), zeroed for all live
// particles whenever the transfer switches to APIC (vectors left from an earlier APIC period
// no longer match the velocities), written by APIC's G2P and left alone by pf_push.
#include <algorithm>
#include <cmath>

#include "api/handle.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class ApicState : public GpuTest {
protected:
    static bool all_zero(const std::vector<float>& v) {
        return std::all_of(v.begin(), v.end(), [](float x) { return x == 0.0f; });
    }
    static float largest(const std::vector<float>& v) {
        float m = 0.0f;
        for (float x : v) m = std::max(m, std::abs(x));
        return m;
    }
    static void set_transfer(pf_sim* sim, pf_transfer transfer) {
        pf_sim_params p = sized_params();
        ASSERT_EQ(pf_get_params(sim, &p), PF_OK);
        p.transfer = transfer;
        ASSERT_EQ(pf_set_params(sim, &p), PF_OK) << last_log();
    }
};

TEST_F(ApicState, AffineVectorsStartAtZeroAndFollowTheTransfer) {
    SimPtr handle = create(test_desc(10, 10, 10, 0.05f));
    ASSERT_TRUE(handle);
    Simulation& sim = *pf::entry(handle)->impl;
    const float lo[3] = {0.1f, 0.05f, 0.1f}, hi[3] = {0.35f, 0.3f, 0.3f}, v[3] = {0.4f, 0.0f, 0.0f};
    ASSERT_EQ(pf_fill_box(handle.get(), lo, hi, v), PF_OK);
    const uint32_t n = uint32_t(read_all(handle.get()).count());
    for (int f = 0; f < 3; ++f) ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
    EXPECT_TRUE(sim.read_affine().empty()) << "PIC/FLIP alone must not allocate the affine buffer";

    set_transfer(handle.get(), PF_TRANSFER_APIC);
    std::vector<float> c = sim.read_affine();
    ASSERT_EQ(c.size(), size_t(n) * 12);
    EXPECT_TRUE(all_zero(c));
    // A falling, sliding block has velocity gradients at its surface: G2P writes them.
    for (int f = 0; f < 3; ++f) ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
    c = sim.read_affine();
    EXPECT_GT(largest(c), 0.1f);
    for (float x : c) ASSERT_TRUE(std::isfinite(x));

    // pf_push changes v only.
    const float centre[3] = {0.2f, 0.15f, 0.2f}, dv[3] = {0.0f, 1.0f, 0.0f};
    ASSERT_EQ(pf_push(handle.get(), centre, 0.2f, dv), PF_OK);
    EXPECT_EQ(sim.read_affine(), c);

    // Particles added under APIC start at zero; the others keep theirs.
    const float extra[3] = {0.4f, 0.4f, 0.4f};
    ASSERT_EQ(pf_add_particles(handle.get(), extra, nullptr, 1), PF_OK);
    std::vector<float> more = sim.read_affine();
    ASSERT_EQ(more.size(), size_t(n + 1) * 12);
    EXPECT_TRUE(std::equal(c.begin(), c.end(), more.begin()));
    EXPECT_TRUE(all_zero(std::vector<float>(more.end() - 12, more.end())));

    // Leaving APIC and coming back starts again from zero.
    set_transfer(handle.get(), PF_TRANSFER_PIC_FLIP);
    ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
    EXPECT_FALSE(all_zero(sim.read_affine())) << "PIC/FLIP steps do not touch C";
    set_transfer(handle.get(), PF_TRANSFER_APIC);
    EXPECT_TRUE(all_zero(sim.read_affine()));

    // After pf_clear_particles the slots are reused with C = 0.
    ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
    ASSERT_EQ(pf_clear_particles(handle.get()), PF_OK);
    EXPECT_TRUE(sim.read_affine().empty());
    ASSERT_EQ(pf_fill_box(handle.get(), lo, hi, v), PF_OK);
    c = sim.read_affine();
    ASSERT_EQ(c.size(), size_t(n) * 12);
    EXPECT_TRUE(all_zero(c));
}

}  // namespace
}  // namespace pf::test
