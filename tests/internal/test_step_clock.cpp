// The step's clocks without a GL context (src/sim/step_clock.h): how many projections a frame
// takes and how far the velocity is extrapolated for the particle trace.
#include <cmath>

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

// At rest under Earth's gravity in cells of `cell` metres, a frame of `frame_units` gravity
// times sqrt(cell / g): the same flow at every cell size (Froude similarity).
ProjectionDemand at_scale(float cell, float frame_units) {
    ProjectionDemand d = demand(0.0f, 8.0f, 64);
    d.acceleration = 0.0f;
    d.cell_size = cell;
    d.gravity = 9.81f;
    d.frame_dt = frame_units * std::sqrt(cell / 9.81f);
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
    d.max_dt = 1.0f / 200.0f;  // a capillary limit: 4 projections in a 1/60 s frame
    EXPECT_EQ(projections_for(d).count, 4u);
    d = demand(0.0f, 1.0f, 16);
    d.imposed_speed = 5.9f;  // a wind: 9.8 cells a frame
    EXPECT_EQ(projections_for(d).count, 10u);
}

TEST(StepClock, StrainLimitsTheCompressionOfStraightMoves) {
    ProjectionDemand d = demand(2.0f, 8.0f, 16);
    ASSERT_EQ(projections_for(d).count, 1u) << "the speed alone asks for one";
    // frame_dt^2 P = 0.022: one projection would compress the liquid 2.2% in the frame; three
    // keep it under kStrainRate / 60 = 0.83%.
    d.strain = 0.022f * 3600.0f;
    EXPECT_EQ(projections_for(d).count, 3u);
    d.strain = 0.008f * 3600.0f;  // 0.8% with one
    EXPECT_EQ(projections_for(d).count, 1u);
    // Per time, not per frame: a frame twice as long compresses four times as much with one
    // projection and may compress twice as much (8.8% / 1.67%: six projections).
    d = demand(0.0f, 8.0f, 16);
    d.frame_dt = 2.0f / 60.0f;
    d.strain = 0.022f * 3600.0f;
    EXPECT_EQ(projections_for(d).count, 6u);
    // Rotation (P < 0) expands: no limit; the cap still clamps and says so.
    d.strain = -1e6f;
    EXPECT_EQ(projections_for(d).count, 1u);
    d.strain = 1e6f;
    const ProjectionCount k = projections_for(d);
    EXPECT_EQ(k.count, 16u);
    EXPECT_TRUE(k.clamped);
}

// The strain limit's unit is the gravity time sqrt(dx / |g|), measured at the laboratory columns'
// 3.572 mm cells: there it is 0.5 1/s, at 4 times their cells (2 times the gravity time) a
// frame may compress half as much; without gravity the laboratory's unit.
TEST(StepClock, StrainLimitIsInGravityTime) {
    ProjectionDemand d = demand(0.0f, 8.0f, 16);
    d.strain = 0.022f * 3600.0f;  // 2.64 times what a 1/60 s frame may compress with one projection
    d.gravity = 9.81f;
    d.cell_size = 9.81f * kStrainGravityTime * kStrainGravityTime;  // 3.572 mm
    EXPECT_EQ(projections_for(d).count, 3u);
    d.cell_size *= 4.0f;
    EXPECT_EQ(projections_for(d).count, 6u);  // 5.28
    d.gravity = 0.0f;
    EXPECT_EQ(projections_for(d).count, 3u);
}

// Froude similarity: the same flow 100 times larger (strain 1/100, frames 10 times longer) takes
// the same projections.
TEST(StepClock, TheStrainLimitScalesWithTheCell) {
    for (const float strain_at_1mm : {3e3f, 2e4f, 1e5f}) {
        uint32_t counts[3] = {};
        const float cells[3] = {1e-3f, 0.1f, 10.0f};
        for (int i = 0; i < 3; ++i) {
            ProjectionDemand d = at_scale(cells[i], 0.4f);
            d.strain = strain_at_1mm * 1e-3f / cells[i];
            counts[i] = projections_for(d).count;
        }
        EXPECT_GT(counts[1], 1u) << strain_at_1mm;
        EXPECT_EQ(counts[0], counts[1]) << strain_at_1mm;
        EXPECT_EQ(counts[2], counts[1]) << strain_at_1mm;
    }
}

