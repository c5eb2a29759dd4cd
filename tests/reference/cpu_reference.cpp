// Double-precision CPU reference of one pflip substep; see cpu_reference.h and docs/design.md.
#include "reference/cpu_reference.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace pf::ref {
namespace {

// Calls f(i, j, k, index) for every sample of lattice c.
template <class F> void for_each_face(const Grid& grid, int c, F&& f) {
    const glm::ivec3 d = grid.face_dims(c);
    for (int k = 0; k < d.z; ++k)
        for (int j = 0; j < d.y; ++j)
            for (int i = 0; i < d.x; ++i) f(i, j, k, grid.face_index(c, i, j, k));
}

template <class F> void for_each_cell(const Grid& grid, F&& f) {
    for (int k = 0; k < grid.nz; ++k)
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i) f(i, j, k, grid.cell_index(i, j, k));
}

// The 8 nodes and trilinear weights of the §3 stencil of lattice c at grid coordinate g.
struct Stencil {
    int index[8];
    double weight[8];
};

Stencil stencil(const Grid& grid, int c, const glm::dvec3& g) {
    const glm::ivec3 n = grid.face_dims(c);
    const glm::dvec3 off = Grid::face_offset_g(c);
    int b[3];
    double f[3];
    for (int a = 0; a < 3; ++a) {
        const double s = std::clamp(g[a] - off[a], 0.0, double(n[a] - 1));
        // min(.., N-2) keeps the upper node inside the lattice at s = N-1 (f becomes 1).
        b[a] = std::min(int(std::floor(s)), n[a] - 2);
        f[a] = s - b[a];
    }
    Stencil st;
    int m = 0;
    for (int dk = 0; dk < 2; ++dk)
        for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di, ++m) {
                st.index[m] = grid.face_index(c, b[0] + di, b[1] + dj, b[2] + dk);
                st.weight[m] = (di ? f[0] : 1.0 - f[0]) * (dj ? f[1] : 1.0 - f[1]) *
                               (dk ? f[2] : 1.0 - f[2]);
            }
    return st;
}

// The §3 stencil with each node's grid position and the gradient of its weight with respect
// to the particle's grid coordinate (0 along an axis where the clamp holds the stencil).
struct AffineStencil {
    int index[8];
    double weight[8];
    glm::dvec3 node_g[8];
    glm::dvec3 grad_g[8];
};

AffineStencil affine_stencil(const Grid& grid, int c, const glm::dvec3& g) {
    const glm::ivec3 n = grid.face_dims(c);
    const glm::dvec3 off = Grid::face_offset_g(c);
    int b[3];
    double f[3], slope[3];
    for (int a = 0; a < 3; ++a) {
        const double unclamped = g[a] - off[a];
        const double s = std::clamp(unclamped, 0.0, double(n[a] - 1));
        slope[a] = (unclamped >= 0.0 && unclamped <= double(n[a] - 1)) ? 1.0 : 0.0;
        b[a] = std::min(int(std::floor(s)), n[a] - 2);
        f[a] = s - b[a];
    }
    AffineStencil st;
    int m = 0;
    for (int dk = 0; dk < 2; ++dk)
        for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di, ++m) {
                const int d[3] = {di, dj, dk};
                double w[3], dw[3];
                for (int a = 0; a < 3; ++a) {
                    w[a] = d[a] ? f[a] : 1.0 - f[a];
                    dw[a] = (d[a] ? 1.0 : -1.0) * slope[a];
                }
                st.index[m] = grid.face_index(c, b[0] + di, b[1] + dj, b[2] + dk);
                st.weight[m] = w[0] * w[1] * w[2];
                st.node_g[m] = glm::dvec3(b[0] + di, b[1] + dj, b[2] + dk) + off;
                st.grad_g[m] = glm::dvec3(dw[0] * w[1] * w[2], w[0] * dw[1] * w[2], w[0] * w[1] * dw[2]);
            }
    return st;
}

bool is_fluid(const std::vector<uint8_t>& type, int cell) { return type[cell] == FLUID; }

// Visits the in-domain face neighbours of cell (i,j,k) with the face between the cell and each:
// f(neighbour, face) (walls are not neighbours, §4.6).
template <class F> void for_each_neighbour_face(const Grid& grid, int i, int j, int k, F&& f) {
    if (i > 0) f(grid.cell_index(i - 1, j, k), grid.face_index(0, i, j, k));
    if (i + 1 < grid.nx) f(grid.cell_index(i + 1, j, k), grid.face_index(0, i + 1, j, k));
    if (j > 0) f(grid.cell_index(i, j - 1, k), grid.face_index(1, i, j, k));
    if (j + 1 < grid.ny) f(grid.cell_index(i, j + 1, k), grid.face_index(1, i, j + 1, k));
    if (k > 0) f(grid.cell_index(i, j, k - 1), grid.face_index(2, i, j, k));
    if (k + 1 < grid.nz) f(grid.cell_index(i, j, k + 1), grid.face_index(2, i, j, k + 1));
}

