// Obstacles, per particle, after advection: a particle closer to the obstacles than
// PF_OBSTACLE_PUSH_MARGIN cells (or inside one) is moved along the gradient of the nearest
// obstacle's signed distance (central differences) to that margin outside, and the part of its
// velocity relative to the obstacle's surface there (v + w x r) that points into it is removed
// (free-slip): it leaves at least as fast as a moving obstacle's surface along the normal. Two rounds
// resolve a particle pushed from one obstacle into another; the wall clamp follows. A particle
// inside that was outside a substep ago and moves towards its nearest surface came in through the
// other side and leaves back along its motion instead (came_through). Where the gradient leads
// out of the domain (an obstacle cut by a wall, the particle between its nearest surface and the
// wall) the particle leaves along the axis direction with the shortest way out that stays inside
// the domain instead (sphere-traced through the obstacle).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) buffer Vel { vec4 vel[]; };
#include "effects/obstacles/obstacle_sdf.glsl"

bool in_domain(vec3 x) {
    vec3 g = grid_coord(x);
    return all(greaterThanEqual(g, vec3(kWallEps))) && all(lessThanEqual(g, vec3(sim.grid.xyz) - kWallEps));
}

// The way out of obstacle o from x along one of the six axis directions that ends inside the
// domain, shortest first; x itself when none is found within 32 tracing steps.
vec3 axis_exit(uint o, vec3 x, float margin, out vec3 n) {
    float best = 3.0e38;
    vec3 out_x = x;
    n = vec3(0.0, 1.0, 0.0);
    for (int dir = 0; dir < 6; ++dir) {
        vec3 e = vec3(0.0);
        e[dir / 2] = (dir & 1) == 0 ? -1.0 : 1.0;
        vec3 p = x;
        float travelled = 0.0;
        for (int s = 0; s < 32 && travelled < best; ++s) {
            float d = obstacle_distance(o, p);
            if (d >= margin) break;
            // |d| is the distance to the nearest surface point: a step of margin - d stays at most
            // margin beyond the surface
            p += (margin - d) * e;
            travelled += margin - d;
        }
        if (travelled < best && obstacle_distance(o, p) >= 0.0 && in_domain(p)) {
            best = travelled;
            out_x = p;
            n = e;
        }
    }
    return out_x;
}

// A particle inside obstacle o that was outside a move ago (going back along its last move
// relative to the obstacle) and moves towards the surface nearest to it came in through the other
// side: a thin obstacle or a fast particle put it past the middle. Pushed along the gradient it
// would pass through (tests/engine/test_tunnelling.cpp: a jet against a slab one cell thick); it
// goes back along its motion instead. Returns where it leaves that way, margin outside, or x
// itself when that is not the case or the way back leaves the domain.
vec3 came_through(uint o, vec3 x, float d, vec3 rel, vec3 n, float margin) {
    float speed = length(rel);
    if (d >= 0.0 || speed <= 0.0 || dot(rel, n) <= 0.0) return x;
    if (obstacle_distance(o, x - sim.drift_dt * rel) < 0.0) return x;  // overtaken inside, or started there
    vec3 e = -rel / speed, p = x;
    for (int s = 0; s < 32; ++s) {
        float dp = obstacle_distance(o, p);
        if (dp >= margin) break;
        p += (margin - dp) * e;  // |dp| is the distance to the nearest surface: no further than it
    }
    return obstacle_distance(o, p) >= 0.0 && in_domain(p) ? p : x;
}

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    vec3 x = pos[i].xyz;
    vec3 v = vel[i].xyz;
    float margin = PF_OBSTACLE_PUSH_MARGIN * sim.dx;
    bool moved = false;
    for (int attempt = 0; attempt < 2; ++attempt) {
        int k;
        float d = scene_distance(x, k);
        if (k < 0 || d >= margin) break;
        uint o = uint(k);
        // Central differences, 0.01 cells apart; where they are flat, 8 and 64 times wider. A
        // quantised SDF texture (GL_R8: 3 mm steps of distance) is flat over the small step, and
        // "straight up" there pushed particles under a sphere's equator into it (1 cm deep,
        // SdfFormats test).
        vec3 grad = vec3(0.0);
        float h = 0.01 * sim.dx;
        for (int widen = 0; widen < 3 && grad == vec3(0.0); ++widen, h *= 8.0) {
            grad = vec3(obstacle_distance(o, x + vec3(h, 0, 0)) - obstacle_distance(o, x - vec3(h, 0, 0)),
                        obstacle_distance(o, x + vec3(0, h, 0)) - obstacle_distance(o, x - vec3(0, h, 0)),
                        obstacle_distance(o, x + vec3(0, 0, h)) - obstacle_distance(o, x - vec3(0, 0, h)));
        }
        float len = length(grad);
        vec3 n = len > 0.0 ? grad / len : vec3(0.0, 1.0, 0.0);  // at a medial point: straight up
        vec3 rel = v - obstacle_velocity(o, x);
        vec3 back = came_through(o, x, d, rel, n, margin);
        vec3 pushed = back != x ? back : x + (margin - d) * n;
        if (back != x) n = -normalize(rel);
        x = in_domain(pushed) ? pushed : axis_exit(o, x, margin, n);
        float vn = dot(v - obstacle_velocity(o, x), n);
        if (vn < 0.0) v -= vn * n;
        moved = true;
    }
    if (!moved) return;
    pos[i] = vec4(keep_in_domain(x), 0.0);
    vel[i] = vec4(v, 0.0);
}
