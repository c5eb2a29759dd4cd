// Self-tests of the double-precision CPU reference (tests/reference/), CPU only.
// They check the reference against physics and the docs/design.md contract, so that GPU
// tests can trust it as an oracle.
#include "reference/cpu_reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace pf::ref;

namespace {

constexpr double kGravity = -9.81;

double max_abs(const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
}

// n particles uniformly in the grid-coordinate box [lo, hi), velocities uniform in ±vmax.
Particles random_particles(const Grid& grid, int n, glm::dvec3 lo, glm::dvec3 hi, double vmax,
                           uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    Particles p;
    for (int i = 0; i < n; ++i) {
        glm::dvec3 g, v;
        for (int a = 0; a < 3; ++a) {
            g[a] = lo[a] + (hi[a] - lo[a]) * u01(rng);
            v[a] = vmax * (2.0 * u01(rng) - 1.0);
        }
        p.pos.push_back(grid.to_world(g));
        p.vel.push_back(v);
    }
    return p;
}

// Particles of a random sparse-ish fluid in the lower part of the grid, with air above.
struct Scene {
    Grid grid;
    Particles particles;
};

Scene random_scene(uint64_t seed) {
    Scene s;
    s.grid = Grid{8, 8, 8, 0.05, glm::dvec3(-0.2, 0.1, 0.3)};
    s.particles = random_particles(s.grid, 900, glm::dvec3(0.0), glm::dvec3(8.0, 5.0, 8.0), 1.5,
                                   seed);
    return s;
}

// Weighted residual ‖D^{-1/2}(b - A p)‖: damped Jacobi with ω <= 2/3 never increases it.
double weighted_residual(const Grid& grid, const std::vector<uint8_t>& type,
                         const std::vector<double>& b, const std::vector<double>& p) {
    const std::vector<double> Ap = laplacian(grid, type, p);
    double s = 0.0;
    for (int k = 0; k < grid.nz; ++k)
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i) {
                const int id = grid.cell_index(i, j, k);
                if (type[id] != FLUID) continue;
                const int diag = (i > 0) + (i + 1 < grid.nx) + (j > 0) + (j + 1 < grid.ny) +
                                 (k > 0) + (k + 1 < grid.nz);
                const double r = b[id] - Ap[id];
                s += r * r / diag;
            }
    return std::sqrt(s);
}

} // namespace

TEST(Reference, GridLayoutMatchesDesign) {
    const Grid g{3, 4, 5, 0.1, glm::dvec3(0.0)};
    EXPECT_EQ(g.cells(), 60);
    EXPECT_EQ(g.face_count(0), 4 * 4 * 5);
    EXPECT_EQ(g.face_count(1), 3 * 5 * 5);
    EXPECT_EQ(g.face_count(2), 3 * 4 * 6);
    EXPECT_EQ(g.faces(), 80 + 75 + 72);
    EXPECT_EQ(g.cell_index(2, 3, 4), 2 + 3 * (3 + 4 * 4));
    EXPECT_EQ(g.face_index(0, 3, 2, 1), 3 + 4 * (2 + 4 * 1));
    EXPECT_EQ(g.face_index(1, 2, 4, 1), 80 + 2 + 3 * (4 + 5 * 1));
    EXPECT_EQ(g.face_index(2, 1, 3, 5), 80 + 75 + 1 + 3 * (3 + 4 * 5));
    EXPECT_EQ(g.face_index(2, 2, 3, 5), g.faces() - 1);
    EXPECT_TRUE(g.is_wall_face(0, 0, 1, 1));
    EXPECT_TRUE(g.is_wall_face(0, 3, 1, 1));
    EXPECT_FALSE(g.is_wall_face(0, 1, 0, 0)); // j = 0 is not a wall for u
    EXPECT_TRUE(g.is_wall_face(2, 1, 1, 5));
}

// Uniform particle velocity → every reached face holds exactly that velocity; the stencil is
// a partition of unity (Σ W = N per lattice); counts land in clamp(floor(g)).
TEST(Reference, P2GUniformVelocityAndPartitionOfUnity) {
    const Grid grid{6, 5, 4, 0.1, glm::dvec3(1.0, -2.0, 0.5)};
    Particles p = random_particles(grid, 300, glm::dvec3(0.0), glm::dvec3(6.0, 5.0, 4.0), 0.0, 7);
    const glm::dvec3 v(0.7, -1.3, 2.1);
    for (auto& pv : p.vel) pv = v;
    const P2GResult r = p2g(grid, p);

    int reached = 0;
    for (int c = 0; c < 3; ++c) {
        double wsum = 0.0;
        for (int f = grid.face_offset(c); f < grid.face_offset(c) + grid.face_count(c); ++f) {
            wsum += r.weight[f];
            if (r.weight[f] > 0.0) {
                ++reached;
                EXPECT_NEAR(r.momentum[f] / r.weight[f], v[c], 1e-12) << "c=" << c << " f=" << f;
            } else {
                EXPECT_EQ(r.momentum[f], 0.0);
            }
        }
        EXPECT_NEAR(wsum, 300.0, 1e-9) << "c=" << c;
    }
    EXPECT_GT(reached, grid.faces() / 2);

    std::vector<uint32_t> expect(grid.cells(), 0);
    for (const auto& x : p.pos) {
        const glm::ivec3 c = glm::ivec3(glm::floor(grid.to_grid(x)));
        ++expect[grid.cell_index(c.x, c.y, c.z)];
    }
    EXPECT_EQ(r.count, expect);

    // A particle exactly on the upper domain corner is counted in the last cell (clamp).
    Particles corner{{grid.to_world(glm::dvec3(6.0, 5.0, 4.0))}, {glm::dvec3(0.0)}};
    EXPECT_EQ(p2g(grid, corner).count[grid.cell_index(5, 4, 3)], 1u);
}

