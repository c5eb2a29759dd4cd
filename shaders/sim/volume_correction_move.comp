// Volume correction, particle move (docs/design.md §4.5): each particle is displaced by the
// trilinear interpolation of the face displacements d = q_lo - q_hi of the potential that
// volume_correction_setup's problem solved for (metres). Positions only: velocities are not
// touched, so the correction never enters FLIP's velocity difference and adds no kinetic
// energy. Walls and faces beside SOLID cells do not move (d = 0); q = 0 at the free surface,
// so a face between FLUID and AIR divides its difference by theta as the velocity update does. A
// displacement is kept within sim.correction_reach cells per axis (half a cell; where the
// correction runs in every projection, half a cell per 1/60 s of the substep, at least a quarter:
// VolumeCorrection::reach_cells in src/sim/volume_correction.h), then the wall clamp of every
// advection scheme applies. PF_ORDERED walks the particles in the tiled P2G's order, as G2P does on large
// grids (common/particle_order.glsl): its reads of the potential are gathers too.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_VOLUME_POTENTIAL) readonly buffer Potential { float potential[]; };
layout(std430, binding = PF_SLOT_FACE_FRACTION) readonly buffer Fraction { float face_fraction[]; };
#include "common/particle_order.glsl"

float face_displacement(int axis, ivec3 f) {
    // A grid one cell thick gives the clamped stencil a zero-weight face outside the grid.
    if (!face_inside(axis, f) || face_is_wall(axis, f)) return 0.0;
    ivec3 lo = face_cell_below(axis, f);
    int a = cell_index(lo), b = cell_index(f);
    uint ta = PF_CELL_KIND(cell_type[a]), tb = PF_CELL_KIND(cell_type[b]);
    if (ta == PF_CELL_SOLID || tb == PF_CELL_SOLID) return 0.0;
    float qa = ta == PF_CELL_FLUID ? potential[a] : 0.0;
    float qb = tb == PF_CELL_FLUID ? potential[b] : 0.0;
    return ta == tb ? qa - qb : (qa - qb) / face_fraction[face_index(axis, f)];
}

void main() {
    uint t = flat_id();
    if (t >= sim.particle_count) return;
    uint i = particle_slot(t);
    vec3 x = pos[i].xyz;
    vec3 g = grid_coord(x);
    vec3 d = vec3(0.0);
    for (int axis = 0; axis < 3; ++axis) {
        Stencil s = face_stencil(axis, g);
        float t[8];
        for (int n = 0; n < 8; ++n) {
            ivec3 o = stencil_offset(n);
            t[n] = stencil_weight(s.frac, o) * face_displacement(axis, s.base + o);
        }
        d[axis] = mirror_sum(t);  // mirrored particles move by mirrored displacements, bit for bit
    }
    d = clamp(d, vec3(-sim.correction_reach * sim.dx), vec3(sim.correction_reach * sim.dx));
    pos[i] = vec4(keep_in_domain(x + d), 0.0);
}
