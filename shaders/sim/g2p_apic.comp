// Grid-to-particle, APIC (Jiang et al. 2015, "The affine particle-in-cell method"): the
// particle's velocity is the interpolated grid velocity, v_a = sum_i w_i u_i, and its affine
// vector for component a is the gradient of that same interpolant, c_a = sum_i u_i grad w_i
// (the multilinear-kernel form of B D^-1, §5.3 of the paper), in 1/s. P2G hands v + C (x_i - x_p)
// back to the grid, so rotation and shear survive the round trip that PIC averages away,
// without FLIP's noise. Same clamped trilinear stencil, NaN guard and speed clamp as g2p.comp;
// C is zeroed when v or C is non-finite, scaled by v's factor when v is clamped, and limited to
// |C|_F dx <= max_speed (flagged as a speed clamp), which bounds every APIC P2G addend
// (design.md §4.2, §4.9). PF_SOLID_WALLS stops the stencil at obstacles (common/solid_walls.glsl).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) writeonly buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_FACE_VEL) readonly buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_PARTICLE_AFFINE) writeonly buffer Affine { vec4 affine[]; };
layout(std430, binding = PF_SLOT_STATUS) buffer Status { uint status[]; };
#if PF_SOLID_WALLS
layout(std430, binding = PF_SLOT_APIC_CELL_TYPE) readonly buffer Type { uint cell_type[]; };  // affine's slot is 6
#endif
#include "common/solid_walls.glsl"
#include "common/particle_velocity.glsl"

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    vec3 g = grid_coord(pos[i].xyz);
    vec3 v;
    vec3 c[3];
    for (int axis = 0; axis < 3; ++axis) {
        vec3 slope = stencil_slope(axis, g);
        Stencil st = sampling_stencil(axis, g, slope);
        float value[8], ds_x[8], ds_y[8], ds_z[8];
        for (int n = 0; n < 8; ++n) {
            ivec3 d = stencil_offset(n);
            // Per-axis weight factors and their derivatives along s (+1 upper node, -1 lower).
            vec3 w = mix(1.0 - st.frac, st.frac, vec3(d));
            vec3 dw = vec3(2 * d - 1);
            float u = face_vel[face_index(axis, st.base + d)];
            value[n] = w.x * w.y * w.z * u;
            ds_x[n] = dw.x * w.y * w.z * u;
            ds_y[n] = w.x * dw.y * w.z * u;
            ds_z[n] = w.x * w.y * dw.z * u;
        }
        v[axis] = mirror_sum(value);
        // d/dx_p = (ds/dg) (dg/dx_p) d/ds, with dg/dx_p = 1/dx.
        c[axis] = vec3(mirror_sum(ds_x), mirror_sum(ds_y), mirror_sum(ds_z)) * slope / sim.dx;
    }
    uint flags = 0u;
    float speed;
    // The factor C is multiplied by: v's own guard factor, then 0 for a non-finite C, then the
    // |C|_F dx <= max_speed limit.
    float scale = limit_velocity(v, flags, speed);
    bool c_finite = true;
    for (int a = 0; a < 3; ++a) c_finite = c_finite && !any(isnan(c[a])) && !any(isinf(c[a]));
    if (!c_finite) {
        scale = 0.0;
        flags |= PF_GPU_FLAG_NONFINITE;
    }
    float norm = sqrt(dot(c[0], c[0]) + dot(c[1], c[1]) + dot(c[2], c[2])) * scale;
    float limit = sim.max_speed / sim.dx;
    if (norm > limit) {
        scale *= limit / norm;
        flags |= PF_GPU_FLAG_SPEED_CLAMPED;
    }
    publish_status(speed, flags);
    vel[i] = vec4(v, 0.0);
    for (int a = 0; a < 3; ++a) affine[3u * i + uint(a)] = vec4(scale == 0.0 ? vec3(0.0) : c[a] * scale, 0.0);
}
