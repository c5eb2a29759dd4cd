// The effects mechanism as an engine sees it (docs/design.md §9): with every effect off the
// per-pass list is exactly the core step's; turning an effect on adds its own passes and no
// other, and changes no core pass's dispatch count; pf_set_features keeps every particle;
// unknown feature bits are refused with nothing changed.
#include <map>
#include <string>
#include <vector>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class Effects : public GpuTest {};

std::vector<std::string> names(const std::vector<pf_pass_stats>& list) {
    std::vector<std::string> out;
    for (const pf_pass_stats& e : list) out.push_back(e.name);
    return out;
}

// A small tank with one obstacle, force field, emitter and sink and a turning domain, present
// whatever is on.
SimPtr make_scene(Effects& t, uint32_t features) {
    pf_sim_desc d = test_desc(16, 16, 16, 0.05f);
    d.features = features;
    d.params.pressure_iterations = 12;
    pf_sim* raw = nullptr;
    EXPECT_EQ(pf_create(&d, &raw), PF_OK) << last_log();
    SimPtr sim(raw);
    (void)t;
    if (!sim) return sim;
    const float lo[3] = {0, 0, 0}, hi[3] = {0.8f, 0.4f, 0.8f};
    EXPECT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    pf_obstacle o = pf_default_obstacle();
    o.shape = PF_OBSTACLE_SPHERE;
    o.position[0] = 0.4f, o.position[1] = 0.6f, o.position[2] = 0.4f;
    EXPECT_EQ(pf_add_obstacle(sim.get(), &o, nullptr), PF_OK);
    pf_force_field f = pf_default_force_field();
    f.vector[0] = 1.0f;
    EXPECT_EQ(pf_add_force_field(sim.get(), &f, nullptr), PF_OK);
    pf_emitter e = pf_default_emitter();
    e.position[0] = 0.2f, e.position[1] = 0.6f, e.position[2] = 0.2f;
    e.radius = 0.05f;
    e.rate = 600.0f;  // 10 particles a frame at 60 Hz
    EXPECT_EQ(pf_add_emitter(sim.get(), &e, nullptr), PF_OK);
    pf_sink k = pf_default_sink();
    k.position[0] = 0.05f, k.position[1] = 0.05f, k.position[2] = 0.05f;
    k.half_extents[0] = k.half_extents[1] = k.half_extents[2] = 0.05f;
    EXPECT_EQ(pf_add_sink(sim.get(), &k, nullptr), PF_OK);
    pf_domain_motion m = pf_default_domain_motion();
    m.angular_velocity[1] = 0.5f;
    EXPECT_EQ(pf_set_domain_motion(sim.get(), &m), PF_OK);
    return sim;
}

// The core step's list, in order: the core passes, the metrics, the hydrostatic start, the free
// surface and the wall release, then
// the default P2G scheme's sort, the default solver's entries (MGPCG and its V-cycle), then the
// volume correction's.
const std::vector<std::string> kCoreList = {"clear",       "p2g", "grid_forces", "classify", "pressure_setup",
                                            "velocity_update", "extrapolate", "g2p", "advect", "metrics",
                                            "hydrostatic_start", "free_surface", "wall_release", "p2g_tile_sort", "mgpcg", "mgpcg/precondition",
                                            "volume_correction_setup", "volume_correction_solve",
                                            "volume_correction_move"};

TEST_F(Effects, EveryEffectOffListsExactlyTheCorePasses) {
    SimPtr sim = make_scene(*this, 0);
    ASSERT_TRUE(sim);
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    EXPECT_EQ(names(pass_list(sim.get())), kCoreList);
}

