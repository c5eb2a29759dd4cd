// A CPU upload (glBufferSubData) over data a compute pass wrote must land after that write:
// pf_add_particles zeroes APIC's affine vectors with a compute clear, and a later upload of the
// same buffer must keep the uploaded values. (NVIDIA lost the upload while Mesa llvmpipe kept
// it, even with every barrier bit set before the upload; only glFinish helped. gl::Buffer's
// upload now stages the data and copies it on the GPU's timeline.)
#include <cstring>
#include <random>

#include "api/handle.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class UploadOrder : public GpuTest {};

TEST_F(UploadOrder, UploadAfterAComputeClearKeepsTheUploadedValues) {
    constexpr int kParticles = 3000;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u01(0.05f, 0.95f);
    std::vector<float> pos, affine(size_t(kParticles) * 12);
    for (int i = 0; i < kParticles * 3; ++i) pos.push_back(0.5f * u01(rng));
    for (float& a : affine) a = u01(rng);
    {
        pf_sim_desc d = test_desc(10, 10, 10, 0.05f);
        d.params.transfer = PF_TRANSFER_APIC;
        d.max_particles = kParticles;
        SimPtr handle = create(d);
        ASSERT_TRUE(handle);
        Simulation& sim = *pf::entry(handle)->impl;
        ASSERT_EQ(pf_add_particles(handle.get(), pos.data(), nullptr, kParticles), PF_OK);  // clears the vectors
        sim.write_affine_for_test(affine);
        const std::vector<float> stored = sim.read_affine();
        ASSERT_EQ(stored.size(), affine.size());
        size_t differ = 0;
        for (size_t k = 0; k < stored.size(); ++k) differ += std::memcmp(&stored[k], &affine[k], 4) != 0;
        EXPECT_EQ(differ, 0u) << "of " << stored.size() << " words";
    }
}

}  // namespace
}  // namespace pf::test