// The same neighbours without their faces: f(neighbour).
template <class F> void for_each_neighbour(const Grid& grid, int i, int j, int k, F&& f) {
    for_each_neighbour_face(grid, i, j, k, [&](int n, int) { f(n); });
}

// theta of a face (empty: the marker-cell surface, 1 everywhere).
double theta_of(const std::vector<double>& theta, int face) { return theta.empty() ? 1.0 : theta[size_t(face)]; }

// Coefficient of the link between FLUID cell a and neighbour b across `face` (§4.6a): 1
// between two FLUID cells, 1/theta to an AIR cell.
double link(const std::vector<uint8_t>& type, const std::vector<double>& theta, int a, int b, int face) {
    return type[a] == type[b] ? 1.0 : 1.0 / theta_of(theta, face);
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
    double s = 0.0;
    for (size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
    return s;
}

} // namespace

std::vector<double> sample_faces(const Grid& grid, const std::function<double(int c, const glm::dvec3& g)>& f) {
    std::vector<double> out(size_t(grid.faces()));
    for (int c = 0; c < 3; ++c)
        for_each_face(grid, c, [&](int i, int j, int k, int id) { out[size_t(id)] = f(c, glm::dvec3(i, j, k) + Grid::face_offset_g(c)); });
    return out;
}

P2GResult p2g(const Grid& grid, const Particles& particles) {
    P2GResult r;
    r.momentum.assign(grid.faces(), 0.0);
    r.weight.assign(grid.faces(), 0.0);
    r.count.assign(grid.cells(), 0u);
    for (size_t p = 0; p < particles.pos.size(); ++p) {
        const glm::dvec3 g = grid.to_grid(particles.pos[p]);
        for (int c = 0; c < 3; ++c) {
            const Stencil st = stencil(grid, c, g);
            for (int m = 0; m < 8; ++m) {
                r.momentum[st.index[m]] += st.weight[m] * particles.vel[p][c];
                r.weight[st.index[m]] += st.weight[m];
            }
        }
        // Clamped so a particle exactly on the upper wall still lands in a cell.
        glm::ivec3 cell;
        for (int a = 0; a < 3; ++a)
            cell[a] = std::clamp(int(std::floor(g[a])), 0, grid.cell_dims()[a] - 1);
        ++r.count[grid.cell_index(cell.x, cell.y, cell.z)];
    }
    return r;
}

P2GResult p2g_apic(const Grid& grid, const Particles& particles) {
    // Weights and counts as in plain P2G; the momentum is summed again with the affine term.
    P2GResult r = p2g(grid, Particles{particles.pos, std::vector<glm::dvec3>(particles.pos.size()), {}});
    for (double& m : r.momentum) m = 0.0;
    for (size_t p = 0; p < particles.pos.size(); ++p) {
        const glm::dvec3 g = grid.to_grid(particles.pos[p]);
        const Affine c = p < particles.affine.size() ? particles.affine[p] : Affine{};
        for (int comp = 0; comp < 3; ++comp) {
            const AffineStencil st = affine_stencil(grid, comp, g);
            for (int m = 0; m < 8; ++m) {
                const glm::dvec3 to_node = grid.to_world(st.node_g[m]) - particles.pos[p];
                r.momentum[st.index[m]] += st.weight[m] * (particles.vel[p][comp] + glm::dot(c[comp], to_node));
            }
        }
    }
    return r;
}

std::vector<uint8_t> classify(const Grid& grid, const std::vector<uint32_t>& count) {
    std::vector<uint8_t> type(grid.cells());
    for (int i = 0; i < grid.cells(); ++i) type[i] = count[i] > 0 ? FLUID : AIR;
    return type;
}

std::vector<double> free_surface_fractions(const Grid& grid, const std::vector<double>& weight, double rest) {
    std::vector<double> theta(size_t(grid.faces()), 1.0);
    for (int f = 0; f < grid.faces(); ++f) {
        const double r = std::clamp(weight[size_t(f)] / rest, 0.0, 1.0);
        const double s = r <= 0.5 ? std::sqrt(2.0 * r) - 1.0 : 1.0 - std::sqrt(2.0 * (1.0 - r));
        theta[size_t(f)] = std::clamp(0.5 + s, kMinSurfaceFraction, 1.0);
    }
    return theta;
}