TEST(Reference, ClassifyAndGridForces) {
    const Grid grid{5, 6, 4, 0.1, glm::dvec3(0.0)};
    const Particles p =
        random_particles(grid, 120, glm::dvec3(0.0), glm::dvec3(5.0, 3.0, 4.0), 2.0, 11);
    const P2GResult acc = p2g(grid, p);

    const std::vector<uint8_t> type = classify(grid, acc.count);
    for (int c = 0; c < grid.cells(); ++c) EXPECT_EQ(type[c], acc.count[c] > 0 ? FLUID : AIR);

    const glm::dvec3 gravity(0.5, kGravity, 1.0);
    const double dt = 0.01;
    const GridForces f = grid_forces(grid, acc, gravity, dt);
    int walls_with_old = 0;
    for (int c = 0; c < 3; ++c) {
        const glm::ivec3 d = grid.face_dims(c);
        for (int k = 0; k < d.z; ++k)
            for (int j = 0; j < d.y; ++j)
                for (int i = 0; i < d.x; ++i) {
                    const int id = grid.face_index(c, i, j, k);
                    const double W = acc.weight[id];
                    if (W == 0.0) {
                        EXPECT_EQ(f.vel[id], 0.0);
                        EXPECT_EQ(f.vel_old[id], 0.0);
                        continue;
                    }
                    EXPECT_DOUBLE_EQ(f.vel_old[id], acc.momentum[id] / W);
                    if (grid.is_wall_face(c, i, j, k)) {
                        EXPECT_EQ(f.vel[id], 0.0);
                        walls_with_old += f.vel_old[id] != 0.0;
                    } else {
                        EXPECT_NEAR(f.vel[id], f.vel_old[id] + dt * gravity[c], 1e-15);
                    }
                }
    }
    EXPECT_GT(walls_with_old, 0); // wall u_old keeps the P2G value (FLIP needs it)
}

TEST(Reference, InterpolateLinearFieldAndClamp) {
    const Grid grid{6, 7, 5, 0.2, glm::dvec3(-1.0, 0.5, 2.0)};
    const glm::dmat3 A(0.3, -1.2, 0.8, 2.0, 0.1, -0.7, -0.4, 1.1, 0.9);
    const glm::dvec3 B(0.25, -3.0, 1.5);
    auto F = [&](glm::dvec3 x) { return A * x + B; };

    std::vector<double> field(grid.faces());
    for (int c = 0; c < 3; ++c) {
        const glm::ivec3 d = grid.face_dims(c);
        for (int k = 0; k < d.z; ++k)
            for (int j = 0; j < d.y; ++j)
                for (int i = 0; i < d.x; ++i) {
                    const glm::dvec3 g = glm::dvec3(i, j, k) + Grid::face_offset_g(c);
                    field[grid.face_index(c, i, j, k)] = F(grid.to_world(g))[c];
                }
    }

    // Inside g ∈ [1, n-1] no lattice clamps: trilinear reproduces linear fields exactly.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int t = 0; t < 200; ++t) {
        glm::dvec3 g;
        for (int a = 0; a < 3; ++a) g[a] = 1.0 + (grid.cell_dims()[a] - 2.0) * u01(rng);
        const glm::dvec3 x = grid.to_world(g), got = interpolate(grid, field, x), want = F(x);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-12);
    }

    // Below g_y = ½ the u and w lattices clamp (constant extension); v (offset 0) does not.
    const glm::dvec3 g_low(2.3, 0.2, 3.1), g_half(2.3, 0.5, 3.1);
    const glm::dvec3 low = interpolate(grid, field, grid.to_world(g_low));
    const glm::dvec3 half = interpolate(grid, field, grid.to_world(g_half));
    EXPECT_NEAR(low.x, half.x, 1e-12);
    EXPECT_NEAR(low.z, half.z, 1e-12);
    EXPECT_NEAR(low.y, F(grid.to_world(g_low)).y, 1e-12);
    EXPECT_GT(std::abs(low.x - F(grid.to_world(g_low)).x), 1e-3); // the clamp is real
}

