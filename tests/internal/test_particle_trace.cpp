// The particle trace inside a substep (docs/design.md §5) against the double-precision CPU
// reference, for moves of several cells: a smooth swirling face velocity is written directly
// (no P2G or solve), G2P and advection run once with a substep long enough for the fastest
// particles to cross about six cells, and every particle must land where the reference's trace
// puts it. Particles start everywhere, walls included, so the clamp of every sub-step is
// exercised. With RK2 and RK3 the reference's own single move (a trace of sub-steps of 16 cells)
// lands far from its trace: the comparison can tell a trace from a single move. (Euler's path is
// a straight line at the particle's velocity, the same in sub-steps as in one move.) RK2_OFFSET's
// particles carry velocities of their own (FLIP with the grid unchanged keeps them), so its
// offset from the field is not zero.
#include <cmath>
#include <random>

#include "api/handle.h"
#include "reference/cpu_reference.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

constexpr int kN = 16;             // cells per axis
constexpr float kDx = 0.1f;        // m
constexpr double kSpeed = 2.0;     // m/s: the field's peak
constexpr double kDt = 0.3;        // s: the fastest particles cross 6 cells

// A divergence-free swirl with cells of four-cell scale, so that a move of several cells turns.
glm::dvec3 swirl(const glm::dvec3& x) {
    const double k = 2.0 * M_PI / (8.0 * kDx);
    return kSpeed * glm::dvec3(std::sin(k * x.y) * std::cos(k * x.z), std::sin(k * x.z) * std::cos(k * x.x),
                               std::sin(k * x.x) * std::cos(k * x.y));
}

struct TraceRun {
    double worst = 0.0;        // largest |GPU - reference trace| position, cells
    double single_worst = 0.0; // largest |reference single move - reference trace|, cells
    double mean_moved = 0.0;   // mean distance moved, cells
    size_t particles = 0;
};

class ParticleTrace : public GpuTest {
protected:
    TraceRun run(pf_advection scheme) {
        pf_sim_desc d = test_desc(kN, kN, kN, kDx);
        d.params.gravity[1] = 0.0f;
        // Euler moves with G2P's (PIC) velocity: the same field. RK2_OFFSET's particles keep
        // their own (FLIP: the grid's change, zero here, added to them).
        const bool own = scheme == PF_ADVECTION_RK2_OFFSET;
        d.params.flip_ratio = own ? 1.0f : 0.0f;
        d.params.advection = scheme;
        d.max_speed = 100.0f;
        SimPtr handle = create(d);
        if (!handle) return {};
        Simulation& sim = *pf::entry(handle)->impl;

        ref::Grid grid{kN, kN, kN, kDx, glm::dvec3(d.origin[0], d.origin[1], d.origin[2])};
        const std::vector<uint32_t> words = floats_as_words(
            ref::sample_faces(grid, [&](int c, const glm::dvec3& g) { return swirl(grid.to_world(g))[c]; }));
        const std::vector<double> field = words_as_floats(words);  // the reference reads the GPU's floats
        sim.write_grid_for_test(GridBuffer::face_vel, words);
        sim.write_grid_for_test(GridBuffer::face_vel_old, words);
        // No obstacle: every cell AIR (the trace stops before SOLID ones; nothing classified them).
        sim.write_grid_for_test(GridBuffer::cell_type, std::vector<uint32_t>(size_t(grid.cells()), 0u));

        std::mt19937 rng(7);
        std::uniform_real_distribution<float> u01(0.0f, 1.0f);
        std::vector<float> pos, vel;
        ref::Particles particles;
        for (int p = 0; p < 2000; ++p) {
            glm::vec3 x, v(0.0f);
            for (int a = 0; a < 3; ++a) x[a] = d.origin[a] + kDx * kN * u01(rng);
            if (own) v = float(kSpeed) * (glm::vec3(u01(rng), u01(rng), u01(rng)) - 0.5f);
            pos.insert(pos.end(), {x.x, x.y, x.z});
            vel.insert(vel.end(), {v.x, v.y, v.z});
            particles.pos.emplace_back(x);
            particles.vel.emplace_back(v);
        }
        EXPECT_EQ(pf_add_particles(handle.get(), pos.data(), vel.data(), uint32_t(pos.size() / 3)), PF_OK) << last_log();
        EXPECT_EQ(sim.run_g2p_and_advect_for_test(float(kDt)), PF_OK) << last_log();
        const ParticleState end = read_all(handle.get());

        // The reference's trace (sub-steps of at most one cell), and its single move.
        const ref::Particles start = particles;
        ref::g2p(grid, particles, field, field, double(d.params.flip_ratio), double(d.max_speed));
        ref::Particles single = particles;
        const ref::Advection rk = ref::Advection(scheme);  // the reference's values are pf_advection's
        if (scheme == PF_ADVECTION_EULER) {
            ref::advect(grid, particles, kDt);
            single = particles;
        } else {
            ref::advect_rk(grid, particles, field, kDt, rk, 1.0);
            ref::advect_rk(grid, single, field, kDt, rk, 16.0);
        }
        TraceRun out;
        out.particles = end.count();
        EXPECT_EQ(end.count(), particles.pos.size());
        for (size_t p = 0; p < std::min(end.count(), particles.pos.size()); ++p) {
            const glm::dvec3 gpu(end.pos[p * 3], end.pos[p * 3 + 1], end.pos[p * 3 + 2]);
            out.worst = std::max(out.worst, glm::length(gpu - particles.pos[p]) / kDx);
            out.single_worst = std::max(out.single_worst, glm::length(single.pos[p] - particles.pos[p]) / kDx);
            out.mean_moved += glm::length(particles.pos[p] - start.pos[p]) / kDx / double(end.count());
        }
        return out;
    }
};

TEST_F(ParticleTrace, MovesOfSeveralCellsFollowTheReferenceTrace) {
    for (pf_advection scheme : {PF_ADVECTION_EULER, PF_ADVECTION_RK2, PF_ADVECTION_RK3, PF_ADVECTION_RK2_OFFSET}) {
        const TraceRun traced = run(scheme);
        std::printf("scheme %d: moved %.2f cells on average; |GPU - reference trace| at most %.2e cells; a single "
                    "move lands up to %.2e cells from the trace\n",
                    int(scheme), traced.mean_moved, traced.worst, traced.single_worst);
        ASSERT_EQ(traced.particles, 2000u);
        EXPECT_GT(traced.mean_moved, 2.0) << "the substep must carry particles several cells";
        // Float against double through about six sub-steps of a field whose gradient is about
        // 1.6 / s: rounding of coordinates up to 16 cells (1e-6 cells each), grown along the path
        // (measured: 1.3e-5 and 1.8e-5 cells with RK2 and RK3, 3e-6 with Euler).
        EXPECT_LT(traced.worst, 1e-4) << "scheme " << int(scheme);
        // A single move misses the trace by far more than that.
        if (scheme != PF_ADVECTION_EULER) EXPECT_GT(traced.single_worst, 0.1) << "scheme " << int(scheme);
    }
}

}  // namespace
}  // namespace pf::test
