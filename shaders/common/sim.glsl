// Per-step constants and MAC-grid helpers shared by every simulation kernel.
// Conventions: docs/design.md §2-3 (face lattices stored u, v, w back to back; clamped
// trilinear stencil shared by P2G and G2P).
#include "common/slots.h"
#include "common/dispatch.glsl"

layout(std140, binding = PF_UBO_SIM) uniform SimUniforms {
#define PF_UNIFORM(type, name) type name;
#include "common/sim_uniforms.h"
#undef PF_UNIFORM
} sim;

int cell_index(ivec3 c) { return lattice_index(sim.grid.xyz, c); }
ivec3 cell_coord(int c) { return lattice_coord(sim.grid.xyz, c); }

// Half cells (2 x 2 x 2 per cell, h = floor(2 g)), x fastest: the sorted-gather P2G's buckets.
int half_cell_index(ivec3 h) { return lattice_index(2 * sim.grid.xyz, h); }

bool cell_inside(ivec3 c) { return lattice_inside(sim.grid.xyz, c); }
// The id spaces a cell kernel and a face kernel run over: [0, cell_total()), [0, face_total()).
int cell_total() { return sim.grid.w; }
int face_total() { return sim.face_count.w; }

// Cell corners (nodes; viscosity's edge stresses live on them): per axis, a node's flat index and
// back, and their count.
ivec3 node_dims() { return sim.grid.xyz + 1; }
int node_index(ivec3 n) { return lattice_index(node_dims(), n); }
ivec3 node_coord(int id) { return lattice_coord(node_dims(), id); }
int node_total() { return lattice_total(node_dims()); }

// Sample counts of the lattice of face component `axis`.
ivec3 face_dims(int axis) {
    ivec3 d = sim.grid.xyz;
    d[axis] += 1;
    return d;
}

int face_offset(int axis) {
    return axis == 0 ? 0 : (axis == 1 ? sim.face_count.x : sim.face_count.x + sim.face_count.y);
}

int face_index(int axis, ivec3 f) { return face_offset(axis) + lattice_index(face_dims(axis), f); }

// Inverse of face_index over the concatenated lattices.
void decode_face(int id, out int axis, out ivec3 f) {
    axis = id < sim.face_count.x ? 0 : (id < sim.face_count.x + sim.face_count.y ? 1 : 2);
    int local = id - face_offset(axis);
    f = lattice_coord(face_dims(axis), local);
}

bool face_inside(int axis, ivec3 f) { return lattice_inside(face_dims(axis), f); }

// The cell below face f of lattice `axis` (f - e_axis; the cell above is f itself).
ivec3 face_cell_below(int axis, ivec3 f) {
    f[axis] -= 1;
    return f;
}
// Cell c's face of lattice `axis` on its - side (side 0) or its + side (side 1: the + neighbour's).
int cell_face(int axis, ivec3 c, int side) {
    c[axis] += side;
    return face_index(axis, c);
}
// The face between cell c and its neighbour n (kNeighbours' order: -x, +x, -y, +y, -z, +z).
int neighbour_face(ivec3 c, int n) { return cell_face(n / 2, c, n & 1); }

// The words of face `face` in the P2G accumulator: 2 face (momentum), 2 face + 1 (weight).
int accum_word(int face, int k) { return 2 * face + k; }

// Domain walls are the boundary faces of each lattice (free-slip: normal velocity 0).
bool face_is_wall(int axis, ivec3 f) { return f[axis] == 0 || f[axis] == sim.grid[axis]; }

// An interior face between cells of kinds a and b that sim/velocity_update.comp leaves without a
// velocity (two AIR or two SOLID cells): the extrapolation fills it.
bool face_left_to_extrapolation(uint a, uint b) { return a == b && a != PF_CELL_FLUID; }

vec3 grid_coord(vec3 world) { return (world - sim.origin.xyz) / sim.dx; }

// World positions of cell c's lowest corner, of its centre, and of the centre of face f of
// lattice `axis` (decode_face).
vec3 cell_corner(ivec3 c) { return sim.origin.xyz + vec3(c) * sim.dx; }
vec3 cell_centre(ivec3 c) { return sim.origin.xyz + (vec3(c) + 0.5) * sim.dx; }
vec3 face_centre(int axis, ivec3 f) {
    vec3 offset = vec3(0.5);
    offset[axis] = 0.0;
    return sim.origin.xyz + (vec3(f) + offset) * sim.dx;
}

// The cell holding grid coordinate g, clamped into the grid; the half cell (2 x 2 x 2 a cell).
ivec3 cell_of(vec3 g) { return clamp(ivec3(floor(g)), ivec3(0), sim.grid.xyz - 1); }
ivec3 half_cell_of(vec3 g) { return clamp(ivec3(floor(2.0 * g)), ivec3(0), 2 * sim.grid.xyz - 1); }