// The converged solve makes the updated velocity divergence free in every FLUID cell.
TEST(Reference, ExactPressureRemovesDivergence) {
    const Scene s = random_scene(21);
    const double dt = 1.0 / 120.0, rho = 1000.0;
    const P2GResult acc = p2g(s.grid, s.particles);
    const GridForces f = grid_forces(s.grid, acc, glm::dvec3(0, kGravity, 0), dt);
    const std::vector<uint8_t> type = classify(s.grid, acc.count);
    ASSERT_GT(std::count(type.begin(), type.end(), AIR), 100);
    ASSERT_GT(std::count(type.begin(), type.end(), FLUID), 200);

    const std::vector<double> b = pressure_rhs(s.grid, type, f.vel, rho, dt);
    const std::vector<double> p = solve_pressure_exact(s.grid, type, b);
    std::vector<double> res = laplacian(s.grid, type, p);
    for (size_t i = 0; i < res.size(); ++i) res[i] -= b[i];
    EXPECT_LT(max_abs(res), 1e-11 * max_abs(b));

    const double div_before = max_abs(divergence(s.grid, type, f.vel));
    ASSERT_GT(div_before, 0.1);
    const VelocityUpdate upd = velocity_update(s.grid, type, f.vel, p, rho, dt);
    EXPECT_LT(max_abs(divergence(s.grid, type, upd.vel)), 1e-9 * div_before);

    // Validity: walls and faces touching FLUID are valid, faces between two AIR cells not.
    const Grid& g = s.grid;
    for (int c = 0; c < 3; ++c) {
        const glm::ivec3 d = g.face_dims(c);
        for (int k = 0; k < d.z; ++k)
            for (int j = 0; j < d.y; ++j)
                for (int i = 0; i < d.x; ++i) {
                    const int id = g.face_index(c, i, j, k);
                    if (g.is_wall_face(c, i, j, k)) {
                        EXPECT_EQ(upd.valid[id], 1);
                        EXPECT_EQ(upd.vel[id], 0.0);
                        continue;
                    }
                    glm::ivec3 lo(i, j, k);
                    lo[c] -= 1;
                    const bool fluid = type[g.cell_index(lo.x, lo.y, lo.z)] == FLUID ||
                                       type[g.cell_index(i, j, k)] == FLUID;
                    EXPECT_EQ(upd.valid[id], fluid ? 1 : 0);
                    if (!fluid) {
                        EXPECT_EQ(upd.vel[id], 0.0);
                    }
                }
    }
}

// Damped Jacobi (ω = 2/3) never increases the D^{-1/2}-weighted residual, and many sweeps
// reach the converged solution; starting from the solution it stays there.
TEST(Reference, JacobiConvergesToExactSolve) {
    const Scene s = random_scene(5);
    const double dt = 1.0 / 120.0, rho = 1000.0;
    const P2GResult acc = p2g(s.grid, s.particles);
    const GridForces f = grid_forces(s.grid, acc, glm::dvec3(0, kGravity, 0), dt);
    const std::vector<uint8_t> type = classify(s.grid, acc.count);
    const std::vector<double> b = pressure_rhs(s.grid, type, f.vel, rho, dt);
    const std::vector<double> exact = solve_pressure_exact(s.grid, type, b);

    // Garbage in non-FLUID cells of p0 must be ignored.
    std::vector<double> p(s.grid.cells(), 0.0);
    for (int c = 0; c < s.grid.cells(); ++c)
        if (type[c] != FLUID) p[c] = 1e6;
    const double r0 = weighted_residual(s.grid, type, b, jacobi(s.grid, type, b, p, 0, 2.0 / 3.0));
    EXPECT_NEAR(r0, weighted_residual(s.grid, type, b, std::vector<double>(p.size(), 0.0)),
                1e-12 * r0);
    double prev = r0;
    for (int it = 0; it < 400; ++it) {
        p = jacobi(s.grid, type, b, p, 1, 2.0 / 3.0);
        const double r = weighted_residual(s.grid, type, b, p);
        ASSERT_LE(r, prev * (1.0 + 1e-12)) << "iteration " << it;
        prev = r;
    }
    EXPECT_LT(prev, 0.5 * r0);

    p = jacobi(s.grid, type, b, p, 5000, 2.0 / 3.0);
    double err = 0.0;
    for (int c = 0; c < s.grid.cells(); ++c) {
        err = std::max(err, std::abs(p[c] - exact[c]));
        if (type[c] != FLUID) {
            EXPECT_EQ(p[c], 0.0);
        }
    }
    EXPECT_LT(err, 1e-8 * max_abs(exact));

    // The exact solution is a fixed point of Jacobi for any ω.
    const std::vector<double> q = jacobi(s.grid, type, b, exact, 50, 1.0);
    for (int c = 0; c < s.grid.cells(); ++c) EXPECT_NEAR(q[c], exact[c], 1e-9 * max_abs(exact));
}

