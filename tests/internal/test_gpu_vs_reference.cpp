// Each GPU pass of one substep against the double-precision CPU reference, on random
// particles. Every pass is checked in isolation: the reference pass is fed the GPU's own
// input to that pass (read back from the buffers the substep leaves behind), so a
// tolerance only has to cover float-vs-double rounding of that one pass. P2G is compared
// in its fixed-point units, where the bound is the rounding of each contribution.
#include <cmath>
#include <cstring>
#include <random>

#include "api/handle.h"
#include "reference/cpu_reference.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

std::vector<double> as_floats(const std::vector<uint32_t>& words) {
    std::vector<double> out(words.size());
    for (size_t i = 0; i < words.size(); ++i) {
        float f;
        std::memcpy(&f, &words[i], 4);
        out[i] = f;
    }
    return out;
}

struct Scene {
    ref::Grid grid;
    ref::Particles particles;
    std::vector<float> pos, vel;  // the same particles as floats, as uploaded
};

// Random particles in the lower part of the domain (so there is a free surface, AIR above)
// with random velocities; positions are floats converted exactly to doubles.
Scene random_scene(uint32_t seed, const pf_sim_desc& d, int count, float speed) {
    Scene s;
    s.grid = ref::Grid{int(d.grid_size[0]), int(d.grid_size[1]), int(d.grid_size[2]), d.cell_size,
                       glm::dvec3(d.origin[0], d.origin[1], d.origin[2])};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f), uv(-speed, speed);
    for (int i = 0; i < count; ++i) {
        glm::vec3 p, v;
        for (int a = 0; a < 3; ++a) {
            const float extent = d.cell_size * float(d.grid_size[a]) * (a == 1 ? 0.6f : 1.0f);
            p[a] = d.origin[a] + extent * u01(rng);
            v[a] = uv(rng);
        }
        for (int a = 0; a < 3; ++a) {
            s.pos.push_back(p[a]);
            s.vel.push_back(v[a]);
        }
        s.particles.pos.emplace_back(p);
        s.particles.vel.emplace_back(v);
    }
    return s;
}

// Number of (particle, node) contributions per face: bounds the fixed-point rounding.
std::vector<int> contributions(const ref::Grid& g, const ref::Particles& p) {
    std::vector<int> n(size_t(g.faces()), 0);
    for (const glm::dvec3& x : p.pos) {
        const glm::dvec3 gc = g.to_grid(x);
        for (int c = 0; c < 3; ++c) {
            const glm::dvec3 dims = glm::dvec3(g.face_dims(c));
            const glm::dvec3 s = glm::clamp(gc - ref::Grid::face_offset_g(c), glm::dvec3(0.0), dims - 1.0);
            const glm::ivec3 b = glm::ivec3(glm::min(glm::floor(s), dims - 2.0));
            for (int k = 0; k < 2; ++k)
                for (int j = 0; j < 2; ++j)
                    for (int i = 0; i < 2; ++i) ++n[size_t(g.face_index(c, b.x + i, b.y + j, b.z + k))];
        }
    }
    return n;
}

class GpuVsReference : public GpuTest, public ::testing::WithParamInterface<uint32_t> {};

