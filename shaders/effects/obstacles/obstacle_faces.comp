// Obstacles, per face, after obstacle_cells: a face with a SOLID cell on either side takes the
// normal component of the velocity, at the face's centre (v + w x r), of the obstacle that cell
// lies deepest in (0 for static obstacles): free-slip, as the domain walls, moving with it. The pressure setup reads it as the boundary
// velocity and velocity_update keeps it. Domain walls stay 0.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_FACE_VEL) buffer FaceVel { float face_vel[]; };
#include "effects/obstacles/obstacle_sdf.glsl"

void main() {
    int id = int(flat_id());
    if (id >= face_total()) return;
    int axis;
    ivec3 f;
    decode_face(id, axis, f);
    if (face_is_wall(axis, f)) return;
    ivec3 lo = face_cell_below(axis, f);
    bool solid_lo = PF_CELL_KIND(cell_type[cell_index(lo)]) == PF_CELL_SOLID;
    if (!solid_lo && PF_CELL_KIND(cell_type[cell_index(f)]) != PF_CELL_SOLID) return;
    int nearest;
    scene_distance(cell_centre(solid_lo ? lo : f), nearest);
    face_vel[id] = nearest >= 0 ? obstacle_velocity(uint(nearest), face_centre(axis, f))[axis] : 0.0;
}
