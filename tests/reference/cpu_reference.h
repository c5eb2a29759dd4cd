// Double-precision CPU reference of one pflip substep (docs/design.md §2-4).
//
// Every pass is a plain function over std::vector storage so tests can run the GPU kernels
// and this reference on the same small inputs and compare pass by pass. The reference uses
// exact (unquantised) P2G sums; everything else follows the contract literally.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

namespace pf::ref {

// Cell grid and MAC face lattices (design.md §2). Requires nx, ny, nz >= 2: the clamped
// stencil (§3) needs at least two samples per axis on every lattice.
struct Grid {
    int nx = 0, ny = 0, nz = 0;
    double dx = 1.0;
    glm::dvec3 origin{0.0};

    int cells() const { return nx * ny * nz; }
    glm::ivec3 cell_dims() const { return {nx, ny, nz}; }
    // Sample counts N_c of lattice c (0 = u, 1 = v, 2 = w).
    glm::ivec3 face_dims(int c) const { return {nx + (c == 0), ny + (c == 1), nz + (c == 2)}; }
    int face_count(int c) const { const glm::ivec3 d = face_dims(c); return d.x * d.y * d.z; }
    int faces() const { return face_count(0) + face_count(1) + face_count(2); }
    int face_offset(int c) const {
        return c == 0 ? 0 : c == 1 ? face_count(0) : face_count(0) + face_count(1);
    }
    int face_index(int c, int i, int j, int k) const {
        const glm::ivec3 d = face_dims(c);
        return face_offset(c) + i + d.x * (j + d.y * k);
    }
    int cell_index(int i, int j, int k) const { return i + nx * (j + ny * k); }
    // Lattice offset off_c: u (0,½,½), v (½,0,½), w (½,½,0).
    static glm::dvec3 face_offset_g(int c) { glm::dvec3 o(0.5); o[c] = 0.0; return o; }
    // Boundary faces of the domain (i = 0 or i = nx for u, likewise v, w): solid, free-slip.
    bool is_wall_face(int c, int i, int j, int k) const {
        const int a = glm::ivec3(i, j, k)[c];
        return a == 0 || a == cell_dims()[c];
    }
    glm::dvec3 to_grid(const glm::dvec3& x) const { return (x - origin) / dx; }
    glm::dvec3 to_world(const glm::dvec3& g) const { return origin + g * dx; }
};

enum CellType : uint8_t { AIR = 0, FLUID = 1, SOLID = 2 };

// APIC affine vectors of one particle: c[a] is the gradient of velocity component a (1/s).
using Affine = std::array<glm::dvec3, 3>;

struct Particles {
    std::vector<glm::dvec3> pos, vel;
    std::vector<Affine> affine;  // APIC only: one per particle (empty: all zero)
};

// pf_transfer and pf_advection, for substep().
enum class Transfer { pic_flip = 0, apic = 1 };
enum class Advection { euler = 0, rk2 = 1, rk3 = 2, rk2_offset = 4 };  // pf_advection's values (no leapfrog)

// Face fields: one std::vector<double> of size grid.faces(), u then v then w.
// A face field sampled from f(c, g): the value on lattice c at grid coordinate g (cells from the
// grid's origin, g = (i, j, k) + face_offset_g(c)), in the GPU's face order.
std::vector<double> sample_faces(const Grid& grid, const std::function<double(int c, const glm::dvec3& g)>& f);

// §4.2: momentum = Σ w·v_c, weight = Σ w over the §3 stencil, count per particle cell
// clamp(floor(g), 0, n-1). Exact sums (the GPU's are quantised by S_m, S_w).
struct P2GResult {
    std::vector<double> momentum, weight;
    std::vector<uint32_t> count;
};
P2GResult p2g(const Grid& grid, const Particles& particles);

// §4.2 with APIC: each contribution is w·(v_c + c_c·(x_i - x_p)), x_i the node's world position.
P2GResult p2g_apic(const Grid& grid, const Particles& particles);

// §4.4: FLUID if count > 0, else AIR.
std::vector<uint8_t> classify(const Grid& grid, const std::vector<uint32_t>& count);

// §4.6a ghost-fluid free surface: theta per face from its P2G weight W over the rest count r
// (W/r = (1+s)^2/2 for s <= 0, 1 - (1-s)^2/2 above, theta = 1/2 + s, clamped to
// [kMinSurfaceFraction, 1]). The functions below take theta per face; an empty vector is the
// marker-cell surface (theta = 1).
constexpr double kMinSurfaceFraction = 0.05;
std::vector<double> free_surface_fractions(const Grid& grid, const std::vector<double>& weight, double rest);
// Per FLUID cell: the sum over its AIR faces of 1/theta - 1 (what the GPU packs into its type word).
std::vector<double> surface_extra_diagonal(const Grid& grid, const std::vector<uint8_t>& type,
                                           const std::vector<double>& theta);

// §4.3: vel_old = W > 0 ? M / W : 0; vel = W > 0 ? vel_old + dt·g_c : 0; wall faces vel = 0
// (vel_old keeps the P2G value there).
struct GridForces {
    std::vector<double> vel, vel_old;
};
GridForces grid_forces(const Grid& grid, const P2GResult& p2g_result, glm::dvec3 gravity,
                       double dt);

// §4.5: per cell Σ_c (u_c[+] - u_c[-]) in m/s (not divided by dx); 0 for non-FLUID cells.
std::vector<double> divergence(const Grid& grid, const std::vector<uint8_t>& type,
                               const std::vector<double>& vel);

// §4.11 (shaders/sim/metrics.comp): per interior FLUID cell (no AIR face neighbour) the strain
// P = (tr(G^2) - tr(G)^2) / 2 of the cell-centred velocity gradient G, in 1/s^2: G's diagonal
// from the cell's own faces, its other entries central differences of face-averaged components
// between FLUID neighbours (one-sided beside a non-FLUID one, 0 with neither); 0 elsewhere.
std::vector<double> strain(const Grid& grid, const std::vector<uint8_t>& type, const std::vector<double>& vel);

// §2 wall release: a FLUID cell touching AIR whose last pressure is at most 0.1·ρ|g|dx gives each of
// its domain walls that gravity pulls the liquid away from the part of its opposite face's velocity
// that leaves the wall (grids one cell thick along an axis keep their walls there).
void wall_release(const Grid& grid, const std::vector<uint8_t>& type, const std::vector<double>& last_pressure,
                  glm::dvec3 gravity, double density, std::vector<double>& vel);

// §4.5: b = -div·ρ·dx/dt for FLUID cells, 0 elsewhere.
std::vector<double> pressure_rhs(const Grid& grid, const std::vector<uint8_t>& type,
                                 const std::vector<double>& vel, double density, double dt);
// §4.5 volume correction, right-hand side (metres): b = k·e·dx for FLUID cells with
// e = min(count/rest − 1, 1), and e = max(e, 0) in cells with an AIR neighbour (e = max(e − 1/4, 0)
// there with the `ghost_fluid` surface) and, with `separation`, in cells whose `pressure` is <= 0 beside a
// domain wall or a SOLID cell; 0 elsewhere.
std::vector<double> volume_correction_rhs(const Grid& grid, const std::vector<uint8_t>& type,
                                          const std::vector<uint32_t>& count, double rest, double k,
                                          bool separation, const std::vector<double>& pressure,
                                          bool ghost_fluid = false);

// §4.5 volume correction, particle move: the face displacement d = q_lo − q_hi (q = 0 outside
// FLUID cells, divided by theta between FLUID and AIR; 0 on walls and beside SOLID cells)
// interpolated as in §3, each component kept within ±dx/2, then keep_in_domain. Velocities are
// left alone.
void volume_correction_move(const Grid& grid, const std::vector<uint8_t>& type, const std::vector<double>& q,
                            Particles& particles, const std::vector<double>& theta = {});

// §4.6 operator: (A p)_i = Σ_{j∈N(i)} (p_i - p_j)·l_ij for FLUID i, with N(i) the in-domain
// neighbours that are not SOLID (walls and obstacles excluded: Neumann), p_j = 0 for AIR j and
// l_ij = 1, or 1/theta across a FLUID-AIR face (§4.6a); 0 for non-FLUID i. The pressure system is
// A p = b; tests use b - A p as the residual.
std::vector<double> laplacian(const Grid& grid, const std::vector<uint8_t>& type,
                              const std::vector<double>& p, const std::vector<double>& theta = {});

// §4.6: `iterations` damped (ω) Jacobi sweeps, ping-pong. p0 entries of non-FLUID cells are
// treated as 0; the result is 0 in non-FLUID cells.
std::vector<double> jacobi(const Grid& grid, const std::vector<uint8_t>& type,
                           const std::vector<double>& rhs, std::vector<double> p0,
                           int iterations, double omega,
                           bool no_tension = false, // no_tension: projected Jacobi, p >= 0
                           const std::vector<double>& theta = {});

// The MGPCG preconditioner's V-cycle, z = V(r) (src/sim/solvers/mgpcg/multigrid.h), in double:
// levels halve each axis (rounding up) until one has at most `coarse_cells` cells or there are
// `max_levels`; a coarse cell is AIR if a child is, else FLUID if a child is, else SOLID. Per
// level: red then black Gauss-Seidel from zero, the residual restricted by R = P^T scaled by
// 4 / 2^(coarsened axes), the coarser level's cycle prolonged by cell-centred trilinear P, then
// black and red; the coarsest level runs red and `coarse_sweeps` black-red pairs from zero.
// `extra_diagonal` (per cell, or empty) is the fine level's ghost-fluid surface term.
std::vector<double> multigrid_vcycle(const Grid& grid, const std::vector<uint8_t>& type,
                                     const std::vector<double>& extra_diagonal, const std::vector<double>& r,
                                     int coarse_cells, int max_levels, int coarse_sweeps);
// The V-cycles' cell-centred trilinear prolongation, one axis: the weight of coarse index c (of
// nc) at fine index f (3/4 for its parent, 1/4 for the parent's other neighbour, clamped).
double prolong_weight(int f, int c, int nc);

// The MGPCG V-cycle with Galerkin coarse levels (shaders/solvers/mgpcg/galerkin.glsl), in double,
// with its operators built as explicit matrices: level 1 is s P^T A P with the trilinear P and
// s = 4 / 2^(coarsened axes), deeper levels P^T A P with the aggregation P (a parent's value to its
// children); a coarse cell is FLUID if a child is. Levels halve each axis (rounding up) until one
// beyond level 1 has at most `coarse_cells` cells or there are `max_levels`. The fine level: red
// and black Gauss-Seidel from zero, the correction, black and red; a coarse level: e = omega r /
// diag, the correction scaled by alpha, one Jacobi step; the coarsest: Gauss-Seidel over the 8
// parity colours forward then backward, `coarse_pairs` times, from zero. The fine level must not
// be the coarsest itself.
struct GalerkinCycle {
    int coarse_cells = 0, max_levels = 0, coarse_pairs = 0;
    double omega = 0.0, alpha = 0.0;
};
std::vector<double> galerkin_vcycle(const Grid& grid, const std::vector<uint8_t>& type,
                                    const std::vector<double>& extra_diagonal, const std::vector<double>& r,
                                    const GalerkinCycle& cycle);

// Converged solve of the same system (conjugate gradients to ‖b - A p‖ <= 1e-12·‖b‖).
std::vector<double> solve_pressure_exact(const Grid& grid, const std::vector<uint8_t>& type,
                                         const std::vector<double>& rhs, const std::vector<double>& theta = {});

// §4.7: wall faces keep their velocity (0, or what wall_release gave them) and are valid; faces between a SOLID cell and another keep their velocity (the
// obstacle's) and are valid, faces between two SOLID cells become 0 and invalid; other interior
// faces with a FLUID side get the pressure gradient (divided by theta between FLUID and AIR) and
// are valid; faces between two AIR cells become 0 and invalid.
struct VelocityUpdate {
    std::vector<double> vel;
    std::vector<uint8_t> valid;
};
VelocityUpdate velocity_update(const Grid& grid, const std::vector<uint8_t>& type,
                               const std::vector<double>& vel, const std::vector<double>& p,
                               double density, double dt, const std::vector<double>& theta = {});

// §4.8: `layers` rounds; in each, an invalid face with >= 1 valid lattice neighbour (old mask)
// takes the average of those neighbours and is valid from the next round on.
void extrapolate(const Grid& grid, VelocityUpdate& v, int layers);

// §3: clamped trilinear interpolation of the three components of a face field.
glm::dvec3 interpolate(const Grid& grid, const std::vector<double>& field, glm::dvec3 world_pos);

// §4.9: v = (1-r)·I(u) + r·(v_p + I(u - u_old)); on a non-wall face between two AIR or two SOLID
// cells of `type`, the FLIP value v_p + u - u_old moves towards its clamp between v_p and u by the
// particle's solitude, 1 - (the P2G `weight` on its cell's six faces less its own)/kCompany, at
// least 0 (neither when `weight` is empty); non-finite → 0; |v| > max_speed → scaled.
constexpr double kCompany = 1.0;  // sim/g2p.comp
void g2p(const Grid& grid, Particles& particles, const std::vector<double>& vel,
         const std::vector<double>& vel_old, double flip_ratio, double max_speed,
         const std::vector<double>& weight = {}, const std::vector<uint8_t>& type = {});

// §3 with APIC: the gradient (1/s) of component c's interpolant at world_pos, Σ u_i ∇w_i; 0
// along an axis where the stencil clamp holds (g - off_c outside [0, N_c - 1]).
glm::dvec3 interpolate_gradient(const Grid& grid, const std::vector<double>& field, int c, glm::dvec3 world_pos);

// §4.9 with APIC: v = I(u), c_a = ∇I(u_a); non-finite v → v = 0 and C = 0, non-finite C → C = 0;
// |v| > max_speed → v and C scaled by max_speed/|v|; then |C|_F·dx > max_speed → C scaled to it.
void g2p_apic(const Grid& grid, Particles& particles, const std::vector<double>& vel, double max_speed);

// §4.10: x += dt·v, then keep_in_domain and wall_stopped_velocity (a straight path: sub-steps of
// §5's trace would end where one move's clamp does).
void advect(const Grid& grid, Particles& particles, double dt);

// The wall clamp of every advection scheme: a coordinate outside [-ε, n + ε] goes to clamp(g,
// 1/4, n - 1/4) (a quarter cell inside), then g = clamp(g, ε, n - ε), ε = 1e-3 cells.
glm::dvec3 keep_in_domain(const Grid& grid, glm::dvec3 world_pos);

// The velocity kept after keep_in_domain returned world_pos from beyond a wall: v's components
// into each wall crossed by more than ε are dropped.
glm::dvec3 wall_stopped_velocity(const Grid& grid, glm::dvec3 world_pos, glm::dvec3 v);

// §4.10 Runge-Kutta through the grid velocity (vel, interpolated as in §3): midpoint (rk2) or
// Ralston's third order (rk3), or the midpoint whose first stage is the particle's own velocity v
// and every later one the field plus v - vel(x0), its difference at the start (rk2_offset), traced
// in sub-steps (§5) of h = remaining time, or trace_cells dx / |k1| when the particle would cross
// more than trace_cells cells in the rest of dt (the 64th takes the rest; the GPU's trace_cells
// is 1); every stage position and every sub-step's end go through
// keep_in_domain, and a wall any sub-step crossed stops particles.vel (wall_stopped_velocity).
void advect_rk(const Grid& grid, Particles& particles, const std::vector<double>& vel, double dt,
               Advection scheme, double trace_cells = 1.0);

// §4.5a: the hydrostatic start. Along gravity's dominant axis a (ties: x before y before z),
// the run of L FLUID cells resting on the floor of each column gets, in its k-th cell from the
// floor, p = ρ·|g_a|·dx·(L - k) where p is still 0. A SOLID cell is a floor for the run above
// it; a run capped by a SOLID cell is skipped. Other cells are unchanged.
void hydrostatic_start(const Grid& grid, const std::vector<uint8_t>& type, glm::dvec3 gravity,
                       double density, std::vector<double>& pressure);

// Pressure (Pa) per cell, the warm start of the next substep's solve. Resized to
// grid.cells() zeros when its size does not match. hydrostatic_start: the next substep starts
// from §4.5a (as the GPU does after particles are added).
struct SubstepState {
    std::vector<double> pressure;
    bool hydrostatic_start = true;
};

// Steps 1-10 of §4 in order, with the marker-cell surface. jacobi_iterations < 0 replaces the Jacobi solve by
// solve_pressure_exact (a reference-only switch for tests that need a converged pressure).
void substep(const Grid& grid, Particles& particles, SubstepState& state, glm::dvec3 gravity,
             double dt, double density, double flip_ratio, int jacobi_iterations, double omega,
             int extrapolation_layers, double max_speed,
             bool no_tension = false, Transfer transfer = Transfer::pic_flip,
             Advection advection = Advection::euler);

} // namespace pf::ref
