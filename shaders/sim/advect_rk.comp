// Advection through the grid velocity with an explicit Runge-Kutta scheme (design.md §4.10).
// PF_RK_ORDER 2: the midpoint rule; 3: Ralston's third-order method. PF_RK_OFFSET 1
// (PF_ADVECTION_RK2_OFFSET): the first stage is the particle's own velocity v and every later one
// adds its difference from the grid velocity at its start, d = v - u(x0), so a particle keeps its
// FLIP velocity where the grid is uniform and the grid's change along the path bends it (at a
// wall, u's normal part and so the path's go to 0 instead of the move ending against the wall);
// PF_ORDERED walks the particles in the tiled P2G's order, as G2P does on large grids (its reads
// of the faces are gathers too). The particle is traced in
// sub-steps that cross at most one cell each, sized by the velocity at their start
// (common/particle_trace.glsl). Every stage samples the projected, extrapolated face velocity
// with G2P's clamped trilinear stencil (§3) at the stage position, and every stage position,
// like each sub-step's end, goes through Euler's wall clamp, so the field is only sampled inside
// the domain; a wall any sub-step crossed stops the particle's velocity into it, and so does a wall
// its own velocity would cross in the substep (Euler's rule: the grid's velocity into a wall goes
// to 0 at the wall, so a traced path slows to it without crossing, and a lone particle's velocity
// into the floor, never stopped, grew with gravity for ever); with PF_SOLID_WALLS (obstacles) the
// trace ends before any sub-step, a single one too, whose move would enter a SOLID cell (landed
// inside a wall one cell thick past its middle, the obstacles' push would put a particle out on
// the far side), and common/solid_walls.glsl stops its stencils at such walls. Why: Euler with
// the particle's velocity spirals out of a rotating flow by sqrt(1 + w^2 dt^2) per step; these
// schemes follow the grid's flow to O(dt^3) and O(dt^4) per sub-step.
#include "common/sim.glsl"
#if !defined(PF_RK_OFFSET) || (PF_RK_OFFSET && PF_RK_ORDER != 2)
#error PF_RK_OFFSET must be 0, or 1 with PF_RK_ORDER 2
#endif
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_FACE_VEL) readonly buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
#include "common/particle_order.glsl"
#include "common/particle_trace.glsl"

#include "common/face_velocity.glsl"

void main() {
    uint t = flat_id();
    if (t >= sim.particle_count) return;
    uint i = particle_slot(t);
    vec3 x0 = pos[i].xyz;
    const vec3 v0 = vel[i].xyz;
    WallsCrossed walls = no_walls_crossed();
    trace_wall_clamp(x0 + sim.drift_dt * v0, walls);  // the walls its own velocity would cross
#if PF_RK_OFFSET
    const vec3 d = v0 - sample_velocity(keep_in_domain(x0));  // sampled inside, as every stage
#else
    const vec3 d = vec3(0.0);
#endif
    float remaining = sim.drift_dt;
#if PF_SOLID_WALLS
    bool was_solid = false;  // whether the sub-step starts in a SOLID cell (read at the first)
#endif
    for (int s = 0; s < kMaxTraceSubsteps; ++s) {
#if PF_RK_OFFSET
        vec3 k1 = s == 0 ? v0 : sample_velocity(x0) + d;
#else
        vec3 k1 = sample_velocity(x0);
#endif
        float dt = trace_substep(length(k1), remaining, s);
        vec3 k2 = sample_velocity(keep_in_domain(x0 + (0.5 * dt) * k1)) + d;
#if PF_RK_ORDER == 2
        vec3 x = x0 + dt * k2;
#elif PF_RK_ORDER == 3
        vec3 k3 = sample_velocity(keep_in_domain(x0 + (0.75 * dt) * k2));
        vec3 x = x0 + dt * ((2.0 / 9.0) * k1 + (1.0 / 3.0) * k2 + (4.0 / 9.0) * k3);
#else
#error PF_RK_ORDER must be 2 or 3
#endif
        WallsCrossed crossed = walls;
        vec3 next = trace_wall_clamp(x, crossed);
#if PF_SOLID_WALLS  // only obstacles make SOLID cells
        if (s == 0) was_solid = in_solid_cell(x0);
        // A move that enters no SOLID cell ends outside one (move_enters_solid samples its end).
        if (was_solid)
            was_solid = in_solid_cell(next);
        else if (move_enters_solid(x0, next))
            break;
#endif
        x0 = next;
        walls = crossed;
        if (dt == remaining) break;
        remaining -= dt;
    }
    pos[i] = vec4(x0, 0.0);
    vel[i].xyz = stopped_at_walls(walls.low, walls.high, v0);
}
