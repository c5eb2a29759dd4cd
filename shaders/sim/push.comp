// Interaction impulse (pf_push): adds dv to the velocity of particles within a sphere,
// weighted by a smooth falloff (1 - (d/r)^2)^2 that reaches 0 at the rim, then clamps the
// speed to max_speed (flagged, as in G2P).
#include "common/dispatch.glsl"
#include "common/robust_length.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_STATUS) buffer Status { uint status[]; };
layout(location = PF_LOC_PUSH_CENTER_RADIUS) uniform vec4 u_center_radius;
layout(location = PF_LOC_PUSH_DV_MAX_SPEED) uniform vec4 u_dv_max_speed;
layout(location = PF_LOC_PUSH_COUNT) uniform uint u_count;

void main() {
    uint i = flat_id();
    if (i >= u_count) return;
    // (|offset| / r)^2 without squaring either first: a centre or radius near float range would
    // make both squares +Inf and q NaN. Both are scaled by the same power of two when either is
    // huge: NVIDIA divides as a * (1 / b), and 1 / b is denormal, flushed to 0, for b > 2^126.
    vec3 offset = pos[i].xyz - u_center_radius.xyz;
    float radius = u_center_radius.w;
    if (max(max(max(abs(offset.x), abs(offset.y)), abs(offset.z)), radius) > kRobustLarge) {
        offset *= kRobustDown;
        radius *= kRobustDown;
    }
    float q = length(offset) / radius;
    q *= q;
    if (q >= 1.0) return;
    float falloff = (1.0 - q) * (1.0 - q);
    vec3 v = vel[i].xyz + falloff * u_dv_max_speed.xyz;
    float speed = robust_length(v);
    if (speed > u_dv_max_speed.w) {
        v = robust_direction(v) * u_dv_max_speed.w;
        atomicOr(status[PF_STATUS_FLAGS], PF_GPU_FLAG_SPEED_CLAMPED);
    }
    vel[i] = vec4(v, 0.0);
}
