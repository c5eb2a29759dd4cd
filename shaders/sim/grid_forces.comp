// Grid forces: turns the P2G sums (fixed point, or floats with PF_P2G_FLOAT) into face
// velocities (kept as u_old for FLIP),
// adds gravity on faces that received particles, and zeroes the normal velocity on the
// domain walls (free-slip).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
#if PF_P2G_FLOAT
layout(std430, binding = PF_SLOT_FACE_ACCUM) readonly buffer Accum { float accum[]; };
#else
layout(std430, binding = PF_SLOT_FACE_ACCUM) readonly buffer Accum { int accum[]; };
#endif
layout(std430, binding = PF_SLOT_FACE_VEL) writeonly buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_FACE_VEL_OLD) writeonly buffer FaceVelOld { float face_vel_old[]; };

void main() {
    int id = int(flat_id());
    if (id >= sim.face_count.w) return;
    int axis;
    ivec3 f;
    decode_face(id, axis, f);

#if PF_P2G_FLOAT
    float momentum = accum[2 * id], weight = accum[2 * id + 1];
    bool received = weight > 0.0;
    float u_old = received ? momentum / weight : 0.0;
#else
    int momentum = accum[2 * id];
    int weight = accum[2 * id + 1];
    bool received = weight > 0;
    float u_old = received ? (float(momentum) * sim.inv_momentum_scale) / (float(weight) * sim.inv_weight_scale) : 0.0;
#endif
    float u = received ? u_old + sim.dt * sim.gravity[axis] : 0.0;
    face_vel_old[id] = u_old;
    face_vel[id] = face_is_wall(axis, f) ? 0.0 : u;
}
