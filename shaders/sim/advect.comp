// Advection, explicit Euler (the original's integrator): x += dt * v with the particle's own
// velocity, then the wall clamp of common/sim.glsl keeps particles inside the domain.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) readonly buffer Vel { vec4 vel[]; };

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    pos[i] = vec4(keep_in_domain(pos[i].xyz + sim.dt * vel[i].xyz), 0.0);
}
