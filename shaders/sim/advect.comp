// Advection, explicit Euler (the original's integrator): x += drift_dt * v with the particle's own
// velocity (drift_dt: the substep, or half of it for the leapfrog's first and last moves of a
// step, design.md §5), then the wall clamp of common/sim.glsl keeps particles inside the domain and a wall
// a particle crossed stops its velocity into it. The path is a straight line, so one clamp at
// its end stops it where sub-steps of the particle trace (common/particle_trace.glsl) would:
// the walls are planes of the grid, and the velocity along them is unchanged by the stop. A move of
// more than a cell is walked in steps of at most a cell, and ends before the first that would enter
// a SOLID cell (common/particle_trace.glsl: the trace's rule for obstacles); a move of at most a
// cell is the original's.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
#include "common/particle_trace.glsl"

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    vec3 v = vel[i].xyz;
    vec3 x0 = pos[i].xyz;
    vec3 x = x0 + sim.drift_dt * v;
    int n = int(clamp(ceil(length(v) * sim.drift_dt / (kTraceCells * sim.dx)), 1.0, float(kMaxTraceSubsteps)));
    vec3 before = x0;
    bool was_solid = n > 1 && in_solid_cell(x0);
    for (int s = 1; n > 1 && s <= n; ++s) {
        vec3 after = s == n ? x : x0 + (float(s) / float(n) * sim.drift_dt) * v;
        bool solid = in_solid_cell(keep_in_domain(after));
        if (solid && !was_solid) {
            x = before;
            break;
        }
        before = after;
        was_solid = solid;
    }
    pos[i] = vec4(keep_in_domain(x), 0.0);
    vel[i].xyz = wall_stopped_velocity(x, v);
}
