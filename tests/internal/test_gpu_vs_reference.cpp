// Each GPU pass of one substep against the double-precision CPU reference, on random
// particles. Every pass is checked in isolation: the reference pass is fed the GPU's own
// input to that pass (read back from the buffers the substep leaves behind), so a
// tolerance only has to cover float-vs-double rounding of that one pass. P2G is compared
// in its fixed-point units, where the bound is the rounding of each contribution.
// Each seed runs three pipelines: PIC/FLIP with Euler (the original), and APIC with RK2 and
// with RK3 (APIC's P2G starts from random affine vectors written into the particle buffer).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <tuple>

#include "api/handle.h"
#include "reference/cpu_reference.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

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

// Calls f(particle, component, face, weight, node grid position) for every (particle, node)
// contribution of P2G (the §3 stencil).
template <class F> void for_each_contribution(const ref::Grid& g, const ref::Particles& p, F&& f) {
    for (size_t q = 0; q < p.pos.size(); ++q) {
        const glm::dvec3 gc = g.to_grid(p.pos[q]);
        for (int c = 0; c < 3; ++c) {
            const glm::dvec3 dims = glm::dvec3(g.face_dims(c));
            const glm::dvec3 s = glm::clamp(gc - ref::Grid::face_offset_g(c), glm::dvec3(0.0), dims - 1.0);
            const glm::dvec3 b = glm::min(glm::floor(s), dims - 2.0);
            const glm::dvec3 frac = s - b;
            for (int k = 0; k < 2; ++k)
                for (int j = 0; j < 2; ++j)
                    for (int i = 0; i < 2; ++i) {
                        const glm::dvec3 d(i, j, k);
                        const glm::dvec3 w = glm::mix(1.0 - frac, frac, d);
                        const glm::ivec3 node = glm::ivec3(b + d);
                        f(q, c, g.face_index(c, node.x, node.y, node.z), w.x * w.y * w.z,
                          b + d + ref::Grid::face_offset_g(c));
                    }
        }
    }
}

// Number of (particle, node) contributions per face: bounds the fixed-point rounding.
std::vector<int> contributions(const ref::Grid& g, const ref::Particles& p) {
    std::vector<int> n(size_t(g.faces()), 0);
    for_each_contribution(g, p, [&](size_t, int, int face, double, glm::dvec3) { ++n[size_t(face)]; });
    return n;
}

constexpr double kEps = 1.0 / 16777216.0;  // 2^-24: float rounding, relative

// Largest error of a float grid coordinate computed as (x - origin) / dx: two roundings, each
// at most half an ulp of the largest coordinate (ulp(x) <= x 2^-23), doubled for margin.
double grid_coordinate_error(const ref::Grid& g) {
    return 2.0 * double(std::max({g.nx, g.ny, g.nz})) * 2.0 * kEps;
}

// Per face, the bound on |GPU - exact| of APIC's fixed-point momentum. Each contribution is
// roundEven(w (v_a + c_a . r) S_m) with r = (node - g) dx computed in float from the GPU's
// grid coordinate: 1/2 for the rounding to an integer, plus S_m times the float error of the
// addend: a few roundings of w |q| (4 eps), the weight's error from the coordinate error dg
// (|dw| <= 3 dg, each factor's slope is at most 1) times |q|, and w sum_k |c_ak| |dr_k|, with
// |dr_k| <= (dg + 2 eps |r_k / dx|) dx.
std::vector<double> apic_momentum_bound(const ref::Grid& g, const ref::Particles& p, double s_m) {
    std::vector<double> bound(size_t(g.faces()), 0.0);
    const double dg = grid_coordinate_error(g);
    for_each_contribution(g, p, [&](size_t q, int c, int face, double w, glm::dvec3 node) {
        const glm::dvec3 gp = g.to_grid(p.pos[q]);
        const glm::dvec3 r = (node - gp) * g.dx;
        const glm::dvec3 ca = p.affine[q][c];
        const double addend = std::abs(p.vel[q][c] + glm::dot(ca, r));
        double dr_term = 0;
        for (int k = 0; k < 3; ++k) dr_term += std::abs(ca[k]) * (dg + 2.0 * kEps * std::abs(node[k] - gp[k])) * g.dx;
        bound[size_t(face)] += 0.5 + s_m * (4.0 * kEps * w * addend + 3.0 * dg * addend + w * dr_term);
    });
    return bound;
}

