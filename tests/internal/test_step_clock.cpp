// The step's clocks without a GL context (src/sim/step_clock.h): how many projections a frame
// takes and how far the velocity is extrapolated for the particle trace.
#include <gtest/gtest.h>

#include "pf/pf.h"
#include "sim/step_clock.h"

namespace pf {
namespace {

ProjectionDemand demand(float speed, float cfl, uint32_t max) {
    ProjectionDemand d;
    d.frame_dt = 1.0f / 60.0f;
    d.cell_size = 0.01f;
    d.cfl = cfl;
    d.max_projections = max;
    d.speed = speed;
    d.acceleration = 9.81f;
    return d;
}

TEST(StepClock, ProjectionsFollowTheProjectionCfl) {
    // 2 m/s + 1/60 s of gravity = 2.1635 m/s: 3.6 cells of 1 cm in a frame.
    EXPECT_EQ(projections_for(demand(2.0f, 1.0f, 16)).count, 4u);
    EXPECT_EQ(projections_for(demand(2.0f, 2.0f, 16)).count, 2u);
    EXPECT_EQ(projections_for(demand(2.0f, 4.0f, 16)).count, 1u);
    EXPECT_FALSE(projections_for(demand(2.0f, 4.0f, 16)).clamped);
    // At rest: one projection.
    EXPECT_EQ(projections_for(demand(0.0f, 1.0f, 16)).count, 1u);
}

TEST(StepClock, TheCapClampsAndSaysSo) {
    const ProjectionCount k = projections_for(demand(2.0f, 1.0f, 2));
    EXPECT_EQ(k.count, 2u);
    EXPECT_TRUE(k.clamped);
}

TEST(StepClock, EffectsLimitsAndImposedSpeedsCount) {
    ProjectionDemand d = demand(0.0f, 8.0f, 16);
    d.longest_dt = 1.0f / 200.0f;  // a capillary limit: 4 projections in a 1/60 s frame
    EXPECT_EQ(projections_for(d).count, 4u);
    d = demand(0.0f, 1.0f, 16);
    d.imposed_speed = 5.9f;  // a wind: 9.8 cells a frame
    EXPECT_EQ(projections_for(d).count, 10u);
}

TEST(StepClock, TravelIsTheFastestParticlesCellsPerProjection) {
    const ProjectionCount k = projections_for(demand(2.0f, 16.0f, 16));
    EXPECT_EQ(k.count, 1u);
    EXPECT_NEAR(k.travel_cells, 2.1635f / 60.0f / 0.01f, 1e-3f);
    const ProjectionCount two = projections_for(demand(2.0f, 2.0f, 16));
    EXPECT_NEAR(two.travel_cells, k.travel_cells / 2.0f, 1e-3f);
}

TEST(StepClock, VelocityReachesAsFarAsAProjectionCarriesAParticle) {
    pf_sim_params p = pf_default_sim_params();
    p.extrapolation_layers = 2;
    EXPECT_EQ(extrapolation_layers(p, 1.0f), 2u) << "unchanged within one cell";
    EXPECT_EQ(extrapolation_layers(p, 0.3f), 2u);
    EXPECT_EQ(extrapolation_layers(p, 0.0f), 2u);
    EXPECT_EQ(extrapolation_layers(p, 4.5f), 6u);
    p.extrapolation_layers = 1;
    EXPECT_EQ(extrapolation_layers(p, 16.0f), 16u);
    EXPECT_EQ(extrapolation_layers(p, 100.0f), 17u) << "at most 16 layers beyond the parameter's";
}

}  // namespace
}  // namespace pf
