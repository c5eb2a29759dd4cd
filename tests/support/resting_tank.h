// The tank at rest that the tests of effects which must leave still liquid still share: 12^3
// cells of 10 cm, filled to half its height, stepped at 1/60 s.
#pragma once
#include <algorithm>
#include <string>

#include "support/sim_fixture.h"

namespace pf::test {

struct RestingTank {
    double max_speed = 0.0;  // largest particle speed, m/s, sampled every 60 frames
    bool entry_ran = false;  // the pass-list entry named dispatched in the last step
};

// `frames` frames with `features` on, after configure(sim) set the effect's parameters.
template <class Configure>
RestingTank step_resting_tank(uint32_t features, int frames, const char* entry, Configure&& configure) {
    pf_sim_desc d = test_desc(12, 12, 12, 0.1f);
    d.features = features;
    pf_sim* raw = nullptr;
    EXPECT_EQ(pf_create(&d, &raw), PF_OK) << last_log();
    const SimPtr sim(raw);
    RestingTank out;
    if (!sim) return out;
    configure(sim.get());
    const float lo[3] = {0, 0, 0}, hi[3] = {1.2f, 0.6f, 1.2f};
    EXPECT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    for (int f = 1; f <= frames; ++f) {
        EXPECT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        if (f % 60 == 0) out.max_speed = std::max(out.max_speed, max_speed_of(read_all(sim.get())));
    }
    for (const pf_pass_stats& s : pass_list(sim.get())) out.entry_ran = out.entry_ran || (std::string(s.name) == entry && s.dispatches > 0);
    return out;
}

}  // namespace pf::test
