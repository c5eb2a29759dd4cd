// Case 2 (docs/stability.md): a 30 m/s jet slamming into a wall and into a corner. A nozzle
// adds particles every frame, so the energy bound is the start plus everything the nozzle put
// in (kinetic and potential): impacts, the projection and the walls only take energy away.
#include <cmath>

#include "stability/stability.h"

namespace pf::test {
namespace {

class Jet : public Stability {
protected:
    // Shoots `frames` frames of a 2x2-cell nozzle at `speed` m/s along `dir` (unit) from near the
    // -x wall of a 16 x 8 x 8 tank of 0.1 m cells.
    void shoot(const float dir[3], float speed, int frames) {
        pf_sim_desc d = desc(16, 8, 8, 0.1f);
        d.max_particles = 40000;
        SimPtr sim = create(d);
        ASSERT_TRUE(sim);
        const double m = particle_mass(d);
        double injected = 0;  // J
        size_t n = 0;
        double worst_ratio = 0;
        for (int f = 1; f <= frames; ++f) {
            // One slab of nozzle particles per frame, at 8 per cell: 2 x 2 cells, 1 cell deep.
            std::vector<float> pos, vel;
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 4; ++j)
                    for (int k = 0; k < 4; ++k) {
                        const float p[3] = {0.05f + 0.05f * float(i) + 0.025f, 0.3f + 0.05f * float(j) + 0.025f,
                                            0.3f + 0.05f * float(k) + 0.025f};
                        for (int a = 0; a < 3; ++a) {
                            pos.push_back(p[a]);
                            vel.push_back(speed * dir[a]);
                        }
                        // Kinetic plus potential (height above the floor, gravity -y).
                        injected += m * (0.5 * double(speed) * speed + 9.81 * p[1]);
                    }
            const uint32_t batch = uint32_t(pos.size() / 3);
            ASSERT_EQ(pf_add_particles(sim.get(), pos.data(), vel.data(), batch), PF_OK) << last_log();
            n += batch;
            ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 1));
            const Soundness s = check(sim.get(), d, n, "frame " + std::to_string(f));
            worst_ratio = std::max(worst_ratio, s.energy.total() / injected);
            if (HasFailure()) return;
        }
        record("energy_max_over_injected", worst_ratio);
        EXPECT_LT(worst_ratio, 1.0) << "the jet's liquid gained energy";
        // Then the nozzle stops and the tank settles: nothing is lost, and all of it is sound.
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 30));
        check(sim.get(), d, n, "settled");
        expect_usable(sim.get(), d, "after the jet");
    }
};

TEST_P(Jet, IntoAWall) {
    const float dir[3] = {1.0f, 0.0f, 0.0f};
    shoot(dir, 30.0f, 24);
}

TEST_P(Jet, IntoACorner) {
    const float s = 1.0f / std::sqrt(3.0f);
    const float dir[3] = {s, s, s};
    shoot(dir, 30.0f, 24);
}

PF_STABILITY_PRESETS(Jet);

}  // namespace
}  // namespace pf::test