TEST_P(GpuVsReference, EveryPassOfOneSubstep) {
    pf_sim_desc d = test_desc(12, 10, 8, 0.1f);
    d.origin[0] = -0.5f;
    d.origin[1] = 0.25f;
    d.origin[2] = 1.0f;
    d.max_speed = 4.0f;                 // S_m = 2^18: fine fixed-point resolution
    d.params.flip_ratio = 0.9f;
    d.params.pressure_iterations = 30;
    d.params.jacobi_omega = 0.8f;
    d.params.extrapolation_layers = 3;
    d.params.gravity[0] = 1.5f;         // every axis gets a body force
    d.params.separation = GetParam() % 2;  // odd seeds: projected Jacobi (p >= 0)
    d.params.gravity[2] = -0.5f;
    const double dt = 0.01, rho = d.density;
    const glm::dvec3 gravity(d.params.gravity[0], d.params.gravity[1], d.params.gravity[2]);

    Scene sc = random_scene(GetParam(), d, 2500, 2.0f);
    SimPtr handle = create(d);
    ASSERT_TRUE(handle);
    ASSERT_EQ(pf_add_particles(handle.get(), sc.pos.data(), sc.vel.data(), uint32_t(sc.particles.pos.size())), PF_OK)
        << last_log();
    Simulation& sim = *handle->impl;
    ASSERT_EQ(sim.run_substep_for_test(float(dt)), PF_OK);
    const ref::Grid& g = sc.grid;

    // P2G, in fixed-point units: each contribution rounds by at most 1/2, plus float
    // rounding of w*v*S (relative 2^-23 per contribution, bounded by S per contribution).
    const double s_m = 1048576.0 / d.max_speed, s_w = 1048576.0;
    const ref::P2GResult p2g = ref::p2g(g, sc.particles);
    const std::vector<uint32_t> accum = sim.read_grid(GridBuffer::face_accum);
    const std::vector<int> n = contributions(g, sc.particles);
    double worst_m = 0, worst_w = 0;
    for (int f = 0; f < g.faces(); ++f) {
        const double m_gpu = double(int32_t(accum[2 * f])), w_gpu = double(int32_t(accum[2 * f + 1]));
        const double tol_m = n[f] * (0.5 + 4.0 * d.max_speed * s_m * 1.2e-7) + 1e-9;
        const double tol_w = n[f] * (0.5 + s_w * 1.2e-7) + 1e-9;
        worst_m = std::max(worst_m, std::abs(m_gpu - p2g.momentum[f] * s_m) / tol_m);
        worst_w = std::max(worst_w, std::abs(w_gpu - p2g.weight[f] * s_w) / tol_w);
    }
    EXPECT_LE(worst_m, 1.0) << "P2G momentum off by more than its rounding bound";
    EXPECT_LE(worst_w, 1.0) << "P2G weight off by more than its rounding bound";

    // Cell counts and classification: exact.
    const std::vector<uint32_t> count = sim.read_grid(GridBuffer::cell_count);
    const std::vector<uint32_t> type_words = sim.read_grid(GridBuffer::cell_type);
    std::vector<uint8_t> type(type_words.size());
    for (size_t c = 0; c < count.size(); ++c) {
        ASSERT_EQ(count[c], p2g.count[c]) << "cell " << c;
        type[c] = uint8_t(type_words[c]);
    }
    EXPECT_EQ(type, ref::classify(g, p2g.count));

    // Grid forces: u_old = (M/S_m)/(W/S_w) from the GPU's own integer sums; then gravity and walls.
    const std::vector<double> vel_old = as_floats(sim.read_grid(GridBuffer::face_vel_old));
    ref::P2GResult gpu_p2g{std::vector<double>(size_t(g.faces())), std::vector<double>(size_t(g.faces())), p2g.count};
    for (int f = 0; f < g.faces(); ++f) {
        gpu_p2g.momentum[f] = double(int32_t(accum[2 * f])) / s_m;
        gpu_p2g.weight[f] = double(int32_t(accum[2 * f + 1])) / s_w;
    }
    const ref::GridForces forces = ref::grid_forces(g, gpu_p2g, gravity, dt);
    for (int f = 0; f < g.faces(); ++f) {
        ASSERT_NEAR(vel_old[f], forces.vel_old[f], 1e-6 * (1.0 + std::abs(forces.vel_old[f]))) << "face " << f;
    }

    // Pressure setup: b = -div * rho dx / dt on FLUID cells.
    const std::vector<double> rhs = as_floats(sim.read_grid(GridBuffer::rhs));
    const std::vector<double> rhs_ref = ref::pressure_rhs(g, type, forces.vel, rho, dt);
    double rhs_scale = 0;
    for (double b : rhs_ref) rhs_scale = std::max(rhs_scale, std::abs(b));
    ASSERT_GT(rhs_scale, 1.0);
    for (int c = 0; c < g.cells(); ++c) ASSERT_NEAR(rhs[c], rhs_ref[c], 2e-5 * rhs_scale) << "cell " << c;

    // Jacobi: K weighted iterations from p = 0 on the GPU's right-hand side.
    const std::vector<double> p = as_floats(sim.read_grid(GridBuffer::pressure));
    const std::vector<double> p_ref = ref::jacobi(g, type, rhs, std::vector<double>(size_t(g.cells()), 0.0),
                                                  int(d.params.pressure_iterations), d.params.jacobi_omega,
                                                  d.params.separation != 0);
    double p_scale = 0;
    for (double v : p_ref) p_scale = std::max(p_scale, std::abs(v));
    ASSERT_GT(p_scale, 1.0);
    for (int c = 0; c < g.cells(); ++c) ASSERT_NEAR(p[c], p_ref[c], 1e-5 * p_scale) << "cell " << c;

    // Velocity update and extrapolation, from the GPU's pressure.
    ref::VelocityUpdate vu = ref::velocity_update(g, type, forces.vel, p, rho, dt);
    ref::extrapolate(g, vu, int(d.params.extrapolation_layers));
    const std::vector<double> vel = as_floats(sim.read_grid(GridBuffer::face_vel));
    const std::vector<uint32_t> valid = sim.read_grid(GridBuffer::face_valid);
    double v_scale = 0;
    for (double v : vu.vel) v_scale = std::max(v_scale, std::abs(v));
    for (int f = 0; f < g.faces(); ++f) {
        ASSERT_EQ(valid[f] != 0, vu.valid[f] != 0) << "face " << f;
        ASSERT_NEAR(vel[f], vu.vel[f], 1e-5 * v_scale) << "face " << f;
    }

    // G2P from the GPU's face velocities, then advection.
    ref::Particles expect = sc.particles;
    ref::g2p(g, expect, vel, vel_old, d.params.flip_ratio, d.max_speed);
    ref::Particles moved = expect;
    ref::advect(g, moved, dt);
    ParticleState got = read_all(handle.get());
    for (size_t i = 0; i < got.count(); ++i) {
        for (int a = 0; a < 3; ++a) {
            ASSERT_NEAR(got.vel[i * 3 + a], expect.vel[i][a], 1e-5 * v_scale) << "particle " << i;
            ASSERT_NEAR(got.pos[i * 3 + a], moved.pos[i][a], 1e-6) << "particle " << i;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(RandomSeeds, GpuVsReference, ::testing::Values(1u, 2u, 3u, 4u));

}  // namespace
}  // namespace pf::test