TEST(StepClock, TheLongestProjectionCutsLongFrames) {
    ProjectionDemand d = demand(0.0f, 8.0f, 16);
    d.acceleration = 0.0f;  // neither speed nor acceleration asks for more than one
    d.cell_size = 0.1f;
    d.gravity = 9.81f;
    d.longest_projection = kLeapfrogLongestProjection;
    const float unit = std::sqrt(0.1f / 9.81f);  // 0.101 s
    EXPECT_FLOAT_EQ(longest_projection_seconds(kLeapfrogLongestProjection, 0.1f, 9.81f), 0.5f * unit);
    EXPECT_EQ(projections_for(d).count, 1u) << "a 1/60 s frame";
    for (const float frame : {0.5f * unit, 0.5f * unit * 1.00001f}) {  // exactly the longest, and a rounding above
        d.frame_dt = frame;
        EXPECT_EQ(projections_for(d).count, 1u) << frame;
    }
    d.frame_dt = 0.1f;
    EXPECT_EQ(projections_for(d).count, 2u);
    d.frame_dt = 0.5f;
    EXPECT_EQ(projections_for(d).count, 10u);
    EXPECT_FALSE(projections_for(d).clamped);
    d.frame_dt = 1.0f;  // 20 wanted: the cap clamps and says so
    const ProjectionCount k = projections_for(d);
    EXPECT_EQ(k.count, 16u);
    EXPECT_TRUE(k.clamped);
    // Without gravity nothing sets the unit: no limit.
    d.gravity = 0.0f;
    d.frame_dt = 0.5f;
    EXPECT_EQ(projections_for(d).count, 1u);
}

// Froude similarity: a liquid built 100 times larger, its frames sqrt(100) times longer, takes
// the same projections (1 mm cells at 4 ms frames, 10 cm at 40 ms, 10 m at 0.4 s).
TEST(StepClock, TheLongestProjectionScalesWithTheCell) {
    for (const float frame_units : {0.4f, 0.6f, 1.3f, 3.7f}) {
        uint32_t counts[3] = {};
        const float cells[3] = {1e-3f, 0.1f, 10.0f};
        for (int i = 0; i < 3; ++i) {
            ProjectionDemand d = at_scale(cells[i], frame_units);
            d.longest_projection = kLeapfrogLongestProjection;
            counts[i] = projections_for(d).count;
        }
        EXPECT_EQ(counts[0], counts[1]) << frame_units;
        EXPECT_EQ(counts[2], counts[1]) << frame_units;
        EXPECT_EQ(counts[1], uint32_t(std::ceil(frame_units / kLeapfrogLongestProjection))) << frame_units;
    }
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

MeasuredStep measured(uint32_t projections, float total_ms, float solve_ms, uint32_t iterations) {
    MeasuredStep m;
    m.step = 10;
    m.projections = projections;
    m.total_ms = total_ms;
    m.solve_ms = solve_ms;
    m.iterations = iterations;
    return m;
}

TEST(StepClock, NoBudgetOrNoMeasurementChangesNothing) {
    const BudgetPlan none = fit_budget(0.0f, 7, 40, measured(2, 4.0f, 2.0f, 8));
    EXPECT_EQ(none.projections, 7u);
    EXPECT_EQ(none.iteration_cap, 40u);
    EXPECT_FALSE(none.fewer_projections);
    const BudgetPlan unmeasured = fit_budget(1.0f, 7, 40, MeasuredStep{});
    EXPECT_EQ(unmeasured.projections, 7u);
    EXPECT_FALSE(unmeasured.fewer_projections);
}

TEST(StepClock, TheBudgetTakesTheProjectionsThatFit) {
    // 2 ms a projection: a 5 ms budget fits 2 of the 7 the CFL wants, a 20 ms budget all of them.
    const BudgetPlan cut = fit_budget(5.0f, 7, 40, measured(2, 4.0f, 2.0f, 8));
    EXPECT_EQ(cut.projections, 2u);
    EXPECT_TRUE(cut.fewer_projections);
    EXPECT_EQ(cut.iteration_cap, 40u) << "two whole projections fit: the solves keep their work";
    const BudgetPlan all = fit_budget(20.0f, 7, 40, measured(2, 4.0f, 2.0f, 8));
    EXPECT_EQ(all.projections, 7u);
    EXPECT_FALSE(all.fewer_projections);
}

TEST(StepClock, WhenOneProjectionDoesNotFitTheSolveGivesWay) {
    // A projection: 2 ms, of which the solve 1.5 ms over 10 iterations (0.15 ms each); a 1 ms
    // budget leaves the solve 0.5 ms: 3 iterations.
    const BudgetPlan plan = fit_budget(1.0f, 4, 40, measured(1, 2.0f, 1.5f, 10));
    EXPECT_EQ(plan.projections, 1u);
    EXPECT_TRUE(plan.fewer_projections);
    EXPECT_EQ(plan.iteration_cap, 3u);
    // Less than the rest of the projection: the solve keeps one iteration.
    EXPECT_EQ(fit_budget(0.2f, 1, 40, measured(1, 2.0f, 1.5f, 10)).iteration_cap, 1u);
    // A wanted single projection over the budget is cut in its solve, not in its count.
    const BudgetPlan one = fit_budget(1.0f, 1, 40, measured(1, 2.0f, 1.5f, 10));
    EXPECT_EQ(one.projections, 1u);
    EXPECT_FALSE(one.fewer_projections);
    EXPECT_EQ(one.iteration_cap, 3u);
}

}  // namespace
}  // namespace pf