// One valid source spreads exactly one lattice step per layer (old/new mask), within its
// own component; averaging takes the mean of valid neighbours.
TEST(Reference, ExtrapolateLayerByLayer) {
    const Grid grid{5, 5, 5, 0.1, glm::dvec3(0.0)};
    VelocityUpdate v{std::vector<double>(grid.faces(), 0.0),
                     std::vector<uint8_t>(grid.faces(), 0)};
    const glm::ivec3 src(2, 2, 2);
    v.vel[grid.face_index(0, src.x, src.y, src.z)] = 3.0;
    v.valid[grid.face_index(0, src.x, src.y, src.z)] = 1;
    extrapolate(grid, v, 2);
    for (int c = 0; c < 3; ++c) {
        const glm::ivec3 d = grid.face_dims(c);
        for (int k = 0; k < d.z; ++k)
            for (int j = 0; j < d.y; ++j)
                for (int i = 0; i < d.x; ++i) {
                    const int id = grid.face_index(c, i, j, k);
                    const int dist = std::abs(i - src.x) + std::abs(j - src.y) + std::abs(k - src.z);
                    const bool want = c == 0 && dist <= 2;
                    EXPECT_EQ(v.valid[id], want ? 1 : 0) << c << " " << i << j << k;
                    if (want) {
                        EXPECT_EQ(v.vel[id], 3.0);
                    }
                }
    }

    // Two sources two steps apart along j: after one layer the middle face is their mean,
    // and a face beside one source sees only that source.
    VelocityUpdate w{std::vector<double>(grid.faces(), 0.0),
                     std::vector<uint8_t>(grid.faces(), 0)};
    const int a = grid.face_index(1, 1, 1, 1), b = grid.face_index(1, 1, 3, 1);
    w.vel[a] = 1.0, w.vel[b] = 4.0, w.valid[a] = w.valid[b] = 1;
    extrapolate(grid, w, 1);
    EXPECT_EQ(w.vel[grid.face_index(1, 1, 2, 1)], 2.5);
    EXPECT_EQ(w.vel[grid.face_index(1, 0, 1, 1)], 1.0);
    EXPECT_EQ(w.valid[grid.face_index(1, 0, 2, 1)], 0); // two steps from both
}

TEST(Reference, G2PBlendClampAndNonFinite) {
    const Grid grid{4, 4, 4, 0.1, glm::dvec3(0.0)};
    const glm::dvec3 u(1.0, 2.0, -3.0), delta(0.5, -0.25, 0.125);
    std::vector<double> vel(grid.faces()), vel_old(grid.faces());
    for (int c = 0; c < 3; ++c)
        for (int f = grid.face_offset(c); f < grid.face_offset(c) + grid.face_count(c); ++f) {
            vel[f] = u[c];
            vel_old[f] = u[c] - delta[c];
        }
    // Positions include clamped border regions: uniform fields are still exact there.
    Particles p = random_particles(grid, 50, glm::dvec3(0.001), glm::dvec3(3.999), 2.0, 9);
    const Particles p0 = p;
    const double r = 0.8;
    g2p(grid, p, vel, vel_old, r, 100.0);
    for (size_t i = 0; i < p.pos.size(); ++i) {
        const glm::dvec3 want = (1.0 - r) * u + r * (p0.vel[i] + delta);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p.vel[i][c], want[c], 1e-12);
    }

    // Speed clamp keeps direction.
    p = p0;
    g2p(grid, p, vel, vel_old, 0.0, 1.5);
    for (const auto& v : p.vel) {
        EXPECT_NEAR(glm::length(v), 1.5, 1e-12);
        EXPECT_NEAR(glm::dot(v, u) / (1.5 * glm::length(u)), 1.0, 1e-12);
    }

    // A non-finite interpolated value zeroes the whole velocity.
    p = p0;
    std::fill(vel.begin() + grid.face_offset(1), vel.begin() + grid.face_offset(2),
              std::numeric_limits<double>::quiet_NaN());
    g2p(grid, p, vel, vel_old, 0.5, 100.0);
    for (const auto& v : p.vel) EXPECT_EQ(v, glm::dvec3(0.0));
}

