// Cases 3 and 4 (docs/stability.md): all particles packed into one cell; particles exactly on
// cell faces, grid nodes and the domain walls; and the fixed-point P2G at its limit (more
// full-weight particles on one grid sample than its 31-bit sum holds, at max_speed).
#include <algorithm>
#include <cmath>
#include <random>

#include "api/handle.h"
#include "stability/stability.h"

namespace pf::test {
namespace {

class Packed : public Stability {
protected:
    // `count` particles at random points of cell (i, j, k) with velocities of up to `speed`.
    static void pack(pf_sim* sim, const pf_sim_desc& d, int i, int j, int k, uint32_t count, float speed) {
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> u(0.0f, 1.0f), uv(-1.0f, 1.0f);
        std::vector<float> pos, vel;
        const int cell[3] = {i, j, k};
        for (uint32_t p = 0; p < count; ++p) {
            float v[3] = {uv(rng), uv(rng), uv(rng)};
            const float len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + 1e-6f;
            for (int a = 0; a < 3; ++a) {
                pos.push_back(d.origin[a] + d.cell_size * (float(cell[a]) + u(rng)));
                vel.push_back(speed * v[a] / len * 0.999f);
            }
        }
        ASSERT_EQ(pf_add_particles(sim, pos.data(), vel.data(), count), PF_OK) << last_log();
    }
};

// 1000 particles (125 times the rest density) in one cell at the bottom of a 12^3 tank: the
// pressure (and volume correction) spread them out. They start at rest, so the only energy is
// their potential; spreading converts some of it and the compression's excess, never more
// than the packing stored: the bound is the potential of the same particles stacked at rest
// density above that cell (measured in the results table).
TEST_P(Packed, AllParticlesInOneCell) {
    const pf_sim_desc d = desc(12, 12, 12, 0.1f);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    ASSERT_NO_FATAL_FAILURE(pack(sim.get(), d, 6, 0, 6, 1000, 0.0f));
    const Soundness start = check(sim.get(), d, 1000, "start");
    double worst = 0;
    for (int f = 1; f <= 90; ++f) {
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 1));
        if (f % 10) continue;
        const Soundness s = check(sim.get(), d, 1000, "frame " + std::to_string(f));
        worst = std::max(worst, s.energy.total());
    }
    const Soundness end = check(sim.get(), d, 1000, "end");
    // A column of 1000 / 8 = 125 cells' worth standing on one cell, 12.5 m high, has potential
    // m g sum(h) = 1000 m g (12.5 m / 2): the most the packing could release.
    const double stacked = 1000 * particle_mass(d) * 9.81 * (125 * 0.1 / 2);
    record("energy_max_over_stacked", worst / stacked);
    const std::vector<uint32_t> counts = cell_counts_of(read_all(sim.get()), d);
    record("occupied_cells_end", double(std::count_if(counts.begin(), counts.end(), [](uint32_t c) { return c > 0; })));
    record("max_speed_end", end.max_speed);
    EXPECT_LT(worst, stacked);
    EXPECT_GT(end.volume, 4 * start.volume) << "the packed particles did not spread";
    expect_usable(sim.get(), d, "after unpacking");
}

// Particles exactly on cell faces, grid nodes and all six domain walls (the lattice x = i dx
// for i = 0..n, including the far walls x = n dx): every clamp and floor() meets its edge case.
TEST_P(Packed, ParticlesOnFacesNodesAndWalls) {
    const pf_sim_desc d = desc(8, 8, 8, 0.1f);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    std::vector<float> pos;
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 4; ++j)
            for (int k = 0; k <= 8; ++k) {
                pos.push_back(d.cell_size * float(i));
                pos.push_back(d.cell_size * float(j));
                pos.push_back(d.cell_size * float(k));
            }
    // And half-cell offsets: exactly on the faces between nodes.
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 8; ++k) {
            pos.push_back(d.cell_size * (float(i) + 0.5f));
            pos.push_back(0.0f);
            pos.push_back(d.cell_size * float(k));
        }
    const uint32_t n = uint32_t(pos.size() / 3);
    ASSERT_EQ(pf_add_particles(sim.get(), pos.data(), nullptr, n), PF_OK) << last_log();
    const Soundness start = check(sim.get(), d, n, "start");
    for (int f = 1; f <= 60; ++f) {
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 1));
        if (f % 15 == 0) check(sim.get(), d, n, "frame " + std::to_string(f));
    }
    const Soundness end = check(sim.get(), d, n, "end");
    record("energy_end_over_start", end.energy.total() / start.energy.total());
    EXPECT_LT(end.energy.total(), start.energy.total()) << "released from rest, the liquid gained energy";
    expect_usable(sim.get(), d, "after the lattice");
}