// True when float rounding of the grid coordinate (dg) could put the particle on the other
// side of a node plane of some lattice than its exact coordinate: there the gradient of the
// trilinear interpolant (APIC's C) jumps, so GPU and reference may legitimately differ.
bool near_a_node_plane(const ref::Grid& g, const glm::dvec3& world) {
    const double dg = grid_coordinate_error(g);
    const glm::dvec3 gc = g.to_grid(world);
    for (int c = 0; c < 3; ++c)
        for (int a = 0; a < 3; ++a) {
            const double s = gc[a] - ref::Grid::face_offset_g(c)[a];
            if (std::abs(s - std::round(s)) <= 2.0 * dg) return true;
        }
    return false;
}

struct Pipeline {
    const char* name;
    pf_transfer transfer;
    pf_advection advection;
};
void PrintTo(const Pipeline& p, std::ostream* os) { *os << p.name; }
const Pipeline kPipelines[] = {{"FlipEuler", PF_TRANSFER_PIC_FLIP, PF_ADVECTION_EULER},
                               {"ApicRk2", PF_TRANSFER_APIC, PF_ADVECTION_RK2},
                               {"ApicRk3", PF_TRANSFER_APIC, PF_ADVECTION_RK3},
                               {"FlipRk2Offset", PF_TRANSFER_PIC_FLIP, PF_ADVECTION_RK2_OFFSET}};

class GpuVsReference : public GpuTest, public ::testing::WithParamInterface<std::tuple<uint32_t, Pipeline>> {};