std::vector<double> surface_extra_diagonal(const Grid& grid, const std::vector<uint8_t>& type,
                                           const std::vector<double>& theta) {
    std::vector<double> extra(size_t(grid.cells()), 0.0);
    for_each_cell(grid, [&](int i, int j, int k, int id) {
        if (type[id] != FLUID) return;
        for_each_neighbour_face(grid, i, j, k, [&](int n, int f) {
            if (type[n] == AIR) extra[size_t(id)] += 1.0 / theta_of(theta, f) - 1.0;
        });
    });
    return extra;
}

GridForces grid_forces(const Grid& grid, const P2GResult& acc, glm::dvec3 gravity, double dt) {
    GridForces f;
    f.vel.assign(grid.faces(), 0.0);
    f.vel_old.assign(grid.faces(), 0.0);
    for (int c = 0; c < 3; ++c)
        for_each_face(grid, c, [&](int i, int j, int k, int id) {
            const double W = acc.weight[id];
            if (!(W > 0.0)) return; // no particle reached this face: both stay 0
            f.vel_old[id] = acc.momentum[id] / W;
            // Walls are free-slip: normal velocity 0. vel_old keeps the P2G value so that
            // G2P's FLIP delta (vel - vel_old) removes the particles' normal velocity there.
            f.vel[id] = grid.is_wall_face(c, i, j, k) ? 0.0 : f.vel_old[id] + dt * gravity[c];
        });
    return f;
}

std::vector<double> divergence(const Grid& grid, const std::vector<uint8_t>& type,
                               const std::vector<double>& vel) {
    std::vector<double> div(grid.cells(), 0.0);
    for_each_cell(grid, [&](int i, int j, int k, int id) {
        if (!is_fluid(type, id)) return;
        div[id] = (vel[grid.face_index(0, i + 1, j, k)] - vel[grid.face_index(0, i, j, k)]) +
                  (vel[grid.face_index(1, i, j + 1, k)] - vel[grid.face_index(1, i, j, k)]) +
                  (vel[grid.face_index(2, i, j, k + 1)] - vel[grid.face_index(2, i, j, k)]);
    });
    return div;
}

std::vector<double> strain(const Grid& grid, const std::vector<uint8_t>& type, const std::vector<double>& vel) {
    std::vector<double> out(grid.cells(), 0.0);
    const glm::ivec3 n = grid.cell_dims();
    const auto inside = [&](glm::ivec3 c) { return glm::all(glm::greaterThanEqual(c, glm::ivec3(0))) && glm::all(glm::lessThan(c, n)); };
    const auto fluid_at = [&](glm::ivec3 c) { return inside(c) && is_fluid(type, grid.cell_index(c.x, c.y, c.z)); };
    const auto face = [&](int a, glm::ivec3 f) { return vel[grid.face_index(a, f.x, f.y, f.z)]; };
    const auto centred = [&](int a, glm::ivec3 c) {
        glm::ivec3 hi = c;
        hi[a] += 1;
        return 0.5 * (face(a, c) + face(a, hi));
    };
    for_each_cell(grid, [&](int i, int j, int k, int id) {
        if (!is_fluid(type, id)) return;
        const glm::ivec3 c(i, j, k);
        for (int m = 0; m < 6; ++m) {
            glm::ivec3 nb = c;
            nb[m / 2] += (m % 2) ? 1 : -1;
            if (inside(nb) && type[grid.cell_index(nb.x, nb.y, nb.z)] == AIR) return;
        }
        double G[3][3];  // G[d][a] = d u_a / d x_d
        for (int a = 0; a < 3; ++a)
            for (int d = 0; d < 3; ++d) {
                if (d == a) {
                    glm::ivec3 hi = c;
                    hi[a] += 1;
                    G[d][a] = (face(a, hi) - face(a, c)) / grid.dx;
                    continue;
                }
                glm::ivec3 p = c, q = c;
                p[d] += 1;
                q[d] -= 1;
                const bool has_p = fluid_at(p), has_q = fluid_at(q);
                const double span = double(has_p) + double(has_q);
                const double up = has_p ? centred(a, p) : centred(a, c), down = has_q ? centred(a, q) : centred(a, c);
                G[d][a] = span > 0.0 ? (up - down) / (span * grid.dx) : 0.0;
            }
        double trace = G[0][0] + G[1][1] + G[2][2], trace_of_square = 0.0;
        for (int a = 0; a < 3; ++a)
            for (int d = 0; d < 3; ++d) trace_of_square += G[a][d] * G[d][a];
        out[id] = 0.5 * (trace_of_square - trace * trace);
    });
    return out;
}

