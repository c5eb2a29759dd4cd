// Grid-to-particle: PIC/FLIP blend v = (1-r) I(u) + r (v_p + I(u - u_old)) with the same
// clamped trilinear stencil as P2G. Non-finite results are zeroed and speeds above
// max_speed clamped (both flagged); the largest speed goes to the status buffer for the
// next frame's CFL estimate. Permutation PF_PIC_ONLY (flip ratio 0) skips u_old; PF_ORDERED
// walks the particles in the tiled P2G's order (common/particle_order.glsl); PF_SOLID_WALLS stops
// the stencil at obstacles (common/solid_walls.glsl).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_FACE_VEL) readonly buffer FaceVel { float face_vel[]; };
#if !PF_PIC_ONLY
layout(std430, binding = PF_SLOT_FACE_VEL_OLD) readonly buffer FaceVelOld { float face_vel_old[]; };
#endif
layout(std430, binding = PF_SLOT_STATUS) buffer Status { uint status[]; };
#if PF_SOLID_WALLS
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
#endif
#include "common/solid_walls.glsl"
#include "common/particle_velocity.glsl"
#include "common/particle_order.glsl"

void main() {
    uint t = flat_id();
    if (t >= sim.particle_count) return;
    uint i = particle_slot(t);
    vec3 g = grid_coord(pos[i].xyz);
    vec3 v_pic = vec3(0.0);
    vec3 delta = vec3(0.0);
    for (int axis = 0; axis < 3; ++axis) {
        Stencil st = sampling_stencil(axis, g);
        float pic[8];
        float dif[8];
        for (int n = 0; n < 8; ++n) {
            ivec3 d = stencil_offset(n);
            float w = stencil_weight(st.frac, d);
            int face = face_index(axis, st.base + d);
            float u = face_vel[face];
            pic[n] = w * u;
#if PF_PIC_ONLY
            dif[n] = 0.0;
#else
            dif[n] = w * (u - face_vel_old[face]);
#endif
        }
        v_pic[axis] = mirror_sum(pic);
        delta[axis] = mirror_sum(dif);
    }
#if PF_PIC_ONLY
    vec3 v = v_pic;
#else
    float r = sim.flip_ratio;
    vec3 v = (1.0 - r) * v_pic + r * (vel[i].xyz + delta);
#endif
    uint flags = 0u;
    float speed;
    limit_velocity(v, flags, speed);
    publish_status(speed, flags);
    vel[i] = vec4(v, 0.0);
}