TEST_F(Effects, EachEffectAddsOnlyItsOwnPasses) {
    struct Case {
        uint32_t feature;
        std::vector<std::string> added;
    };
    const SimPtr off = make_scene(*this, 0);
    ASSERT_TRUE(off);
    ASSERT_EQ(pf_step(off.get(), 1.0f / 60.0f), PF_OK);
    const std::vector<pf_pass_stats> core = pass_list(off.get());
    for (const Case& c : {Case{PF_FEATURE_FORCE_FIELDS, {"force_fields"}},
                          Case{PF_FEATURE_OBSTACLES, {"obstacles", "obstacle_push", "obstacle_forces"}},
                          Case{PF_FEATURE_EMITTERS, {"emit"}}, Case{PF_FEATURE_SINKS, {"sinks"}},
                          Case{PF_FEATURE_DOMAIN_MOTION, {"domain_motion"}},
                          Case{PF_FEATURE_VORTICITY_CONFINEMENT, {"vorticity_confinement"}},
                          Case{PF_FEATURE_WHITEWATER, {"whitewater"}}, Case{PF_FEATURE_VISCOSITY, {"viscosity", "viscosity_projection"}},
                          Case{PF_FEATURE_SURFACE_TENSION, {"surface_tension"}}}) {
        SimPtr sim = make_scene(*this, 0);
        ASSERT_TRUE(sim);
        ASSERT_EQ(pf_set_features(sim.get(), c.feature), PF_OK) << last_log();
        ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        const std::vector<pf_pass_stats> list = pass_list(sim.get());
        std::vector<std::string> expected = kCoreList;
        expected.insert(expected.end(), c.added.begin(), c.added.end());
        EXPECT_EQ(names(list), expected) << c.feature;
        // The core passes ran exactly as often as with the effect off (one substep each here:
        // the first step's CFL estimate does not depend on the effects); the effect's ran.
        for (size_t i = 0; i < core.size() && i < list.size(); ++i)
            EXPECT_EQ(list[i].dispatches, core[i].dispatches) << list[i].name;
        for (size_t i = core.size(); i < list.size(); ++i) EXPECT_GT(list[i].dispatches, 0u) << list[i].name;
        // Off again: its entries stay listed but dispatch nothing.
        ASSERT_EQ(pf_set_features(sim.get(), 0), PF_OK);
        ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        const std::vector<pf_pass_stats> after = pass_list(sim.get());
        ASSERT_EQ(after.size(), list.size());
        for (size_t i = core.size(); i < after.size(); ++i) EXPECT_EQ(after[i].dispatches, 0u) << after[i].name;
    }
}

TEST_F(Effects, TogglingFeaturesKeepsEveryParticle) {
    SimPtr sim = make_scene(*this, 0);
    ASSERT_TRUE(sim);
    const float v[3] = {0.5f, 0.0f, 0.0f}, c[3] = {0.4f, 0.2f, 0.4f};
    ASSERT_EQ(pf_push(sim.get(), c, 0.3f, v), PF_OK);
    for (int i = 0; i < 3; ++i) ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    const ParticleState before = read_all(sim.get());
    ASSERT_GT(before.count(), 0u);
    for (uint32_t f : {uint32_t(PF_FEATURE_FORCE_FIELDS), uint32_t(PF_FEATURE_ALL), uint32_t(PF_FEATURE_OBSTACLES), 0u}) {
        ASSERT_EQ(pf_set_features(sim.get(), f), PF_OK) << last_log();
        uint32_t got = ~0u;  // no valid feature set
        ASSERT_EQ(pf_get_features(sim.get(), &got), PF_OK);
        EXPECT_EQ(got, f);
    }
    const ParticleState after = read_all(sim.get());
    ASSERT_EQ(after.count(), before.count());
    EXPECT_EQ(after.pos, before.pos);
    EXPECT_EQ(after.vel, before.vel);
}

TEST_F(Effects, UnknownFeatureBitsAreRefusedAndChangeNothing) {
    SimPtr sim = make_scene(*this, PF_FEATURE_FORCE_FIELDS);
    ASSERT_TRUE(sim);
    clear_log();
    EXPECT_EQ(pf_set_features(sim.get(), PF_FEATURE_ALL | (uint32_t(PF_FEATURE_ALL) + 1u)), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(last_log()).find("unknown feature bits"), std::string::npos) << last_log();
    uint32_t got = 0;
    ASSERT_EQ(pf_get_features(sim.get(), &got), PF_OK);
    EXPECT_EQ(got, uint32_t(PF_FEATURE_FORCE_FIELDS));
    EXPECT_EQ(pf_get_features(sim.get(), nullptr), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_set_features(nullptr, 0), PF_ERROR_INVALID_ARGUMENT);
    pf_sim_desc d = test_desc(8, 8, 8);
    d.features = 1u << 30;
    pf_sim* raw = nullptr;
    EXPECT_EQ(pf_create(&d, &raw), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(raw, nullptr);
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK) << "still usable";
}

}  // namespace
}  // namespace pf::test
