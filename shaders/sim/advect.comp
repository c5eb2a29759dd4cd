// Advection, explicit Euler (the original's integrator): x += dt * v, then particles are
// kept inside the domain by clamping their grid coordinate to [eps, n - eps], the same
// margin on every side (no wall bias).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) readonly buffer Vel { vec4 vel[]; };

const float kWallMargin = 1e-3;  // cells

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    vec3 x = pos[i].xyz + sim.dt * vel[i].xyz;
    vec3 g = grid_coord(x);
    vec3 clamped = clamp(g, vec3(kWallMargin), vec3(sim.grid.xyz) - kWallMargin);
    x = mix(x, sim.origin.xyz + clamped * sim.dx, notEqual(g, clamped));
    pos[i] = vec4(x, 0.0);
}