// Inside: x += dt v. Beyond a wall by more than 1e-3 cells: back a quarter cell inside, the
// velocity into that wall dropped. Within 1e-3 cells of the plane: kept 1e-3 inside, v kept.
TEST(Reference, AdvectEulerAndClamp) {
    const Grid grid{4, 5, 6, 0.5, glm::dvec3(1.0, 2.0, 3.0)};
    const double grazing = (1.0 + 5e-4) * 0.5 / 0.2;  // reaches g.x = -5e-4
    Particles p{{grid.to_world(glm::dvec3(2.0, 2.5, 3.0)), grid.to_world(glm::dvec3(0.5, 4.5, 5.9)),
                 grid.to_world(glm::dvec3(1.0, 2.0, 3.0))},
                {glm::dvec3(0.5, -0.25, 1.0), glm::dvec3(-10.0, 10.0, -0.5), glm::dvec3(-grazing, 0.0, 0.0)}};
    advect(grid, p, 0.2);
    const glm::dvec3 g0 = grid.to_grid(p.pos[0]), g1 = grid.to_grid(p.pos[1]), g2 = grid.to_grid(p.pos[2]);
    EXPECT_NEAR(g0.x, 2.0 + 0.2 * 0.5 / 0.5, 1e-12);
    EXPECT_NEAR(g0.y, 2.5 - 0.2 * 0.25 / 0.5, 1e-12);
    EXPECT_NEAR(g0.z, 3.0 + 0.2 * 1.0 / 0.5, 1e-12);
    EXPECT_EQ(p.vel[0], glm::dvec3(0.5, -0.25, 1.0));
    EXPECT_NEAR(g1.x, 0.25, 1e-12);
    EXPECT_NEAR(g1.y, 5.0 - 0.25, 1e-12);
    EXPECT_NEAR(g1.z, 5.9 - 0.2 * 0.5 / 0.5, 1e-12);
    EXPECT_EQ(p.vel[1], glm::dvec3(0.0, 0.0, -0.5));
    EXPECT_NEAR(g2.x, 1e-3, 1e-12);
    EXPECT_EQ(p.vel[2], glm::dvec3(-grazing, 0.0, 0.0));
}

// A face field sampling the affine velocity V(x) = a + G x (V_c at each face of lattice c).
struct AffineField {
    glm::dvec3 a;
    glm::dmat3 G;  // glm is column-major: G[k][c] = dV_c/dx_k
    glm::dvec3 at(const glm::dvec3& x) const { return a + G * x; }
    std::vector<double> faces(const Grid& grid) const {
        std::vector<double> f(grid.faces());
        for (int c = 0; c < 3; ++c) {
            const glm::ivec3 d = grid.face_dims(c);
            for (int k = 0; k < d.z; ++k)
                for (int j = 0; j < d.y; ++j)
                    for (int i = 0; i < d.x; ++i)
                        f[grid.face_index(c, i, j, k)] =
                            at(grid.to_world(glm::dvec3(i, j, k) + Grid::face_offset_g(c)))[c];
        }
        return f;
    }
};

const AffineField kShearAndSpin{glm::dvec3(0.3, -0.2, 0.1),
                                glm::dmat3(0.5, -1.5, 0.25, 1.5, -0.25, 0.75, -0.5, 0.2, 0.1)};

// Away from the clamped border the trilinear interpolant reproduces an affine field, so APIC's
// G2P returns its value and, as affine vectors, the rows of its gradient. Where the clamp holds
// an axis (within half a cell of a wall on a tangential lattice) that gradient entry is 0.
TEST(Reference, ApicG2PRecoversAnAffineFieldAndItsGradient) {
    const Grid grid{6, 5, 4, 0.2, glm::dvec3(-0.3, 0.2, 1.0)};
    const std::vector<double> faces = kShearAndSpin.faces(grid);
    Particles p = random_particles(grid, 200, glm::dvec3(0.5), glm::dvec3(5.5, 4.5, 3.5), 0.0, 21);
    g2p_apic(grid, p, faces, 100.0);
    ASSERT_EQ(p.affine.size(), p.pos.size());
    for (size_t i = 0; i < p.pos.size(); ++i) {
        const glm::dvec3 want = kShearAndSpin.at(p.pos[i]);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(p.vel[i][c], want[c], 1e-12);
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.affine[i][c][k], kShearAndSpin.G[k][c], 1e-11);
        }
    }
    // In the clamped band next to the x = 0 wall, the v and w lattices hold x still.
    Particles edge{{grid.to_world(glm::dvec3(0.2, 2.5, 2.0))}, {glm::dvec3(0.0)}, {}};
    g2p_apic(grid, edge, faces, 100.0);
    EXPECT_NEAR(edge.affine[0][0][0], kShearAndSpin.G[0][0], 1e-11);  // u lattice: unclamped in x
    EXPECT_EQ(edge.affine[0][1][0], 0.0);
    EXPECT_EQ(edge.affine[0][2][0], 0.0);
    EXPECT_NEAR(edge.affine[0][1][1], kShearAndSpin.G[1][1], 1e-11);
}