void wall_release(const Grid& grid, const std::vector<uint8_t>& type, const std::vector<double>& last_pressure,
                  glm::dvec3 gravity, double density, std::vector<double>& vel) {
    const double holding = 0.1 * density * glm::length(gravity) * grid.dx;
    const glm::ivec3 n = grid.cell_dims();
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const int c = grid.cell_index(i, j, k);
                if (type[c] != FLUID || last_pressure[c] > holding) continue;
                const glm::ivec3 ijk(i, j, k);
                bool air = false;
                for (int a = 0; a < 3; ++a)
                    for (int s = -1; s <= 1; s += 2) {
                        glm::ivec3 q = ijk;
                        q[a] += s;
                        if (q[a] >= 0 && q[a] < n[a]) air = air || type[grid.cell_index(q.x, q.y, q.z)] == AIR;
                    }
                if (!air) continue;
                for (int a = 0; a < 3; ++a) {
                    if (n[a] < 2) continue;
                    glm::ivec3 hi = ijk;
                    hi[a] += 1;
                    const int low_face = grid.face_index(a, ijk.x, ijk.y, ijk.z);
                    const int high_face = grid.face_index(a, hi.x, hi.y, hi.z);
                    if (ijk[a] == 0 && gravity[a] > 0.0) vel[low_face] = std::max(vel[high_face], 0.0);
                    else if (hi[a] == n[a] && gravity[a] < 0.0) vel[high_face] = std::min(vel[low_face], 0.0);
                }
            }
}

std::vector<double> pressure_rhs(const Grid& grid, const std::vector<uint8_t>& type,
                                 const std::vector<double>& vel, double density, double dt) {
    std::vector<double> b = divergence(grid, type, vel);
    // Scaled so that p comes out in pascals: the update subtracts dt/(ρ dx)·Δp per face.
    for (double& v : b) v *= -density * grid.dx / dt;
    return b;
}

void hydrostatic_start(const Grid& grid, const std::vector<uint8_t>& type, glm::dvec3 gravity,
                       double density, std::vector<double>& pressure) {
    const glm::dvec3 g = glm::abs(gravity);
    const int axis = (g.x >= g.y && g.x >= g.z) ? 0 : (g.y >= g.z ? 1 : 2);
    if (g[axis] == 0.0) return;
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    const glm::ivec3 n = grid.cell_dims();
    const bool down_is_low = gravity[axis] < 0.0;
    const int floor_cell = down_is_low ? 0 : n[axis] - 1, up = down_is_low ? 1 : -1;
    for (int y = 0; y < n[a2]; ++y) {
        for (int x = 0; x < n[a1]; ++x) {
            glm::ivec3 c;
            c[a1] = x;
            c[a2] = y;
            auto index = [&](int k) {
                c[axis] = floor_cell + up * k;
                return grid.cell_index(c.x, c.y, c.z);
            };
            // Runs of FLUID cells resting on the floor or on a SOLID cell; a run capped by a
            // SOLID cell is left alone, the first one capped by AIR (or the lid) is the last.
            int start = 0;
            for (int k = 0; k <= n[axis]; ++k) {
                const uint8_t t = k < n[axis] ? type[index(k)] : uint8_t(AIR);
                if (t == FLUID) continue;
                if (t != SOLID) {
                    for (int j = start; j < k; ++j) {
                        double& p = pressure[index(j)];
                        if (p == 0.0) p = density * g[axis] * grid.dx * (k - j);
                    }
                    break;
                }
                start = k + 1;
            }
        }
    }
}

std::vector<double> volume_correction_rhs(const Grid& grid, const std::vector<uint8_t>& type,
                                          const std::vector<uint32_t>& count, double rest, double k,
                                          bool separation, const std::vector<double>& pressure,
                                          bool ghost_fluid) {
    std::vector<double> b(size_t(grid.cells()), 0.0);
    for_each_cell(grid, [&](int i, int j, int k_, int id) {
        if (type[id] != FLUID) return;
        // e = min(count/rest - 1, 1); a cell with an AIR neighbour (with separation and no
        // pressure: also a wall or SOLID neighbour) only corrects compression; with the ghost
        // fluid, a cell with an AIR neighbour only a surplus beyond a quarter of the rest count.
        double excess = std::min(double(count[id]) / rest - 1.0, 1.0);
        const bool leaving = separation && pressure[id] <= 0.0;
        bool surface = false, beside_air = false;
        for_each_neighbour(grid, i, j, k_, [&](int n) {
            beside_air = beside_air || type[n] == AIR;
            surface = surface || type[n] == AIR || (leaving && type[n] == SOLID);
        });
        if (ghost_fluid && beside_air) excess -= 0.25;
        if (leaving && (i == 0 || j == 0 || k_ == 0 || i == grid.nx - 1 || j == grid.ny - 1 || k_ == grid.nz - 1))
            surface = true;
        if (surface) excess = std::max(excess, 0.0);
        // A net outward displacement of k·e·dx removes k·e·dx³ of liquid.
        b[id] = k * excess * grid.dx;
    });
    return b;
}

