// Grid forces: turns the P2G sums (fixed point, or floats with PF_P2G_FLOAT) into face
// velocities (kept as u_old for FLIP),
// adds gravity on faces that received particles, and zeroes the normal velocity on the
// domain walls (free-slip). Each face's weight also gives the free surface's fraction theta
// there (common/free_surface.glsl; 1 everywhere with the marker-cell surface).
#include "common/sim.glsl"
#include "common/free_surface.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
#if PF_P2G_FLOAT
layout(std430, binding = PF_SLOT_FACE_ACCUM) readonly buffer Accum { float accum[]; };
#else
layout(std430, binding = PF_SLOT_FACE_ACCUM) readonly buffer Accum { int accum[]; };
#endif
layout(std430, binding = PF_SLOT_FACE_VEL) writeonly buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_FACE_VEL_OLD) writeonly buffer FaceVelOld { float face_vel_old[]; };
layout(std430, binding = PF_SLOT_FACE_FRACTION) writeonly buffer Fraction { float face_fraction[]; };

void main() {
    int id = int(flat_id());
    if (id >= face_total()) return;
    int axis;
    ivec3 f;
    decode_face(id, axis, f);

#if PF_P2G_FLOAT
    float momentum = accum[accum_word(id, 0)], weight = accum[accum_word(id, 1)];
    bool received = weight > 0.0;
    float u_old = received ? momentum / weight : 0.0;
    float weight_sum = weight;
#else
    int momentum = accum[accum_word(id, 0)];
    int weight = accum[accum_word(id, 1)];
    bool received = weight > 0;
    float u_old = received ? (float(momentum) * sim.inv_momentum_scale) / (float(weight) * sim.inv_weight_scale) : 0.0;
    float weight_sum = float(weight) * sim.inv_weight_scale;
#endif
    face_fraction[id] = sim.ghost_fluid != 0u ? surface_fraction(weight_sum / sim.rest_particles) : 1.0;
    float u = received ? u_old + sim.dt * sim.gravity[axis] : 0.0;
    face_vel_old[id] = u_old;
    face_vel[id] = face_is_wall(axis, f) ? 0.0 : u;
}
