// Case 9 (docs/stability.md): a long run — a sloshing tank for 10,000 steps: energy bounded by
// its start (nothing drives it after the initial tilt), volume within the loss limit, no
// particle lost. CI's fast mode runs 10,000 steps with the default (balanced) preset and 1,000
// with the others (to keep CI short); the long mode (PF_STABILITY_LONG set) runs 10,000 with every
// preset, and PF_STABILITY_LONG=<steps> above 1 that many (e.g. 1000000, by hand).
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "stability/stability.h"

namespace pf::test {
namespace {

class LongRun : public Stability {};

TEST_P(LongRun, SloshingTankForTenThousandSteps) {
    const char* env = std::getenv("PF_STABILITY_LONG");
    const long requested = env ? std::atol(env) : 0;
    const long steps = requested > 1 ? requested : (long_mode() || GetParam() == PF_QUALITY_BALANCED ? 10000 : 1000);
    // A small tank (8 x 8 x 4 cells of 0.1 m) keeps 10,000 steps within seconds on llvmpipe.
    const pf_sim_desc d = desc(8, 8, 4, 0.1f);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    // A tilted surface: the left half fuller than the right, so it sloshes.
    const float lo[3] = {0, 0, 0}, left[3] = {0.4f, 0.5f, 0.4f}, lo2[3] = {0.4f, 0, 0}, right[3] = {0.8f, 0.3f, 0.4f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, left, nullptr), PF_OK);
    ASSERT_EQ(pf_fill_box(sim.get(), lo2, right, nullptr), PF_OK);
    const size_t n = settled_stats(sim.get()).particle_count;
    const Soundness start = check(sim.get(), d, n, "start");
    const double rest = double(n) / d.fill_particles_per_cell * std::pow(double(d.cell_size), 3);
    double worst_energy = 0, worst_loss = 0, worst_liquid_loss = 0;
    for (long s = 1; s <= steps; ++s) {
        const pf_result r = pf_step(sim.get(), 1.0f / 60.0f);
        ASSERT_EQ(r, PF_OK) << "step " << s;
        if (s % 1000 && s != steps) continue;
        const Soundness now = check(sim.get(), d, n, "step " + std::to_string(s));
        if (HasFailure()) return;
        worst_energy = std::max(worst_energy, now.energy.total() / start.energy.total());
        worst_loss = std::max(worst_loss, 1.0 - now.volume / rest);
        worst_liquid_loss = std::max(worst_liquid_loss, 1.0 - now.liquid / rest);
    }
    const pf_stats st = settled_stats(sim.get());
    record("steps", double(steps));
    record("energy_max_over_start", worst_energy);
    record("volume_loss_max", worst_loss);
    record("liquid_volume_loss_max", worst_liquid_loss);
    // Checked every 1000 steps (16.7 s): energy never above the start, volume within the
    // loss limit, and the library's own detectors quiet.
    EXPECT_LT(worst_energy, 1.0);
    EXPECT_LT(worst_loss, double(d.params.volume_loss_limit));  // the capped count sum: the stricter
    EXPECT_LT(worst_liquid_loss, double(d.params.volume_loss_limit));
    EXPECT_EQ(st.flags & (PF_FLAG_ENERGY_GAINED | PF_FLAG_VOLUME_LOST | PF_FLAG_NONFINITE), 0u);
}

PF_STABILITY_PRESETS(LongRun);

}  // namespace
}  // namespace pf::test