// The speed clamp scales C with v; |C|_F dx is then limited to max_speed; NaN zeroes both.
TEST(Reference, ApicG2PClampsAndGuards) {
    const Grid grid{6, 6, 6, 0.1, glm::dvec3(0.0)};
    std::vector<double> faces = kShearAndSpin.faces(grid);
    Particles p{{grid.to_world(glm::dvec3(3.2, 2.7, 3.4))}, {glm::dvec3(0.0)}, {}};
    Particles free = p;
    g2p_apic(grid, free, faces, 100.0);
    const double speed = glm::length(free.vel[0]);
    Particles slow = p;
    g2p_apic(grid, slow, faces, 0.5 * speed);
    EXPECT_NEAR(glm::length(slow.vel[0]), 0.5 * speed, 1e-12);
    for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(slow.affine[0][a][k], 0.5 * free.affine[0][a][k], 1e-12);
    // A fast spin about the particle: v = 0 there, |C|_F = sqrt(2) 100 / s, limited to max_speed / dx.
    const glm::dvec3 centre = p.pos[0];
    const glm::dmat3 spin(0.0, 100.0, 0.0, -100.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    const AffineField vortex{-(spin * centre), spin};
    Particles steep = p;
    g2p_apic(grid, steep, vortex.faces(grid), 1.0);
    double norm2 = 0;
    for (const glm::dvec3& c : steep.affine[0]) norm2 += glm::dot(c, c);
    EXPECT_NEAR(std::sqrt(norm2) * grid.dx, 1.0, 1e-12);
    EXPECT_NEAR(steep.affine[0][1][0] / steep.affine[0][0][1], -1.0, 1e-12);  // still a rotation
    EXPECT_LT(glm::length(steep.vel[0]), 1e-12);
    std::fill(faces.begin(), faces.begin() + grid.face_count(0), std::numeric_limits<double>::quiet_NaN());
    g2p_apic(grid, p, faces, 100.0);
    EXPECT_EQ(p.vel[0], glm::dvec3(0.0));
    for (const glm::dvec3& c : p.affine[0]) EXPECT_EQ(c, glm::dvec3(0.0));
}

// APIC's P2G is affine-exact: particles anywhere that carry an affine field (v = V(x_p), C = G)
// hand every face they reach the field's value there, M / W = V_c(x_i), however unevenly they
// are spread. Plain PIC's P2G only gets the average of the particles' velocities.
TEST(Reference, ApicP2GTransfersAnAffineFieldExactly) {
    const Grid grid{6, 5, 4, 0.2, glm::dvec3(-0.3, 0.2, 1.0)};
    Particles p = random_particles(grid, 60, glm::dvec3(0.0), glm::dvec3(6.0, 5.0, 4.0), 0.0, 23);
    Affine c;
    for (int a = 0; a < 3; ++a) c[a] = glm::dvec3(kShearAndSpin.G[0][a], kShearAndSpin.G[1][a], kShearAndSpin.G[2][a]);
    for (size_t i = 0; i < p.pos.size(); ++i) {
        p.vel[i] = kShearAndSpin.at(p.pos[i]);
        p.affine.push_back(c);
    }
    const P2GResult apic = p2g_apic(grid, p), pic = p2g(grid, p);
    const std::vector<double> want = kShearAndSpin.faces(grid);
    double worst_apic = 0, worst_pic = 0;
    for (int f = 0; f < grid.faces(); ++f) {
        if (!(apic.weight[f] > 0.0)) continue;
        EXPECT_EQ(apic.weight[f], pic.weight[f]);
        worst_apic = std::max(worst_apic, std::abs(apic.momentum[f] / apic.weight[f] - want[f]));
        worst_pic = std::max(worst_pic, std::abs(pic.momentum[f] / pic.weight[f] - want[f]));
    }
    EXPECT_LT(worst_apic, 1e-12);
    EXPECT_GT(worst_pic, 0.05);  // the same particles through plain P2G (the test can fail)
    EXPECT_EQ(apic.count, pic.count);
}

// On an affine field x' = a + G x (exact in the interior) one Runge-Kutta step of order p is
// the Taylor polynomial of the flow to degree p: x + h f + h^2/2 G f (+ h^3/6 G^2 f), f = a + G x.
TEST(Reference, RungeKuttaStepsAreTheTaylorPolynomialsOnAnAffineField) {
    const Grid grid{8, 8, 8, 0.25, glm::dvec3(-1.0)};
    const std::vector<double> faces = kShearAndSpin.faces(grid);
    const Particles start = random_particles(grid, 50, glm::dvec3(2.5), glm::dvec3(5.5), 0.0, 25);
    const double h = 0.1;
    for (Advection scheme : {Advection::rk2, Advection::rk3}) {
        Particles p = start;
        advect_rk(grid, p, faces, h, scheme);
        for (size_t i = 0; i < p.pos.size(); ++i) {
            const glm::dvec3 f = kShearAndSpin.at(start.pos[i]);
            glm::dvec3 want = start.pos[i] + h * f + h * h / 2.0 * (kShearAndSpin.G * f);
            if (scheme == Advection::rk3) want += h * h * h / 6.0 * (kShearAndSpin.G * (kShearAndSpin.G * f));
            for (int a = 0; a < 3; ++a) EXPECT_NEAR(p.pos[i][a], want[a], 1e-13) << int(scheme);
        }
    }
}

// Every stage position and the result go through the wall clamp: a particle rushing at a wall
// stops at the margin, and its later stages sample the field there, not beyond the wall. The
// moves here cross up to 5 cells in one sub-step (the trace's sub-steps of 16 cells), so the
// scheme's own stages are what is tested.
TEST(Reference, RungeKuttaKeepsStagesInsideTheDomain) {
    constexpr double kOneMove = 16.0;
    const Grid grid{4, 4, 4, 0.5, glm::dvec3(0.0)};
    std::vector<double> faces(grid.faces(), 0.0);
    // u grows towards the x = 4 wall; a stage beyond the wall would sample the clamped value.
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i <= 4; ++i) faces[grid.face_index(0, i, j, k)] = 10.0 + i;
    for (Advection scheme : {Advection::rk2, Advection::rk3}) {
        // Its own velocity would reach x = 3.9 and y = 1: only the traced path crosses a wall.
        Particles p{{grid.to_world(glm::dvec3(3.5, 2.0, 2.0))}, {glm::dvec3(0.2, -0.5, 0.0)}, {}};
        advect_rk(grid, p, faces, 1.0, scheme, kOneMove);
        EXPECT_NEAR(grid.to_grid(p.pos[0]).x, 4.0 - 0.25, 1e-12);  // returned a quarter cell inside
        EXPECT_NEAR(grid.to_grid(p.pos[0]).y, 2.0, 1e-12);
        EXPECT_EQ(p.vel[0], glm::dvec3(0.0, -0.5, 0.0));  // the wall stops the motion into it
        // The path (v = 0 on the y lattice) stays at y = 0.5, but the particle's own velocity
        // would cross the floor in the substep: Euler's rule stops that motion too.
        Particles q{{grid.to_world(glm::dvec3(2.0, 0.5, 2.0))}, {glm::dvec3(0.0, -2.0, 0.0)}, {}};
        std::vector<double> still(grid.faces(), 0.0);
        advect_rk(grid, q, still, 1.0, scheme, kOneMove);
        EXPECT_NEAR(grid.to_grid(q.pos[0]).y, 0.5, 1e-12);
        EXPECT_EQ(q.vel[0], glm::dvec3(0.0));
    }
    // Midpoint from g = 1.2 with dt such that the half step lands beyond the wall: the stage is
    // returned to 4 - 1/4, where u = 10 + 3.75 (in grid units 2 * 13.75 per second).
    Particles p{{grid.to_world(glm::dvec3(1.2, 2.0, 2.0))}, {glm::dvec3(0.0)}, {}};
    const double dt = 0.1;  // half step: 1.2 + 0.05 * 11.2 / 0.5 = 2.32; full: 1.2 + 0.1 * 12.16 / 0.5
    advect_rk(grid, p, faces, dt, Advection::rk2, kOneMove);
    const double k2 = 10.0 + (1.2 + 0.5 * dt * 11.2 / 0.5);
    EXPECT_NEAR(grid.to_grid(p.pos[0]).x, 1.2 + dt * k2 / 0.5, 1e-12);
    Particles q{{grid.to_world(glm::dvec3(1.2, 2.0, 2.0))}, {glm::dvec3(0.0)}, {}};
    advect_rk(grid, q, faces, 0.3, Advection::rk2, kOneMove);  // half step: 4.56 > 4, returned to 3.75
    EXPECT_NEAR(grid.to_grid(q.pos[0]).x, 4.0 - 0.25, 1e-12);  // 1.2 + 0.3 * 13.75 / 0.5 > 4 too
}

