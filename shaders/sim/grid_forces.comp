// Grid forces: turns the fixed-point sums into face velocities (kept as u_old for FLIP),
// adds gravity on faces that received particles, and zeroes the normal velocity on the
// domain walls (free-slip).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_FACE_ACCUM) readonly buffer Accum { int accum[]; };
layout(std430, binding = PF_SLOT_FACE_VEL) writeonly buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_FACE_VEL_OLD) writeonly buffer FaceVelOld { float face_vel_old[]; };

void main() {
    int id = int(flat_id());
    if (id >= sim.face_count.w) return;
    int axis;
    ivec3 f;
    decode_face(id, axis, f);

    int momentum = accum[2 * id];
    int weight = accum[2 * id + 1];
    float u_old = weight > 0 ? (float(momentum) * sim.inv_momentum_scale) / (float(weight) * sim.inv_weight_scale) : 0.0;
    float u = weight > 0 ? u_old + sim.dt * sim.gravity[axis] : 0.0;
    face_vel_old[id] = u_old;
    face_vel[id] = face_is_wall(axis, f) ? 0.0 : u;
}
