// Velocity update: subtracts the pressure gradient on faces next to FLUID cells (p = 0 at the
// free surface, theta of the way from a FLUID centre to an AIR one: the gradient there is
// divided by theta, common/free_surface.glsl) and marks them valid; wall faces keep what
// grid_forces and wall_release.comp gave them (0, or liquid leaving the wall) and are valid; faces between two AIR cells are reset to 0 and left invalid for
// extrapolation. SOLID cells (obstacles) are walls
// too: a face between a SOLID cell and another keeps the obstacle's normal velocity that
// obstacle_faces set (free-slip) and is valid; a face inside a solid (two SOLID cells) is reset
// to 0 and left to extrapolation, like one between two AIR cells.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_FACE_VEL) buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_PRESSURE) readonly buffer Pressure { float pressure[]; };
layout(std430, binding = PF_SLOT_FACE_VALID_OUT) writeonly buffer Valid { uint valid[]; };
layout(std430, binding = PF_SLOT_FACE_FRACTION) readonly buffer Fraction { float face_fraction[]; };

void main() {
    int id = int(flat_id());
    if (id >= face_total()) return;
    int axis;
    ivec3 f;
    decode_face(id, axis, f);
    if (face_is_wall(axis, f)) {
        valid[id] = 1u;
        return;
    }
    ivec3 lo = face_cell_below(axis, f);
    int a = cell_index(lo);
    int b = cell_index(f);
    uint ta = PF_CELL_KIND(cell_type[a]);
    uint tb = PF_CELL_KIND(cell_type[b]);
    if (face_left_to_extrapolation(ta, tb)) {
        face_vel[id] = 0.0;
        valid[id] = 0u;
    } else if (ta == PF_CELL_SOLID || tb == PF_CELL_SOLID) {
        valid[id] = 1u;
    } else {  // a FLUID side
        float pa = ta == PF_CELL_FLUID ? pressure[a] : 0.0;
        float pb = tb == PF_CELL_FLUID ? pressure[b] : 0.0;
        float scale = sim.dt / (sim.density * sim.dx);
        float theta = ta == tb ? 1.0 : face_fraction[id];
        face_vel[id] -= scale * (pb - pa) / theta;
        valid[id] = 1u;
    }
}
