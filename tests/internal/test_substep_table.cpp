// The substep as a table of stages (src/sim/substep_table.h, docs/design.md §4): the table's
// own rules, and the entries a simulation's parameters and effects give it.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/handle.h"
#include "sim/substep_table.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

using Names = std::vector<std::string>;

// A table whose entries append their names to `log` when run.
SubstepTable::Run record(Names& log, const std::string& name) {
    return [&log, name](const SubstepContext&) { log.push_back(name); };
}

TEST(SubstepTable, InsertedEntriesFollowTheirAnchorInInsertionOrder) {
    Names log;
    SubstepTable t;
    t.add("a", record(log, "a"));
    t.add("b", record(log, "b"));
    t.add("c", record(log, "c"));
    EXPECT_TRUE(t.insert_after("a", "x/a", record(log, "x/a")));
    EXPECT_TRUE(t.insert_after("a", "y/a", record(log, "y/a")));
    EXPECT_TRUE(t.insert_after("c", "y/c", record(log, "y/c")));
    EXPECT_FALSE(t.insert_after("missing", "z", record(log, "z")));
    EXPECT_EQ(t.names(), (Names{"a", "x/a", "y/a", "b", "c", "y/c"}));
    t.run(SubstepContext{});
    EXPECT_EQ(log, t.names());
}

TEST(SubstepTable, ReplaceKeepsThePlaceAndRunStartsAtTheNamedEntry) {
    Names log;
    SubstepTable t;
    t.add("a", record(log, "a"));
    t.add("b", record(log, "b"));
    t.add("c", record(log, "c"));
    EXPECT_TRUE(t.replace("b", record(log, "fused b")));
    EXPECT_FALSE(t.replace("missing", record(log, "z")));
    t.run(SubstepContext{}, "b");
    EXPECT_EQ(log, (Names{"fused b", "c"}));
    log.clear();
    t.run(SubstepContext{}, "missing");
    EXPECT_TRUE(log.empty());
    bool seen = false;
    t.replace("a", [&seen](const SubstepContext& c) { seen = c.correct_volume; });
    t.run(SubstepContext{true});
    EXPECT_TRUE(seen) << "the context reaches the entries";
}

class SubstepStages : public GpuTest {};

const Names kCore = {"p2g",          "grid_forces",    "classify",       "free_surface",    "volume_correction",
                     "wall_release", "pressure_setup", "pressure_solve", "velocity_update", "extrapolate",
                     "g2p",          "advect"};

TEST_F(SubstepStages, TheDefaultSubstepIsTheCoreStagesInOrder) {
    SimPtr handle = create(test_desc(12, 10, 8));
    ASSERT_TRUE(handle);
    EXPECT_EQ(pf::entry(handle)->impl->substep_stage_names(), kCore);
}

TEST_F(SubstepStages, ParametersAndEffectsGiveTheirEntriesTheirPlaces) {
    pf_sim_desc d = test_desc(12, 10, 8);
    d.features = PF_FEATURE_OBSTACLES | PF_FEATURE_FORCE_FIELDS | PF_FEATURE_DOMAIN_MOTION | PF_FEATURE_EMITTERS |
                 PF_FEATURE_SINKS;
    SimPtr handle = create(d);
    ASSERT_TRUE(handle);
    Simulation& sim = *pf::entry(handle)->impl;
    // Emitters and sinks run once per step, outside the substep.
    EXPECT_EQ(sim.substep_stage_names(),
              (Names{"p2g", "grid_forces", "force_fields/grid_forces", "domain_motion/grid_forces", "classify",
                     "obstacles/classify", "free_surface", "volume_correction", "wall_release", "pressure_setup", "pressure_solve",
                     "velocity_update", "obstacles/velocity_update", "extrapolate", "g2p", "advect",
                     "obstacles/advect"}));
    // Turned off again: the core table.
    ASSERT_EQ(pf_set_features(handle.get(), 0), PF_OK);
    EXPECT_EQ(sim.substep_stage_names(), kCore);
    // The marker-cell surface has no free_surface entry; no correction, no entry.
    pf_sim_params p = sized_params();
    ASSERT_EQ(pf_get_params(handle.get(), &p), PF_OK);
    p.free_surface = PF_FREE_SURFACE_MARKER_CELL;
    ASSERT_EQ(pf_set_params(handle.get(), &p), PF_OK);
    Names without = kCore;
    without.erase(without.begin() + 3);
    EXPECT_EQ(sim.substep_stage_names(), without);
    p.volume_correction = 0.0f;
    ASSERT_EQ(pf_set_params(handle.get(), &p), PF_OK);
    without.erase(without.begin() + 3);
    EXPECT_EQ(sim.substep_stage_names(), without);
}

}  // namespace
}  // namespace pf::test