void volume_correction_move(const Grid& grid, const std::vector<uint8_t>& type, const std::vector<double>& q,
                            Particles& particles, const std::vector<double>& theta) {
    std::vector<double> d(size_t(grid.faces()), 0.0);
    for (int c = 0; c < 3; ++c) {
        const glm::ivec3 n = grid.face_dims(c);
        for (int k = 0; k < n.z; ++k)
            for (int j = 0; j < n.y; ++j)
                for (int i = 0; i < n.x; ++i) {
                    if (grid.is_wall_face(c, i, j, k)) continue;
                    glm::ivec3 lo(i, j, k);
                    lo[c] -= 1;
                    const int a = grid.cell_index(lo.x, lo.y, lo.z), b = grid.cell_index(i, j, k);
                    if (type[a] == SOLID || type[b] == SOLID) continue;
                    const double qa = type[a] == FLUID ? q[a] : 0.0, qb = type[b] == FLUID ? q[b] : 0.0;
                    const int f = grid.face_index(c, i, j, k);
                    if (type[a] == FLUID || type[b] == FLUID) d[size_t(f)] = (qa - qb) * link(type, theta, a, b, f);
                }
    }
    const glm::dvec3 limit(0.5 * grid.dx);
    for (glm::dvec3& x : particles.pos)
        x = keep_in_domain(grid, x + glm::clamp(interpolate(grid, d, x), -limit, limit));
}

std::vector<double> laplacian(const Grid& grid, const std::vector<uint8_t>& type,
                              const std::vector<double>& p, const std::vector<double>& theta) {
    std::vector<double> out(grid.cells(), 0.0);
    for_each_cell(grid, [&](int i, int j, int k, int id) {
        if (!is_fluid(type, id)) return;
        double s = 0.0;
        for_each_neighbour_face(grid, i, j, k, [&](int n, int f) {
            if (type[n] == SOLID) return; // an obstacle, like a wall: no flux (Neumann)
            // AIR: p = 0 at theta of the way to its centre (free surface)
            s += (p[id] - (is_fluid(type, n) ? p[n] : 0.0)) * link(type, theta, id, n, f);
        });
        out[id] = s;
    });
    return out;
}

std::vector<double> jacobi(const Grid& grid, const std::vector<uint8_t>& type,
                           const std::vector<double>& rhs, std::vector<double> p0,
                           int iterations, double omega, bool no_tension, const std::vector<double>& theta) {
    assert(p0.size() == size_t(grid.cells()));
    for (int id = 0; id < grid.cells(); ++id)
        if (!is_fluid(type, id)) p0[id] = 0.0;
    std::vector<double> next = p0; // non-FLUID entries stay 0 in both buffers
    for (int it = 0; it < iterations; ++it) {
        for_each_cell(grid, [&](int i, int j, int k, int id) {
            if (!is_fluid(type, id)) return;
            double diag = 0.0;
            double sum = 0.0;
            for_each_neighbour_face(grid, i, j, k, [&](int n, int f) {
                if (type[n] == SOLID) return; // Neumann, like a wall
                diag += link(type, theta, id, n, f); // AIR neighbours count in the diagonal but add p = 0
                if (is_fluid(type, n)) sum += p0[n];
            });
            // diag = 0: a FLUID cell walled in by walls and SOLID cells (no equation): p = 0.
            next[id] = diag > 0.0 ? (1.0 - omega) * p0[id] + omega * (rhs[id] + sum) / diag : 0.0;
            if (no_tension) next[id] = std::max(next[id], 0.0); // projected Jacobi: p >= 0 (design.md §4.6)
        });
        std::swap(p0, next); // ping-pong: every cell of a sweep reads the previous sweep
    }
    return p0;
}

std::vector<double> solve_pressure_exact(const Grid& grid, const std::vector<uint8_t>& type,
                                         const std::vector<double>& rhs, const std::vector<double>& theta) {
    // Conjugate gradients on the FLUID cells: A is symmetric positive definite whenever a
    // non-FLUID cell exists (each FLUID component then touches AIR, fixing the constant).
    const int n = grid.cells();
    std::vector<double> x(n, 0.0), r(n, 0.0);
    for (int id = 0; id < n; ++id)
        if (is_fluid(type, id)) r[id] = rhs[id];
    std::vector<double> d = r;
    double rr = dot(r, r);
    const double tol2 = 1e-24 * rr; // (1e-12 relative)^2
    for (int it = 0; it < 10 * n + 100 && rr > tol2 && rr > 0.0; ++it) {
        const std::vector<double> Ad = laplacian(grid, type, d, theta);
        const double dAd = dot(d, Ad);
        if (!(dAd > 0.0)) break; // singular direction (all-FLUID domain): stop, stay finite
        const double alpha = rr / dAd;
        for (int id = 0; id < n; ++id) {
            x[id] += alpha * d[id];
            r[id] -= alpha * Ad[id];
        }
        const double rr_new = dot(r, r);
        const double beta = rr_new / rr;
        rr = rr_new;
        for (int id = 0; id < n; ++id) d[id] = r[id] + beta * d[id];
    }
    return x;
}

