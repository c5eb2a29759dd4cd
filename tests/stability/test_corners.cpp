// Case 6 (docs/stability.md): liquid gathered in each of the eight corners in turn, with
// gravity pointing into that corner (the 2020 original exploded in the +X+Y+Z corner and stuck
// to positive walls). Each run settles to rest, and the eight runs are mirror images of the
// first: the same particles, mirrored, give the same centre of mass, mirrored. Mirroring an
// odd number of axes of this even grid swaps the red and black cells of the solvers' red-black
// smoothing, so within a solve's tolerance the odd corners see a different rounding of the
// pressure: the runs are compared within each parity (where a wall bias still shows: corners 3,
// 5, 6 and 7 have more positive walls than corners 0 and 1), and the two parities apart.
#include <algorithm>
#include <cmath>
#include <random>

#include "stability/stability.h"

namespace pf::test {
namespace {

class Corners : public Stability {};

// Centre of mass of p with the flipped axes mirrored back (into the (-,-,-) corner's frame).
void mirrored_com(const ParticleState& p, const bool flip[3], float extent, double com[3]) {
    for (int a = 0; a < 3; ++a) com[a] = 0;
    for (size_t i = 0; i < p.count(); ++i)
        for (int a = 0; a < 3; ++a) {
            const double x = p.pos[i * 3 + a];
            com[a] += (flip[a] ? extent - x : x) / double(p.count());
        }
}

double rms_speed_of(const ParticleState& p) {
    double sum = 0;
    for (size_t i = 0; i < p.vel.size(); ++i) sum += double(p.vel[i]) * p.vel[i];
    return std::sqrt(sum / double(p.count()));
}

TEST_P(Corners, EachCornerSettlesAndTheEightAreMirrorImages) {
    pf_sim_desc d = desc(10, 10, 10, 0.1f);
    const float extent = 1.0f;
    // A jittered pile in the (-,-,-) corner already shaped as liquid at rest under the diagonal
    // gravity: x + y + z <= 0.8 m, its surface perpendicular to g (85 cells at 8 per cell).
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.1f, 0.9f);
    std::vector<float> block;
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 16; ++j)
            for (int k = 0; k < 16; ++k) {
                const float p[3] = {0.05f * (float(i) + u(rng)), 0.05f * (float(j) + u(rng)), 0.05f * (float(k) + u(rng))};
                if (p[0] + p[1] + p[2] <= 0.8f) block.insert(block.end(), p, p + 3);
            }
    const uint32_t n = uint32_t(block.size() / 3);
    const float g = 9.81f / std::sqrt(3.0f);
    double early0[2][3] = {}, late0[2][3] = {};  // per parity: corners 0 and 1
    double early_error = 0, parity_error = 0, late_error = 0, worst_rms = 0, worst_max = 0;
    for (int corner = 0; corner < 8; ++corner) {
        SCOPED_TRACE("corner " + std::to_string(corner));
        bool flip[3];
        std::vector<float> pos = block;
        for (int a = 0; a < 3; ++a) {
            flip[a] = (corner >> a) & 1;
            d.params.gravity[a] = flip[a] ? g : -g;
            if (flip[a])
                for (size_t i = a; i < pos.size(); i += 3) pos[i] = extent - pos[i];
        }
        SimPtr sim = create(d);
        ASSERT_TRUE(sim);
        ASSERT_EQ(pf_add_particles(sim.get(), pos.data(), nullptr, n), PF_OK);
        double early[3], late[3];
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 15));
        mirrored_com(read_all(sim.get()), flip, extent, early);
        ASSERT_NO_FATAL_FAILURE(run(sim.get(), 1.0f / 60.0f, 105));
        const Soundness s = check(sim.get(), d, n, "settled");
        const ParticleState p = read_all(sim.get());
        mirrored_com(p, flip, extent, late);
        worst_rms = std::max(worst_rms, rms_speed_of(p));
        worst_max = std::max(worst_max, s.max_speed);
        const int parity = (int(flip[0]) + int(flip[1]) + int(flip[2])) & 1;
        if (corner < 2) {
            std::copy(early, early + 3, early0[parity]);
            std::copy(late, late + 3, late0[parity]);
        }
        for (int a = 0; a < 3; ++a) {
            early_error = std::max(early_error, std::abs(early[a] - early0[parity][a]) / d.cell_size);
            late_error = std::max(late_error, std::abs(late[a] - late0[0][a]) / d.cell_size);
            if (corner == 1) parity_error = std::max(parity_error, std::abs(early[a] - early0[0][a]) / d.cell_size);
        }
    }
    const double unit = std::sqrt(9.81 * d.cell_size);
    record("rms_speed_over_sqrt_g_dx", worst_rms / unit);
    record("max_speed_over_sqrt_g_dx", worst_max / unit);
    record("mirror_com_error_cells_0_25s", early_error);
    record("mirror_parity_com_error_cells_0_25s", parity_error);
    record("mirror_com_error_cells_2s", late_error);
    // Settled after 2 s: the pile as a whole is at rest (RMS); single surface particles of a
    // 45-degree surface stair-stepped on the grid keep shuffling (the max, in the table).
    EXPECT_LT(worst_rms, 0.1 * unit);
    // Mirror images: after 0.25 s the runs of one parity differ by rounding only (the kernels
    // have no preferred direction; a wall bias or a floor() instead of a symmetric rounding shows
    // up as 1e-2 cells and more). The parities differ by the red-black order's rounding of
    // unconverged solves (measured on llvmpipe with the ghost-fluid surface: 1.4e-3 cells with
    // balanced, 5.2e-4 fast, 1.7e-5 accurate; the marker cell's solves barely iterate here: 1e-6).
    // Later the flow amplifies rounding chaotically, but a liquid that sticks to positive walls
    // would sit cells away: bound 0.1 cell at 2 s for all eight.
    EXPECT_LT(early_error, 1e-3);
    EXPECT_LT(parity_error, 5e-3);
    EXPECT_LT(late_error, 0.1);
}

PF_STABILITY_PRESETS(Corners);

}  // namespace
}  // namespace pf::test
