// Nothing tunnels at one projection a frame: a jet at 8 m/s crosses 6.7 cells of 2 cm
// in a 1/60 s frame, traced in sub-steps of at most a cell. Against an obstacle one cell thick no
// particle may end inside it or beyond it, and against each of the six walls none may leave the
// domain; with Euler (the particle's own velocity), RK2 (the grid's), leapfrog (Euler's move in
// halves around the projection) and RK2_OFFSET (its own along the grid's path). A single move of
// several cells puts the jet's front beyond the obstacle in one frame, where the obstacles' push
// after advection never sees it.
#include <cmath>
#include <string>
#include <vector>

#include "support/sim_fixture.h"
#include "util.h"

namespace pf::test {
namespace {

constexpr float kDx = 0.02f;
constexpr float kSpeed = 8.0f;
constexpr float kFrame = 1.0f / 60.0f;

class Tunnelling : public GpuTest, public ::testing::WithParamInterface<pf_advection> {
protected:
    // 40 x 10 x 10 cells, no gravity, one projection a frame (the projection CFL far above the
    // 6.7 cells a frame the jet crosses).
    pf_sim_desc desc() const {
        pf_sim_desc d = test_desc(40, 10, 10, kDx);
        d.params.gravity[1] = 0.0f;
        d.params.cfl = 16.0f;
        d.params.max_substeps = 1;
        d.params.advection = GetParam();
        return d;
    }
    // The jet of 8 m/s aimed at a slab across the tank, one cell thick: x in [0.50, 0.52]
    // (cell 25); the slab in *slab, its id in *id.
    SimPtr jet_at_a_slab(pf_obstacle* slab, uint32_t* id) {
        pf_sim_desc d = desc();
        d.features = PF_FEATURE_OBSTACLES;
        SimPtr sim = create(d);
        if (!sim) return sim;
        *slab = pf_default_obstacle();
        slab->shape = PF_OBSTACLE_BOX;
        slab->position[0] = 0.51f, slab->position[1] = 0.1f, slab->position[2] = 0.1f;
        slab->half_extents[0] = 0.5f * kDx, slab->half_extents[1] = 0.2f, slab->half_extents[2] = 0.2f;
        EXPECT_EQ(pf_add_obstacle(sim.get(), slab, id), PF_OK) << last_log();
        const float lo[3] = {0.06f, 0.04f, 0.04f}, hi[3] = {0.26f, 0.16f, 0.16f}, v[3] = {kSpeed, 0.0f, 0.0f};
        EXPECT_EQ(pf_fill_box(sim.get(), lo, hi, v), PF_OK);
        return sim;
    }
};

TEST_P(Tunnelling, AJetStopsAtAnObstacleOneCellThick) {
    pf_obstacle slab;
    uint32_t id = 0;
    SimPtr sim = jet_at_a_slab(&slab, &id);
    ASSERT_TRUE(sim);
    ASSERT_FALSE(HasFailure());
    const size_t n = read_all(sim.get()).count();
    for (int f = 1; f <= 12; ++f) {
        ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
        ASSERT_EQ(settled_stats(sim.get()).substeps, 1u) << "one projection a frame";
        const ParticleState p = read_all(sim.get());
        ASSERT_EQ(p.count(), n);
        size_t inside = 0, beyond = 0;
        for (size_t i = 0; i < p.count(); ++i) {
            const float x = p.pos[i * 3];
            inside += x > 0.50f && x < 0.52f;
            beyond += x >= 0.52f;
        }
        EXPECT_EQ(inside, 0u) << "frame " << f;
        ASSERT_EQ(beyond, 0u) << "frame " << f << ": particles tunnelled through the slab";
    }
}

// Every move stops before SOLID cells, a leapfrog step's first half move (3.3 cells here) too,
// which takes them from the obstacles as they stand, not from the cells the step before left.
// Saved after 2 frames and run 4 more; then the slab is moved across the jet's path, a frame
// stepped, the snapshot restored and 4 frames run again: the same particles, bit for bit.
TEST_P(Tunnelling, ARestoredJetContinuesAsTheOriginal) {
    pf_obstacle slab;
    uint32_t id = 0;
    SimPtr sim = jet_at_a_slab(&slab, &id);
    ASSERT_TRUE(sim);
    ASSERT_FALSE(HasFailure());
    const auto frames = [&](int n) {
        for (int f = 0; f < n; ++f) ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
    };
    frames(2);
    size_t size = 0;
    ASSERT_EQ(pf_snapshot_size(sim.get(), &size), PF_OK);
    std::vector<uint8_t> snap(size);
    ASSERT_EQ(pf_save_snapshot(sim.get(), snap.data(), snap.size()), PF_OK) << last_log();
    frames(4);
    const ParticleState original = read_all(sim.get());
    slab.position[0] = 0.31f;
    ASSERT_EQ(pf_set_obstacle(sim.get(), id, &slab), PF_OK) << last_log();
    frames(1);
    ASSERT_EQ(pf_restore_snapshot(sim.get(), snap.data(), snap.size()), PF_OK) << last_log();
    frames(4);
    const ParticleState again = read_all(sim.get());
    ASSERT_EQ(again.pos.size(), original.pos.size());
    size_t differ = 0;
    for (size_t k = 0; k < again.pos.size(); ++k) differ += again.pos[k] != original.pos[k];
    EXPECT_EQ(differ, 0u) << "floats differing from the original continuation";
}

TEST_P(Tunnelling, AJetAtEachWallStaysInTheDomain) {
    const pf_sim_desc d = desc();
    const float extent[3] = {40 * kDx, 10 * kDx, 10 * kDx};
    for (int wall = 0; wall < 6; ++wall) {
        const int axis = wall / 2;
        const float sign = wall % 2 ? 1.0f : -1.0f;
        SimPtr sim = create(d);
        ASSERT_TRUE(sim);
        float lo[3], hi[3], v[3] = {0, 0, 0};
        for (int a = 0; a < 3; ++a) lo[a] = 0.3f * extent[a], hi[a] = 0.7f * extent[a];
        v[axis] = sign * kSpeed;
        ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, v), PF_OK);
        for (int f = 1; f <= 8; ++f) {
            ASSERT_EQ(pf_step(sim.get(), kFrame), PF_OK);
            const ParticleState p = read_all(sim.get());
            size_t outside = 0;
            for (size_t i = 0; i < p.count(); ++i)
                for (int a = 0; a < 3; ++a) outside += !(p.pos[i * 3 + a] > 0.0f && p.pos[i * 3 + a] < extent[a]);
            ASSERT_EQ(outside, 0u) << "wall " << wall << ", frame " << f;
        }
    }
}

std::string scheme_name(const ::testing::TestParamInfo<pf_advection>& info) { return pfs::advection_name(info.param); }
INSTANTIATE_TEST_SUITE_P(Schemes, Tunnelling, ::testing::Values(PF_ADVECTION_EULER, PF_ADVECTION_RK2, PF_ADVECTION_LEAPFROG,
                                                              PF_ADVECTION_RK2_OFFSET),
                         scheme_name);

}  // namespace
}  // namespace pf::test