namespace {
// An interior face between cells of kinds a and b that velocity_update leaves without a velocity
// (two AIR or two SOLID cells): the extrapolation fills it.
bool left_to_extrapolation(uint8_t a, uint8_t b) { return a == b && a != FLUID; }
}  // namespace

VelocityUpdate velocity_update(const Grid& grid, const std::vector<uint8_t>& type,
                               const std::vector<double>& vel, const std::vector<double>& p,
                               double density, double dt, const std::vector<double>& theta) {
    VelocityUpdate out{vel, std::vector<uint8_t>(grid.faces(), 0)};
    const double scale = dt / (density * grid.dx);
    for (int c = 0; c < 3; ++c)
        for_each_face(grid, c, [&](int i, int j, int k, int id) {
            if (grid.is_wall_face(c, i, j, k)) {  // keeps its value (0, or released by wall_release)
                out.valid[id] = 1;
                return;
            }
            glm::ivec3 lo(i, j, k);
            lo[c] -= 1;
            const int a = grid.cell_index(lo.x, lo.y, lo.z), b = grid.cell_index(i, j, k);
            if (left_to_extrapolation(type[a], type[b])) {
                out.vel[id] = 0.0;  // inside an obstacle or no fluid on either side
            } else if (type[a] == SOLID || type[b] == SOLID) {
                // A face of an obstacle keeps the obstacle's normal velocity (set before the projection).
                out.valid[id] = 1;
            } else {  // a FLUID side
                const double pa = is_fluid(type, a) ? p[a] : 0.0;
                const double pb = is_fluid(type, b) ? p[b] : 0.0;
                out.vel[id] -= scale * (pb - pa) * link(type, theta, a, b, id);
                out.valid[id] = 1;
            }
        });
    return out;
}

void extrapolate(const Grid& grid, VelocityUpdate& v, int layers) {
    for (int layer = 0; layer < layers; ++layer) {
        // Read the old mask, write a new one, so a layer grows exactly one face-step.
        // Writing v.vel in place is safe: only faces invalid in the old mask are written and
        // only faces valid in the old mask are read.
        const std::vector<uint8_t> old = v.valid;
        bool changed = false;
        for (int c = 0; c < 3; ++c) {
            const glm::ivec3 d = grid.face_dims(c);
            for_each_face(grid, c, [&](int i, int j, int k, int id) {
                if (old[id]) return;
                double sum = 0.0;
                int count = 0;
                const glm::ivec3 q(i, j, k);
                for (int a = 0; a < 3; ++a)
                    for (int s = -1; s <= 1; s += 2) {
                        glm::ivec3 nb = q;
                        nb[a] += s;
                        if (nb[a] < 0 || nb[a] >= d[a]) continue;
                        const int nid = grid.face_index(c, nb.x, nb.y, nb.z);
                        if (old[nid]) {
                            sum += v.vel[nid];
                            ++count;
                        }
                    }
                if (count) {
                    v.vel[id] = sum / count;
                    v.valid[id] = 1;
                    changed = true;
                }
            });
        }
        if (!changed) break;
    }
}

glm::dvec3 interpolate(const Grid& grid, const std::vector<double>& field, glm::dvec3 world_pos) {
    const glm::dvec3 g = grid.to_grid(world_pos);
    glm::dvec3 out(0.0);
    for (int c = 0; c < 3; ++c) {
        const Stencil st = stencil(grid, c, g);
        for (int m = 0; m < 8; ++m) out[c] += st.weight[m] * field[st.index[m]];
    }
    return out;
}

