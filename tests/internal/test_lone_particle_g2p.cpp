// FLIP's G2P rule for a particle alone in its cell (shaders/sim/g2p.comp) against the
// double-precision reference, on the configuration that ran away (a droplet one empty row above a
// sheet sliding the other way, docs/notes/2026-12-06-lone-particle-flip.md), where the rule acts:
// GpuVsReference's random scenes rarely give it faces to act on.
#include <cmath>

#include "api/handle.h"
#include "reference/cpu_reference.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class LoneParticleG2p : public GpuTest {};

TEST_F(LoneParticleG2p, MatchesTheReferenceWhereTheRuleActs) {
    const float dx = 0.05f;
    pf_sim_desc d = test_desc(24, 12, 24, dx);
    d.params.advection = PF_ADVECTION_EULER;
    SimPtr handle = create(d);
    ASSERT_TRUE(handle);
    const float lo[3] = {0, 0, 0}, hi[3] = {24 * dx, 0.8f * dx, 24 * dx}, sheet[3] = {4.0f, 0.0f, 0.0f};
    ASSERT_EQ(pf_fill_box(handle.get(), lo, hi, sheet), PF_OK);
    // Droplets alone in their cells at several heights and offsets over the sheet; the last two in
    // neighbouring cells, each with some of the other's weight on its faces (the rule half on).
    const float drops[][3] = {{12.59f, 2.08f, 12.41f}, {6.3f, 2.2f, 17.7f}, {17.8f, 2.05f, 6.2f},
                              {9.5f, 2.5f, 9.5f},     {14.5f, 2.3f, 4.5f}, {15.6f, 2.3f, 4.5f}};
    constexpr size_t kDrops = sizeof drops / sizeof drops[0];
    for (const auto& c : drops) {
        const float p[3] = {c[0] * dx, c[1] * dx, c[2] * dx}, v[3] = {-4.0f, 0.3f, -2.0f};
        ASSERT_EQ(pf_add_particles(handle.get(), p, v, 1), PF_OK);
    }
    const ParticleState before = read_all(handle.get());
    Simulation& sim = *pf::entry(handle)->impl;
    ASSERT_EQ(sim.run_substep_for_test(1.0f / 120.0f), PF_OK);
    const ParticleState after = read_all(handle.get());

    const ref::Grid g{int(d.grid_size[0]), int(d.grid_size[1]), int(d.grid_size[2]), d.cell_size, glm::dvec3(0.0)};
    const std::vector<double> vel = words_as_floats(sim.read_grid(GridBuffer::face_vel));
    const std::vector<double> vel_old = words_as_floats(sim.read_grid(GridBuffer::face_vel_old));
    const std::vector<uint32_t> accum = sim.read_grid(GridBuffer::face_accum);
    const std::vector<uint32_t> type_words = sim.read_grid(GridBuffer::cell_type);
    std::vector<double> weight(size_t(g.faces()));
    for (int f = 0; f < g.faces(); ++f) weight[size_t(f)] = double(int32_t(accum[2 * size_t(f) + 1])) / 1048576.0;
    std::vector<uint8_t> type(type_words.size());
    for (size_t c = 0; c < type.size(); ++c) type[c] = uint8_t(PF_CELL_KIND(type_words[c]));

    double v_scale = 0;
    for (double v : vel) v_scale = std::max(v_scale, std::abs(v));
    const size_t first = before.count() - kDrops;
    ref::Particles drops_ref, drops_plain;
    for (size_t i = first; i < before.count(); ++i) {
        drops_ref.pos.emplace_back(before.pos[i * 3], before.pos[i * 3 + 1], before.pos[i * 3 + 2]);
        drops_ref.vel.emplace_back(before.vel[i * 3], before.vel[i * 3 + 1], before.vel[i * 3 + 2]);
    }
    drops_plain = drops_ref;
    ref::g2p(g, drops_ref, vel, vel_old, d.params.flip_ratio, d.max_speed, weight, type);
    ref::g2p(g, drops_plain, vel, vel_old, d.params.flip_ratio, d.max_speed);
    double acted = 0;
    for (size_t k = 0; k < kDrops; ++k) {
        for (int a = 0; a < 3; ++a) {
            // Euler's move keeps the velocity G2P gave, away from walls.
            EXPECT_NEAR(after.vel[(first + k) * 3 + a], drops_ref.vel[k][a], 1e-5 * v_scale) << "droplet " << k << " axis " << a;
            acted = std::max(acted, std::abs(drops_ref.vel[k][a] - drops_plain.vel[k][a]));
        }
    }
    EXPECT_GT(acted, 100.0 * 1e-5 * v_scale) << "the rule must change a droplet's velocity here for this test to test it";
}

}  // namespace
}  // namespace pf::test
