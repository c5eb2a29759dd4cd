// Signed distance (m, negative inside) of the obstacle list on PF_SLOT_OBSTACLES, shared by the
// obstacle kernels. The scene is the union of the obstacles: the smallest distance wins.
// SDF obstacles sample the engine's 3D texture bound to unit PF_TEX_UNIT_SDF + k (record k),
// with linear filtering; the texture covers the local box [-h, h], so texture coordinate
// p / (2 h) + 0.5. Outside the box the distance is the box surface's sample plus the way to it.
// Requires common/sim.glsl.
#include "effects/obstacles/obstacle_shapes.h"
layout(std430, binding = PF_SLOT_OBSTACLES) readonly buffer Obstacles { vec4 obstacles[]; };
layout(location = PF_LOC_EFFECT_COUNT) uniform uint u_count;  // live obstacles
layout(binding = PF_TEX_UNIT_SDF) uniform sampler3D u_sdf[PF_OBSTACLE_MAX];

// One texel of obstacle k's texture. Sampler arrays take only dynamically uniform indices in
// GLSL 4.30, and k differs between invocations (obstacle_push), so each index is a constant.
float sdf_texel(uint k, vec3 uvw) {
    switch (int(k)) {
        case 0: return textureLod(u_sdf[0], uvw, 0.0).r;
        case 1: return textureLod(u_sdf[1], uvw, 0.0).r;
        case 2: return textureLod(u_sdf[2], uvw, 0.0).r;
        case 3: return textureLod(u_sdf[3], uvw, 0.0).r;
        case 4: return textureLod(u_sdf[4], uvw, 0.0).r;
        case 5: return textureLod(u_sdf[5], uvw, 0.0).r;
        case 6: return textureLod(u_sdf[6], uvw, 0.0).r;
        case 7: return textureLod(u_sdf[7], uvw, 0.0).r;
        case 8: return textureLod(u_sdf[8], uvw, 0.0).r;
        case 9: return textureLod(u_sdf[9], uvw, 0.0).r;
        case 10: return textureLod(u_sdf[10], uvw, 0.0).r;
        case 11: return textureLod(u_sdf[11], uvw, 0.0).r;
        case 12: return textureLod(u_sdf[12], uvw, 0.0).r;
        case 13: return textureLod(u_sdf[13], uvw, 0.0).r;
        case 14: return textureLod(u_sdf[14], uvw, 0.0).r;
        case 15: return textureLod(u_sdf[15], uvw, 0.0).r;
    }
    return 3.0e38;
}

// v rotated by the inverse of unit quaternion q (world direction -> obstacle frame).
vec3 rotate_inverse(vec4 q, vec3 v) {
    vec3 u = -q.xyz;
    vec3 t = 2.0 * cross(u, v);
    return v + q.w * t + cross(u, t);
}

float obstacle_distance(uint k, vec3 x) {
    vec4 ps = obstacles[PF_OBSTACLE_VEC4S * k];
    vec4 size = obstacles[PF_OBSTACLE_VEC4S * k + 2u];
    vec3 p = rotate_inverse(obstacles[PF_OBSTACLE_VEC4S * k + 1u], x - ps.xyz);
    int shape = int(ps.w);
    if (shape == PF_OBSTACLE_SDF_ID) {
        vec3 q = clamp(p, -size.xyz, size.xyz);
        float t = sdf_texel(k, q / (2.0 * size.xyz) + 0.5);
        if (obstacles[PF_OBSTACLE_VEC4S * k + 3u].w > 0.5) t = 2.0 * t - 1.0;
        return t * size.w + length(p - q);
    }
    if (shape == PF_OBSTACLE_BOX_ID) {
        vec3 q = abs(p) - size.xyz;
        return length(max(q, vec3(0.0))) + min(max(q.x, max(q.y, q.z)), 0.0);
    }
    if (shape == PF_OBSTACLE_CAPSULE_ID) p.y -= clamp(p.y, -size.y, size.y);
    return length(p) - size.x;
}

// Velocity of obstacle k's material at world point x: v + w x (x - position).
vec3 obstacle_velocity(uint k, vec3 x) {
    vec3 r = x - obstacles[PF_OBSTACLE_VEC4S * k].xyz;
    return obstacles[PF_OBSTACLE_VEC4S * k + 3u].xyz + cross(obstacles[PF_OBSTACLE_VEC4S * k + 4u].xyz, r);
}

// Distance of the union at x and the obstacle it belongs to (-1 when there is none).
float scene_distance(vec3 x, out int nearest) {
    float best = 3.0e38;
    nearest = -1;
    for (uint k = 0u; k < u_count; ++k) {
        float d = obstacle_distance(k, x);
        if (d < best) {
            best = d;
            nearest = int(k);
        }
    }
    return best;
}