void g2p(const Grid& grid, Particles& particles, const std::vector<double>& vel,
         const std::vector<double>& vel_old, double flip_ratio, double max_speed,
         const std::vector<double>& weight, const std::vector<uint8_t>& type) {
    // Faces the velocity update leaves to the extrapolation (cpu_reference.h: velocity_update).
    std::vector<uint8_t> extrapolated(vel.size(), 0);
    if (!weight.empty()) {
        for (int c = 0; c < 3; ++c)
            for_each_face(grid, c, [&](int i, int j, int k, int id) {
                if (grid.is_wall_face(c, i, j, k)) return;
                glm::ivec3 lo(i, j, k);
                lo[c] -= 1;
                extrapolated[size_t(id)] = left_to_extrapolation(type[size_t(grid.cell_index(lo.x, lo.y, lo.z))],
                                                                 type[size_t(grid.cell_index(i, j, k))]);
            });
    }
    for (size_t p = 0; p < particles.pos.size(); ++p) {
        const glm::dvec3 pic = interpolate(grid, vel, particles.pos[p]);
        const glm::dvec3 own = particles.vel[p];
        const glm::dvec3 g = grid.to_grid(particles.pos[p]);
        const glm::ivec3 cell = glm::clamp(glm::ivec3(glm::floor(g)), glm::ivec3(0), grid.cell_dims() - 1);
        double alone = 0.0;
        if (!weight.empty()) {
            double others = 0.0;
            for (int c = 0; c < 3; ++c) {
                const Stencil st = stencil(grid, c, g);
                for (int k = 0; k < 2; ++k) {
                    glm::ivec3 f = cell;
                    f[c] += k;
                    const int id = grid.face_index(c, f.x, f.y, f.z);
                    double own = 0.0;
                    for (int m = 0; m < 8; ++m)
                        if (st.index[m] == id) own = st.weight[m];
                    others += weight[size_t(id)] - own;
                }
                if (others >= kCompany) break;  // as the GPU stops: 0 from here on
            }
            alone = std::clamp(1.0 - others / kCompany, 0.0, 1.0);
        }
        glm::dvec3 flip = own;
        for (int c = 0; c < 3; ++c) {
            const Stencil st = stencil(grid, c, g);
            for (int m = 0; m < 8; ++m) {
                const int f = st.index[m];
                double change = vel[f] - vel_old[f];
                if (alone > 0.0 && extrapolated[size_t(f)]) {
                    const double to_grid = vel[f] - own[c];
                    change += alone * (std::clamp(change, std::min(to_grid, 0.0), std::max(to_grid, 0.0)) - change);
                }
                flip[c] += st.weight[m] * change;
            }
        }
        glm::dvec3 v = (1.0 - flip_ratio) * pic + flip_ratio * flip;
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) v = glm::dvec3(0.0);
        const double speed = glm::length(v);
        if (speed > max_speed) v *= max_speed / speed;
        particles.vel[p] = v;
    }
}

glm::dvec3 interpolate_gradient(const Grid& grid, const std::vector<double>& field, int c, glm::dvec3 world_pos) {
    const AffineStencil st = affine_stencil(grid, c, grid.to_grid(world_pos));
    glm::dvec3 out(0.0);
    for (int m = 0; m < 8; ++m) out += field[st.index[m]] * st.grad_g[m];
    return out / grid.dx; // d/dx = (1/dx) d/dg
}