// A blob far from walls in free fall: uniform velocity is divergence free, so pressure is
// ~0 and every particle (PIC and FLIP alike) just gains dt·g.
TEST(Reference, FreeFallBlobGainsGravity) {
    const Grid grid{10, 10, 10, 0.1, glm::dvec3(0.0)};
    Particles p = random_particles(grid, 400, glm::dvec3(3.0), glm::dvec3(7.0), 0.0, 17);
    const glm::dvec3 v0(0.3, 0.5, -0.2);
    for (auto& v : p.vel) v = v0;
    const Particles start = p;
    SubstepState st;
    const double dt = 0.01;
    substep(grid, p, st, glm::dvec3(0, kGravity, 0), dt, 1000.0, 0.9, 40, 1.0, 2, 50.0);
    EXPECT_LT(max_abs(st.pressure), 1e-6); // Pa; hydrostatic scale here would be ~1e3
    const glm::dvec3 v1 = v0 + dt * glm::dvec3(0, kGravity, 0);
    for (size_t i = 0; i < p.pos.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(p.vel[i][c], v1[c], 1e-10);
            EXPECT_NEAR(p.pos[i][c], start.pos[i][c] + dt * v1[c], 1e-12);
        }
    }
}

namespace {
// Bottom `depth` cell layers filled with 8 jittered particles per cell, at rest.
Particles hydrostatic_column(const Grid& grid, int depth) {
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    Particles p;
    for (int k = 0; k < grid.nz; ++k)
        for (int j = 0; j < depth; ++j)
            for (int i = 0; i < grid.nx; ++i)
                for (int s = 0; s < 8; ++s) {
                    const glm::dvec3 g(i + 0.25 + 0.5 * (s & 1) + 0.2 * jitter(rng),
                                       j + 0.25 + 0.5 * ((s >> 1) & 1) + 0.2 * jitter(rng),
                                       k + 0.25 + 0.5 * (s >> 2) + 0.2 * jitter(rng));
                    p.pos.push_back(grid.to_world(g));
                    p.vel.push_back(glm::dvec3(0.0));
                }
    return p;
}

double max_speed_of(const Particles& p) {
    double m = 0.0;
    for (const auto& v : p.vel) m = std::max(m, glm::length(v));
    return m;
}

double max_displacement(const Grid& grid, const Particles& a, const Particles& b) {
    double m = 0.0;
    for (size_t i = 0; i < a.pos.size(); ++i) m = std::max(m, glm::length(a.pos[i] - b.pos[i]));
    return m / grid.dx;
}
} // namespace

