// Signed distance (m, negative inside) of the obstacle list on PF_SLOT_OBSTACLES, shared by the
// obstacle kernels. The scene is the union of the obstacles: the smallest distance wins.
// Requires common/sim.glsl.
#include "effects/obstacles/obstacle_shapes.h"
layout(std430, binding = PF_SLOT_OBSTACLES) readonly buffer Obstacles { vec4 obstacles[]; };
layout(location = PF_LOC_EFFECT_COUNT) uniform uint u_count;  // live obstacles

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

// World position of the centre of cell c.
vec3 cell_centre(ivec3 c) { return sim.origin.xyz + (vec3(c) + 0.5) * sim.dx; }

// World position of the centre of face f of lattice `axis` (decode_face).
vec3 face_centre(int axis, ivec3 f) {
    vec3 offset = vec3(0.5);
    offset[axis] = 0.0;
    return sim.origin.xyz + (vec3(f) + offset) * sim.dx;
}
