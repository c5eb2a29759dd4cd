// Advection, explicit Euler (the original's integrator): x += dt * v with the particle's own
// velocity, then the wall clamp of common/sim.glsl keeps particles inside the domain and a wall
// a particle crossed stops its velocity into it. The path is a straight line, so one clamp at
// its end stops it where sub-steps of the particle trace (common/particle_trace.glsl) would:
// the walls are planes of the grid, and the velocity along them is unchanged by the stop.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) buffer Vel { vec4 vel[]; };

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    vec3 v = vel[i].xyz;
    vec3 x = pos[i].xyz + sim.dt * v;
    pos[i] = vec4(keep_in_domain(x), 0.0);
    vel[i].xyz = wall_stopped_velocity(x, v);
}