// Fluid at rest in the bottom half stays at rest with a converged pressure, and the pressure
// is the discrete hydrostatic one: p_j = ρ·|g|·dx·(depth - j) (free surface p = 0 one cell up).
TEST(Reference, HydrostaticColumnStaysAtRestExact) {
    const Grid grid{6, 8, 6, 0.1, glm::dvec3(-0.3, 0.0, 0.0)};
    const int depth = 4;
    Particles p = hydrostatic_column(grid, depth);
    const Particles start = p;
    SubstepState st;
    const double rho = 1000.0, dt = 1.0 / 240.0;
    for (int s = 0; s < 20; ++s)
        substep(grid, p, st, glm::dvec3(0, kGravity, 0), dt, rho, 0.95, -1, 1.0, 3, 20.0);
    EXPECT_LT(max_speed_of(p), 1e-9);                  // m/s
    EXPECT_LT(max_displacement(grid, p, start), 1e-9); // cells
    for (int k = 0; k < grid.nz; ++k)
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i) {
                const double want = j < depth ? rho * -kGravity * grid.dx * (depth - j) : 0.0;
                EXPECT_NEAR(st.pressure[grid.cell_index(i, j, k)], want, 1e-8 * rho);
            }
}

// Same column through the real Jacobi path: the warm start carries convergence across
// substeps, so the residual motion stays small.
TEST(Reference, HydrostaticColumnStaysAtRestJacobi) {
    const Grid grid{6, 8, 6, 0.1, glm::dvec3(-0.3, 0.0, 0.0)};
    Particles p = hydrostatic_column(grid, 4);
    const Particles start = p;
    SubstepState st;
    for (int s = 0; s < 20; ++s)
        substep(grid, p, st, glm::dvec3(0, kGravity, 0), 1.0 / 240.0, 1000.0, 0.95, 150, 1.0, 3,
                20.0);
    EXPECT_LT(max_speed_of(p), 1e-5);                  // m/s (free fall: 0.8, 20 sweeps: 3e-4)
    EXPECT_LT(max_displacement(grid, p, start), 5e-4); // cells (no pressure: 0.36)
}

// Mirroring x (g → n - g, v_x → -v_x) commutes with a full substep.
TEST(Reference, MirrorSymmetryAcrossX) {
    const Grid grid{7, 6, 5, 0.1, glm::dvec3(0.4, -0.2, 0.1)};
    Particles a = random_particles(grid, 600, glm::dvec3(0.0), glm::dvec3(7.0, 4.0, 5.0), 3.0, 42);
    Particles b = a;
    auto mirror_g = [&](glm::dvec3 g) { return glm::dvec3(grid.nx - g.x, g.y, g.z); };
    for (size_t i = 0; i < b.pos.size(); ++i) {
        b.pos[i] = grid.to_world(mirror_g(grid.to_grid(a.pos[i])));
        b.vel[i].x = -b.vel[i].x;
    }
    // max_speed 4 clamps some particles: the clamp must be symmetric too.
    SubstepState sa, sb;
    substep(grid, a, sa, glm::dvec3(0, kGravity, 0), 1.0 / 60.0, 1000.0, 0.9, 30, 0.8, 2, 4.0);
    substep(grid, b, sb, glm::dvec3(0, kGravity, 0), 1.0 / 60.0, 1000.0, 0.9, 30, 0.8, 2, 4.0);
    ASSERT_GT(max_speed_of(a), 1.0);
    for (size_t i = 0; i < a.pos.size(); ++i) {
        const glm::dvec3 ga = grid.to_grid(a.pos[i]), gb = mirror_g(grid.to_grid(b.pos[i]));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(ga[c], gb[c], 1e-9);
        EXPECT_NEAR(a.vel[i].x, -b.vel[i].x, 1e-9);
        EXPECT_NEAR(a.vel[i].y, b.vel[i].y, 1e-9);
        EXPECT_NEAR(a.vel[i].z, b.vel[i].z, 1e-9);
    }
    const double pscale = std::max(1.0, max_abs(sa.pressure));
    for (int k = 0; k < grid.nz; ++k)
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i)
                EXPECT_NEAR(sa.pressure[grid.cell_index(i, j, k)],
                            sb.pressure[grid.cell_index(grid.nx - 1 - i, j, k)], 1e-9 * pscale);
}