// 3000 particles at half of max_speed, all on one x-face sample (x on a face, y and z at a cell
// centre): that sample gets 3000 full weights, more than the 2^31 / 2^20 = 2047 a fixed-point
// sum holds. The overflow is detected, flagged and logged once; the sample's sums wrap, so that
// step's velocity there is wrong (measured below, see docs/stability.md), but G2P's speed clamp
// keeps every particle finite, inside and at most max_speed. Once the overflow is read back,
// the library widens the fixed-point range (by 2 bits: 8191 particles per sample), so later
// steps sum the same pile exactly: no new overflow, and the sample holds the particles' velocity.
TEST_P(Packed, FixedPointP2gAtItsLimit) {
    pf_sim_desc d = desc(8, 8, 8, 0.1f);
    d.max_speed = 20.0f;
    d.max_particles = 8192;
    d.params.p2g = PF_P2G_FIXED_POINT;
    d.params.gravity[1] = 0.0f;
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const uint32_t n = 3000;
    std::vector<float> pos, vel;
    for (uint32_t i = 0; i < n; ++i) {
        const float p[3] = {0.4f, 0.45f, 0.45f}, v[3] = {10.0f, 0.0f, 0.0f};
        pos.insert(pos.end(), p, p + 3);
        vel.insert(vel.end(), v, v + 3);
    }
    ASSERT_EQ(pf_add_particles(sim.get(), pos.data(), vel.data(), n), PF_OK) << last_log();
    // One substep (0.42 cells at 10 m/s): the accumulators then hold that substep's P2G sums.
    ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 240.0f, 1));
    ASSERT_EQ(settled_stats(sim.get()).substeps, 1u);
    const std::vector<uint32_t> accum = pf::entry(sim)->impl->read_grid(GridBuffer::face_accum);
    const size_t face = 4 + 9 * (4 + 8 * 4);  // x-face (4, 4, 4) of the 9 x 8 x 8 x-face lattice
    const int32_t momentum = int32_t(accum[2 * face]), weight = int32_t(accum[2 * face + 1]);
    const double velocity = double(momentum) / double(weight) * d.max_speed;  // momentum_scale = S_w / max_speed
    record("wrapped_weight_in_particles", double(weight) / double(1 << 20));
    record("sample_velocity", velocity);
    for (int f = 1; f <= 30; ++f) {
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 1));
        const Soundness s = check(sim.get(), d, n, "frame " + std::to_string(f));
        ASSERT_LE(s.max_speed, 20.0 * (1 + 1e-5)) << "frame " << f;
        if (HasFailure()) return;
    }
    const pf_stats st = settled_stats(sim.get());
    EXPECT_NE(st.flags & PF_FLAG_P2G_OVERFLOW, 0u);
    EXPECT_EQ(log_.warnings_with("PF_FLAG_P2G_OVERFLOW"), 1u);
    EXPECT_EQ(log_.warnings_with("range widened to 8191"), 1u);
    expect_usable(sim.get(), d, "after the overflow");

    // The widened range: the same pile, added again at rest, sums without overflow.
    ASSERT_EQ(pf_clear_particles(sim.get()), PF_OK);
    ASSERT_EQ(pf_clear_flags(sim.get()), PF_OK);
    ASSERT_EQ(pf_add_particles(sim.get(), pos.data(), vel.data(), n), PF_OK);
    ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 240.0f, 1));
    const std::vector<uint32_t> again = pf::entry(sim)->impl->read_grid(GridBuffer::face_accum);
    const double widened_velocity = double(int32_t(again[2 * face])) / double(int32_t(again[2 * face + 1])) * d.max_speed;
    record("sample_velocity_widened", widened_velocity);
    EXPECT_NEAR(widened_velocity, 10.0, 1e-3) << "the widened sums hold the particles' velocity";
    EXPECT_EQ(settled_stats(sim.get()).flags & PF_FLAG_P2G_OVERFLOW, 0u) << "the widened range overflowed again";
}

PF_STABILITY_PRESETS(Packed);

}  // namespace
}  // namespace pf::test
