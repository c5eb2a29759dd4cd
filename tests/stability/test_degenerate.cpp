// Case 8 (docs/stability.md): degenerate inputs. No particles at all, a single particle, a
// sheet one cell thick, the narrowest grids (1 x N x 1, N x M x 1, a single cell), and cell
// sizes from 1 mm to 10 m, which must behave alike in dimensionless units (lengths in cells,
// times in sqrt(dx / g)).
#include <cmath>

#include "stability/stability.h"

namespace pf::test {
namespace {

class Degenerate : public Stability {};

TEST_P(Degenerate, NoParticlesAtAll) {
    const pf_sim_desc d = desc(8, 8, 8, 0.1f);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 30));
    ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f, 2));
    check(sim.get(), d, 0, "empty");
    const pf_stats st = settled_stats(sim.get());
    EXPECT_EQ(st.flags, 0u);
    EXPECT_EQ(st.kinetic_energy, 0.0f);
    expect_usable(sim.get(), d, "after stepping nothing");
}

// One particle falls freely (a lone particle is its own FLUID cell with AIR all round, so the
// pressure leaves it alone) and comes to rest on the floor.
TEST_P(Degenerate, OneParticleFallsAndLands) {
    const pf_sim_desc d = desc(8, 16, 8, 0.1f);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float p[3] = {0.45f, 1.45f, 0.45f};
    ASSERT_EQ(pf_add_particles(sim.get(), p, nullptr, 1), PF_OK);
    ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 15));
    const ParticleState mid = read_all(sim.get());
    // 0.25 s of free fall: 0.306 m; the grid transfer smooths the start by a fraction of a cell.
    const double fallen = 1.45 - mid.pos[1];
    record("fall_after_0_25s_m", fallen);
    EXPECT_NEAR(fallen, 0.5 * 9.81 * 0.25 * 0.25, 0.3 * d.cell_size);
    ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 75));
    const Soundness s = check(sim.get(), d, 1, "landed");
    const ParticleState end = read_all(sim.get());
    EXPECT_LT(end.pos[1], 0.5 * d.cell_size) << "on the floor";
    EXPECT_LT(s.max_speed, 0.1) << "at rest";
}

// A sheet one cell thick (8 particles per cell) released at mid height lands and spreads as a
// film without any particle escaping or the film tearing into NaNs.
TEST_P(Degenerate, SheetOneCellThick) {
    const pf_sim_desc d = desc(12, 12, 12, 0.1f);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.0f, 0.6f, 0.0f}, hi[3] = {1.2f, 0.7f, 1.2f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    const size_t n = settled_stats(sim.get()).particle_count;
    const Soundness start = check(sim.get(), d, n, "start");
    ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 60));
    const Soundness end = check(sim.get(), d, n, "landed");
    record("energy_end_over_start", end.energy.total() / start.energy.total());
    EXPECT_LT(end.energy.total(), start.energy.total());
    expect_usable(sim.get(), d, "after the sheet");
}

// The narrowest grids: a 1 x 64 x 1 shaft, half full of liquid, a dam break in a one-cell-wide
// slot (16 x 8 x 1), and a single cell holding a few particles. All stay sound; the shaft and
// the cell stay at rest.
TEST_P(Degenerate, NarrowestGrids) {
    {
        const pf_sim_desc d = desc(1, 64, 1, 0.1f);
        SimPtr sim = create(d);
        ASSERT_TRUE(sim);
        const float lo[3] = {0, 0, 0}, hi[3] = {0.1f, 3.2f, 0.1f};
        ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
        const size_t n = settled_stats(sim.get()).particle_count;
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 120));
        const Soundness s = check(sim.get(), d, n, "shaft");
        record("shaft_max_speed_over_sqrt_g_dx", s.max_speed / std::sqrt(9.81 * d.cell_size));
        EXPECT_LT(s.max_speed, 0.05 * std::sqrt(9.81 * d.cell_size));
    }
    {
        const pf_sim_desc d = desc(16, 8, 1, 0.1f);
        SimPtr sim = create(d);
        ASSERT_TRUE(sim);
        const float lo[3] = {0, 0, 0}, hi[3] = {0.6f, 0.6f, 0.1f};
        ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
        const size_t n = settled_stats(sim.get()).particle_count;
        const Soundness start = check(sim.get(), d, n, "slot start");
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 90));
        const Soundness end = check(sim.get(), d, n, "slot");
        EXPECT_LT(end.energy.total(), start.energy.total());
        expect_usable(sim.get(), d, "after the slot");
    }
    {
        const pf_sim_desc d = desc(1, 1, 1, 0.1f);
        SimPtr sim = create(d);
        ASSERT_TRUE(sim);
        const float lo[3] = {0, 0, 0}, hi[3] = {0.1f, 0.05f, 0.1f};
        ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
        const size_t n = settled_stats(sim.get()).particle_count;
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 60));
        const Soundness s = check(sim.get(), d, n, "one cell");
        EXPECT_LT(s.max_speed, 0.05 * std::sqrt(9.81 * d.cell_size));
    }
}

// The same dam break (16 x 8 x 8 cells, a 6 x 6 x 8-cell block) at cell sizes 1 mm, 10 cm and
// 10 m, with frame times scaled by sqrt(dx / g) so each frame is the same dimensionless time.
// Froude similarity: the front position in cells and the potential energy fraction must agree.
TEST_P(Degenerate, CellSizesFromAMillimetreToTenMetresBehaveAlike) {
    struct Result {
        double front_cells, energy_fraction;
    };
    auto dam_break = [&](float dx) -> Result {
        const pf_sim_desc d = desc(16, 8, 8, dx);
        SimPtr sim = create(d);
        EXPECT_TRUE(sim);
        if (!sim) return {};
        const float lo[3] = {0, 0, 0}, hi[3] = {6 * dx, 6 * dx, 8 * dx};
        EXPECT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
        const size_t n = settled_stats(sim.get()).particle_count;
        const Soundness start = check(sim.get(), d, n, "start dx " + std::to_string(dx));
        // 6 frames of 0.4 sqrt(dx / g): the front is half way to the far wall.
        const float frame = float(0.4 * std::sqrt(double(dx) / 9.81));
        for (int f = 0; f < 6; ++f) EXPECT_EQ(pf_step(sim.get(), frame), PF_OK);
        const Soundness end = check(sim.get(), d, n, "end dx " + std::to_string(dx));
        const ParticleState p = read_all(sim.get());
        double front = 0;
        for (size_t i = 0; i < p.count(); ++i) front = std::max(front, double(p.pos[i * 3]));
        return {front / dx, end.energy.potential / start.energy.potential};
    };
    const Result mm = dam_break(1e-3f), dm = dam_break(0.1f), big = dam_break(10.0f);
    record("front_cells_1mm", mm.front_cells);
    record("front_cells_10cm", dm.front_cells);
    record("front_cells_10m", big.front_cells);
    record("potential_fraction_1mm", mm.energy_fraction);
    record("potential_fraction_10m", big.energy_fraction);
    // Same dimensionless motion: fronts within a quarter cell, energy fractions within 1%.
    EXPECT_NEAR(mm.front_cells, dm.front_cells, 0.25);
    EXPECT_NEAR(big.front_cells, dm.front_cells, 0.25);
    EXPECT_NEAR(mm.energy_fraction, dm.energy_fraction, 0.01);
    EXPECT_NEAR(big.energy_fraction, dm.energy_fraction, 0.01);
}

PF_STABILITY_PRESETS(Degenerate);

}  // namespace
}  // namespace pf::test