// Clamped trilinear stencil of lattice `axis` at grid coordinate g.
struct Stencil {
    ivec3 base;
    vec3 frac;
};

Stencil face_stencil(int axis, vec3 g) {
    vec3 offset = vec3(0.5);
    offset[axis] = 0.0;
    vec3 n = vec3(face_dims(axis));
    vec3 s = clamp(g - offset, vec3(0.0), n - 1.0);
    vec3 b = min(floor(s), n - 2.0);
    return Stencil(ivec3(b), s - b);
}

// Derivative of face_stencil's clamped coordinate s with respect to g, per axis: 1 where
// g - off_c lies inside [0, N_c - 1], 0 where the clamp holds s still (there the interpolant
// is constant along that axis, so its gradient is 0). Used by APIC's affine vectors.
vec3 stencil_slope(int axis, vec3 g) {
    vec3 offset = vec3(0.5);
    offset[axis] = 0.0;
    vec3 s = g - offset;
    return vec3(greaterThanEqual(s, vec3(0.0))) * vec3(lessThanEqual(s, vec3(face_dims(axis)) - 1.0));
}

// Weight of stencil node base + d, d in {0,1}^3. The boolean mix selects each factor exactly (a
// float mix may be computed as a + t (b - a), which rounds, and differently in each kernel).
float stencil_weight(vec3 frac, ivec3 d) {
    vec3 w = mix(1.0 - frac, frac, notEqual(d, ivec3(0)));
    return w.x * w.y * w.z;
}

// The 6 face neighbours, in -/+ pairs per axis (neighbour n lies on axis n / 2).
const ivec3 kNeighbours[6] = ivec3[6](ivec3(-1, 0, 0), ivec3(1, 0, 0), ivec3(0, -1, 0),
                                      ivec3(0, 1, 0), ivec3(0, 0, -1), ivec3(0, 0, 1));

ivec3 stencil_offset(int n) { return ivec3(n & 1, (n >> 1) & 1, (n >> 2) & 1); }

// Sum of the 8 stencil terms as a tree: x pairs, then y, then z. Each level adds two
// terms that swap under a mirror of that axis, and float addition is commutative, so
// mirrored inputs give bit-mirrored sums (a left-to-right sum would not).
float mirror_sum(float t[8]) {
    return ((t[0] + t[1]) + (t[2] + t[3])) + ((t[4] + t[5]) + (t[6] + t[7]));
}

// Wall clamp of every advection scheme, the same on every side (no wall bias). A position that
// crossed a wall is put back a quarter cell inside, where pf_fill_box's outermost samples lie (8
// a cell): parked on the wall plane, a particle interpolates almost none of the normal velocity
// or volume correction of the face inside it, so it stays there, and such particles piled up
// where walls meet (docs/notes/2026-11-27-wall-return.md). "Crossed" means beyond kWallEps, so
// that rounding near n cannot make mirrored runs differ. A position within kWallEps of the plane
// is only kept kWallEps inside: moving it further would lift particles off the floor, a ratchet
// that adds energy. Positions inside [kWallEps, n - kWallEps] are returned unchanged.
const float kWallEps = 1e-3;       // cells
const float kWallReturn = 0.25;    // cells
// Grid coordinates beyond the low / high wall of their axis: the walls a position crossed.
bvec3 beyond_low_wall(vec3 g) { return lessThan(g, vec3(-kWallEps)); }
bvec3 beyond_high_wall(vec3 g) { return greaterThan(g, vec3(sim.grid.xyz) + kWallEps); }
vec3 keep_in_domain(vec3 x) {
    vec3 g = grid_coord(x);
    vec3 n = vec3(sim.grid.xyz);
    vec3 kept = mix(g, vec3(kWallReturn), beyond_low_wall(g));
    kept = mix(kept, n - kWallReturn, beyond_high_wall(g));
    kept = clamp(kept, vec3(kWallEps), n - kWallEps);
    return mix(x, sim.origin.xyz + kept * sim.dx, notEqual(g, kept));
}

// v without its motion into the walls marked crossed (low: towards -axis, high: towards +axis).
vec3 stopped_at_walls(bvec3 low, bvec3 high, vec3 v) {
    v = mix(v, max(v, vec3(0.0)), low);
    return mix(v, min(v, vec3(0.0)), high);
}

// The velocity a particle keeps after keep_in_domain returned it from beyond a wall: the wall
// stops its motion into that wall. Kept, that motion would press the particle back every
// substep, and a particle the pressure does not hold (one alone on the floor) would gain
// gravity's speed for ever while the wall returns it to the same place.
vec3 wall_stopped_velocity(vec3 x, vec3 v) {
    vec3 g = grid_coord(x);
    return stopped_at_walls(beyond_low_wall(g), beyond_high_wall(g), v);
}