void g2p_apic(const Grid& grid, Particles& particles, const std::vector<double>& vel, double max_speed) {
    particles.affine.resize(particles.pos.size());
    auto finite = [](const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    for (size_t p = 0; p < particles.pos.size(); ++p) {
        glm::dvec3 v = interpolate(grid, vel, particles.pos[p]);
        Affine c;
        for (int a = 0; a < 3; ++a) c[a] = interpolate_gradient(grid, vel, a, particles.pos[p]);
        double scale = 1.0;
        if (!finite(v)) {
            v = glm::dvec3(0.0);
            scale = 0.0;
        } else if (glm::length(v) > max_speed) {
            scale = max_speed / glm::length(v);
            v *= scale;
        }
        if (!finite(c[0]) || !finite(c[1]) || !finite(c[2])) scale = 0.0;
        const double norm = std::sqrt(glm::dot(c[0], c[0]) + glm::dot(c[1], c[1]) + glm::dot(c[2], c[2])) * scale;
        const double limit = max_speed / grid.dx; // |C|_F dx <= max_speed bounds P2G's addends
        if (norm > limit) scale *= limit / norm;
        for (int a = 0; a < 3; ++a) c[a] = scale == 0.0 ? glm::dvec3(0.0) : c[a] * scale;
        particles.vel[p] = v;
        particles.affine[p] = c;
    }
}

glm::dvec3 keep_in_domain(const Grid& grid, glm::dvec3 world_pos) {
    // cells (shaders/common/sim.glsl): a position more than eps beyond a wall returns a quarter
    // cell inside; one nearer the plane is kept eps inside. Same on every side.
    const double eps = 1e-3, back = 0.25;
    const glm::dvec3 n(grid.cell_dims());
    glm::dvec3 g = grid.to_grid(world_pos);
    for (int a = 0; a < 3; ++a) {
        if (g[a] < -eps || g[a] > n[a] + eps) g[a] = glm::clamp(g[a], back, n[a] - back);
        g[a] = glm::clamp(g[a], eps, n[a] - eps);
    }
    return grid.to_world(g);
}

glm::dvec3 wall_stopped_velocity(const Grid& grid, glm::dvec3 world_pos, glm::dvec3 v) {
    const double eps = 1e-3;
    const glm::dvec3 n(grid.cell_dims()), g = grid.to_grid(world_pos);
    for (int a = 0; a < 3; ++a) {
        if (g[a] < -eps) v[a] = std::max(v[a], 0.0);
        if (g[a] > n[a] + eps) v[a] = std::min(v[a], 0.0);
    }
    return v;
}

namespace {
constexpr int kMaxTraceSubsteps = 64;  // shaders/common/particle_trace.glsl
}

void advect(const Grid& grid, Particles& particles, double dt) {
    for (size_t p = 0; p < particles.pos.size(); ++p) {
        const glm::dvec3 x = particles.pos[p] + dt * particles.vel[p];
        particles.pos[p] = keep_in_domain(grid, x);
        particles.vel[p] = wall_stopped_velocity(grid, x, particles.vel[p]);
    }
}

void advect_rk(const Grid& grid, Particles& particles, const std::vector<double>& vel, double dt,
               Advection scheme, double trace_cells) {
    auto u = [&](const glm::dvec3& x) { return interpolate(grid, vel, keep_in_domain(grid, x)); };
    const double reach = trace_cells * grid.dx;
    for (size_t p = 0; p < particles.pos.size(); ++p) {
        glm::dvec3& x0 = particles.pos[p];
        glm::dvec3 stopped = p < particles.vel.size() ? particles.vel[p] : glm::dvec3(0.0);
        const bool own = scheme == Advection::rk2_offset;
        const glm::dvec3 v0 = stopped, offset = own ? v0 - u(x0) : glm::dvec3(0.0);
        stopped = wall_stopped_velocity(grid, x0 + dt * v0, stopped);  // the walls its own velocity would cross
        double remaining = dt;
        for (int s = 0; s < kMaxTraceSubsteps; ++s) {
            const glm::dvec3 k1 = own && s == 0 ? v0 : u(x0) + offset;
            const double speed = glm::length(k1);
            const bool last = speed * remaining <= reach || s == kMaxTraceSubsteps - 1;
            const double h = last ? remaining : reach / speed;
            const glm::dvec3 k2 = u(x0 + 0.5 * h * k1) + offset;
            glm::dvec3 x;
            if (scheme != Advection::rk3) {
                x = x0 + h * k2; // midpoint
            } else {
                const glm::dvec3 k3 = u(x0 + 0.75 * h * k2); // Ralston's third order
                x = x0 + h * (2.0 / 9.0 * k1 + 1.0 / 3.0 * k2 + 4.0 / 9.0 * k3);
            }
            x0 = keep_in_domain(grid, x);
            stopped = wall_stopped_velocity(grid, x, stopped);  // every wall any sub-step crossed
            if (last) break;
            remaining -= h;
        }
        if (p < particles.vel.size()) particles.vel[p] = stopped;
    }
}

void substep(const Grid& grid, Particles& particles, SubstepState& state, glm::dvec3 gravity,
             double dt, double density, double flip_ratio, int jacobi_iterations, double omega,
             int extrapolation_layers, double max_speed, bool no_tension, Transfer transfer,
             Advection advection) {
    if (state.pressure.size() != size_t(grid.cells())) state.pressure.assign(grid.cells(), 0.0);
    const bool apic = transfer == Transfer::apic;
    const P2GResult acc = apic ? p2g_apic(grid, particles) : p2g(grid, particles); // 1-2
    const GridForces forces = grid_forces(grid, acc, gravity, dt);              // 3
    const std::vector<uint8_t> type = classify(grid, acc.count);                // 4
    const std::vector<double> b = pressure_rhs(grid, type, forces.vel, density, dt); // 5
    for (size_t c = 0; c < type.size(); ++c) {
        if (type[c] != FLUID) state.pressure[c] = 0.0;  // AIR: p = 0
    }
    if (state.hydrostatic_start) hydrostatic_start(grid, type, gravity, density, state.pressure);  // 5a
    state.hydrostatic_start = false;
    state.pressure = jacobi_iterations >= 0                                     // 6
                         ? jacobi(grid, type, b, state.pressure, jacobi_iterations, omega, no_tension)
                         : solve_pressure_exact(grid, type, b);
    VelocityUpdate upd = velocity_update(grid, type, forces.vel, state.pressure, density, dt); // 7
    extrapolate(grid, upd, extrapolation_layers);                               // 8
    if (apic)                                                                   // 9
        g2p_apic(grid, particles, upd.vel, max_speed);
    else
        g2p(grid, particles, upd.vel, forces.vel_old, flip_ratio, max_speed);
    if (advection == Advection::euler)                                          // 10
        advect(grid, particles, dt);
    else
        advect_rk(grid, particles, upd.vel, dt, advection);
}

} // namespace pf::ref