TEST_P(GpuVsReference, EveryPassOfOneSubstep) {
    const uint32_t seed = std::get<0>(GetParam());
    const Pipeline pipeline = std::get<1>(GetParam());
    const bool apic = pipeline.transfer == PF_TRANSFER_APIC;
    pf_sim_desc d = test_desc(12, 10, 8, 0.1f);
    d.origin[0] = -0.5f;
    d.origin[1] = 0.25f;
    d.origin[2] = 1.0f;
    d.max_speed = 4.0f;                 // S_m = 2^18: fine fixed-point resolution
    d.params.flip_ratio = 0.9f;
    d.params.pressure_solver = PF_PRESSURE_SOLVER_JACOBI;  // the reference's; the others: test_solvers.cpp
    d.params.pressure_tolerance = 1e-4f;  // the fast preset's: far below what 30 sweeps reach, so all 30 run
    d.params.pressure_iterations = 30;
    d.params.jacobi_omega = 0.8f;
    d.params.extrapolation_layers = 3;
    d.params.gravity[0] = 1.5f;         // every axis gets a body force
    d.params.separation = seed % 2;     // odd seeds: projected Jacobi (p >= 0)
    // Seeds 2 and 3: the ghost-fluid surface (theta from the weights); 1 and 4: the marker cell.
    const bool ghost = (seed / 2) % 2 == 1;
    d.params.free_surface = ghost ? PF_FREE_SURFACE_GHOST_FLUID : PF_FREE_SURFACE_MARKER_CELL;
    d.params.transfer = pipeline.transfer;
    d.params.advection = pipeline.advection;
    d.params.gravity[2] = -0.5f;
    const double dt = 0.01, rho = d.density;
    const glm::dvec3 gravity(d.params.gravity[0], d.params.gravity[1], d.params.gravity[2]);

    Scene sc = random_scene(seed, d, 2500, 2.0f);
    SimPtr handle = create(d);
    ASSERT_TRUE(handle);
    ASSERT_EQ(pf_add_particles(handle.get(), sc.pos.data(), sc.vel.data(), uint32_t(sc.particles.pos.size())), PF_OK)
        << last_log();
    Simulation& sim = *pf::entry(handle)->impl;
    if (apic) {
        // Added particles start with C = 0; give them random affine vectors of up to 10 / s
        // (|c . r| up to ~4.5 m/s over a stencil, comparable to the velocities).
        const std::vector<float> zero = sim.read_affine();
        ASSERT_EQ(zero.size(), sc.particles.pos.size() * 12);
        for (float v : zero) ASSERT_EQ(v, 0.0f);
        std::mt19937 rng(seed + 100);
        std::uniform_real_distribution<float> uc(-10.0f, 10.0f);
        std::vector<float> affine(zero.size(), 0.0f);
        sc.particles.affine.resize(sc.particles.pos.size());
        for (size_t i = 0; i < sc.particles.pos.size(); ++i)
            for (int a = 0; a < 3; ++a)
                for (int k = 0; k < 3; ++k) {
                    affine[i * 12 + size_t(a) * 4 + size_t(k)] = uc(rng);
                    sc.particles.affine[i][a][k] = affine[i * 12 + size_t(a) * 4 + size_t(k)];
                }
        sim.write_affine_for_test(affine);
    }
    // The pressure the substep starts from (wall release reads the last solve's).
    const std::vector<double> last_pressure = words_as_floats(sim.read_grid(GridBuffer::pressure));
    ASSERT_EQ(sim.run_substep_for_test(float(dt)), PF_OK);
    const ref::Grid& g = sc.grid;

    // P2G, in fixed-point units: each contribution rounds by at most 1/2, plus float
    // rounding of w*v*S (relative 2^-23 per contribution, bounded by S per contribution).
    const double s_m = 1048576.0 / d.max_speed, s_w = 1048576.0;
    const ref::P2GResult p2g = apic ? ref::p2g_apic(g, sc.particles) : ref::p2g(g, sc.particles);
    const std::vector<uint32_t> accum = sim.read_grid(GridBuffer::face_accum);
    const std::vector<int> n = contributions(g, sc.particles);
    const std::vector<double> apic_bound = apic ? apic_momentum_bound(g, sc.particles, s_m) : std::vector<double>();
    double worst_m = 0, worst_w = 0;
    for (int f = 0; f < g.faces(); ++f) {
        const double m_gpu = double(int32_t(accum[2 * f])), w_gpu = double(int32_t(accum[2 * f + 1]));
        const double tol_m = (apic ? apic_bound[f] : n[f] * (0.5 + 4.0 * d.max_speed * s_m * 1.2e-7)) + 1e-9;
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
        type[c] = uint8_t(PF_CELL_KIND(type_words[c]));
    }
    EXPECT_EQ(type, ref::classify(g, p2g.count));

    // Grid forces: u_old = (M/S_m)/(W/S_w) from the GPU's own integer sums; then gravity and walls.
    const std::vector<double> vel_old = words_as_floats(sim.read_grid(GridBuffer::face_vel_old));
    ref::P2GResult gpu_p2g{std::vector<double>(size_t(g.faces())), std::vector<double>(size_t(g.faces())), p2g.count};
    for (int f = 0; f < g.faces(); ++f) {
        gpu_p2g.momentum[f] = double(int32_t(accum[2 * f])) / s_m;
        gpu_p2g.weight[f] = double(int32_t(accum[2 * f + 1])) / s_w;
    }
    ref::GridForces forces = ref::grid_forces(g, gpu_p2g, gravity, dt);
    for (int f = 0; f < g.faces(); ++f) {
        ASSERT_NEAR(vel_old[f], forces.vel_old[f], 1e-6 * (1.0 + std::abs(forces.vel_old[f]))) << "face " << f;
    }
    ref::wall_release(g, type, last_pressure, gravity, rho, forces.vel);

    // The free surface (§4.6a): theta per face (from the GPU's weights with the ghost fluid, 1 with
    // the marker cell), and each FLUID word's extra diagonal (fixed point, 1/PF_CELL_SURFACE_ONE, plus float rounding of 1/theta).
    const std::vector<double> theta_gpu = words_as_floats(sim.read_grid(GridBuffer::face_fraction));
    const std::vector<double> theta = ghost ? ref::free_surface_fractions(g, gpu_p2g.weight, double(d.fill_particles_per_cell))
                                            : std::vector<double>(size_t(g.faces()), 1.0);
    for (int f = 0; f < g.faces(); ++f) ASSERT_NEAR(theta_gpu[f], theta[f], 1e-5) << "face " << f;
    const std::vector<double> extra = ref::surface_extra_diagonal(g, type, theta_gpu);
    size_t surface_cells = 0;
    for (int c = 0; c < g.cells(); ++c) {
        const double got = double(type_words[c] >> PF_CELL_SURFACE_SHIFT) / PF_CELL_SURFACE_ONE;
        ASSERT_NEAR(got, extra[c], 1.0 / PF_CELL_SURFACE_ONE + 1e-6 * extra[c]) << "cell " << c;
        surface_cells += extra[c] > 0.0;
    }
    if (ghost) EXPECT_GT(surface_cells, 0u) << "the scene must have a free surface with theta < 1";
    else EXPECT_EQ(surface_cells, 0u) << "the marker-cell surface carries no extra diagonal";

    // Pressure setup: b = -div * rho dx / dt on FLUID cells.
    const std::vector<double> rhs = words_as_floats(sim.read_grid(GridBuffer::rhs));
    const std::vector<double> rhs_ref = ref::pressure_rhs(g, type, forces.vel, rho, dt);
    double rhs_scale = 0;
    for (double b : rhs_ref) rhs_scale = std::max(rhs_scale, std::abs(b));
    ASSERT_GT(rhs_scale, 1.0);
    for (int c = 0; c < g.cells(); ++c) ASSERT_NEAR(rhs[c], rhs_ref[c], 2e-5 * rhs_scale) << "cell " << c;

    // Jacobi: K weighted iterations on the GPU's right-hand side, from the hydrostatic start
    // (§4.5a: the first substep after particles were added).
    const std::vector<double> p = words_as_floats(sim.read_grid(GridBuffer::pressure));
    std::vector<double> p_start(size_t(g.cells()), 0.0);
    ref::hydrostatic_start(g, type, gravity, rho, p_start);
    const std::vector<double> p_ref = ref::jacobi(g, type, rhs, p_start,
                                                  int(d.params.pressure_iterations), d.params.jacobi_omega,
                                                  d.params.separation != 0, theta_gpu);
    double p_scale = 0;
    for (double v : p_ref) p_scale = std::max(p_scale, std::abs(v));
    ASSERT_GT(p_scale, 1.0);
    for (int c = 0; c < g.cells(); ++c) ASSERT_NEAR(p[c], p_ref[c], 1e-5 * p_scale) << "cell " << c;

    // Velocity update and extrapolation, from the GPU's pressure.
    ref::VelocityUpdate vu = ref::velocity_update(g, type, forces.vel, p, rho, dt, theta_gpu);
    ref::extrapolate(g, vu, int(d.params.extrapolation_layers));
    const std::vector<double> vel = words_as_floats(sim.read_grid(GridBuffer::face_vel));
    const std::vector<uint32_t> valid = sim.read_grid(GridBuffer::face_valid);
    double v_scale = 0;
    for (double v : vu.vel) v_scale = std::max(v_scale, std::abs(v));
    for (int f = 0; f < g.faces(); ++f) {
        ASSERT_EQ(valid[f] != 0, vu.valid[f] != 0) << "face " << f;
        ASSERT_NEAR(vel[f], vu.vel[f], 1e-5 * v_scale) << "face " << f;
    }

    // G2P from the GPU's face velocities, then advection (which also stops velocities at walls).
    ref::Particles expect = sc.particles;
    if (apic)
        ref::g2p_apic(g, expect, vel, d.max_speed);
    else
        ref::g2p(g, expect, vel, vel_old, d.params.flip_ratio, d.max_speed, gpu_p2g.weight, type);
    ref::Particles moved = expect;
    if (pipeline.advection == PF_ADVECTION_EULER)
        ref::advect(g, moved, dt);
    else
        ref::advect_rk(g, moved, vel, dt, ref::Advection(pipeline.advection));
    // Velocities: 1e-5 relative to the largest face velocity covers the float interpolation.
    // Positions: Euler's 1e-6 m (a few ulps of ~2 m coordinates); Runge-Kutta adds dt times
    // each stage's velocity error, which is the interpolation error plus the field's change
    // over the stage position's error (Lipschitz constant at most 2 v_scale / dx per axis).
    const double tol_v = 1e-5 * v_scale;
    const double tol_x = pipeline.advection == PF_ADVECTION_EULER
                             ? 1e-6
                             : 1e-6 + dt * tol_v * (1.0 + dt * 6.0 * v_scale / g.dx);
    ParticleState got = read_all(handle.get());
    for (size_t i = 0; i < got.count(); ++i) {
        for (int a = 0; a < 3; ++a) {
            ASSERT_NEAR(got.vel[i * 3 + a], moved.vel[i][a], tol_v) << "particle " << i;  // after the walls
            ASSERT_NEAR(got.pos[i * 3 + a], moved.pos[i][a], tol_x) << "particle " << i;
        }
    }
    if (!apic) return;
    // APIC's C = sum u_i grad w_i / dx: the float sums round by a few eps of sum |u_i| |dw_i|
    // <= 2 v_scale per axis (16 eps), and the coordinate error dg moves C by at most the
    // interpolant's mixed derivatives, 4 v_scale per cell per axis (3 axes: 12 dg).
    const std::vector<float> affine = sim.read_affine();
    ASSERT_EQ(affine.size(), got.count() * 12);
    const double tol_c = (32.0 * kEps + 12.0 * grid_coordinate_error(g)) * v_scale / g.dx;
    size_t skipped = 0;
    double worst_c = 0;
    for (size_t i = 0; i < got.count(); ++i) {
        if (near_a_node_plane(g, expect.pos[i])) {
            ++skipped;
            continue;
        }
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < 3; ++k)
                worst_c = std::max(worst_c, std::abs(affine[i * 12 + size_t(a) * 4 + size_t(k)] - expect.affine[i][a][k]));
    }
    EXPECT_LE(worst_c, tol_c) << "APIC affine vectors off by more than their rounding bound";
    EXPECT_LT(skipped, got.count() / 100) << "too many particles on node planes to check C";
}

INSTANTIATE_TEST_SUITE_P(RandomSeeds, GpuVsReference,
                         ::testing::Combine(::testing::Values(1u, 2u, 3u, 4u), ::testing::ValuesIn(kPipelines)),
                         [](const auto& info) {
                             return std::get<1>(info.param).name + std::to_string(std::get<0>(info.param));
                         });

}  // namespace
}  // namespace pf::test
