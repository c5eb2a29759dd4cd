// Spray: a particle with hardly any liquid around it is a droplet, not a piece of the surface.
// Drawn at full radius it makes a sphere-sized bump on the surface or a ball in the air; the
// liquid surface draws it at rnd.spray.x of the radius instead. "Hardly any" is read from the
// simulation's particle counts per cell (its last substep's P2G): fewer than rnd.spray.y
// particles in the particle's cell and its six face neighbours together (half a cell's rest
// count). The counts are used only while they describe the particles (rnd.spray.z = 1: a step
// has run since particles were last added); until then every particle is drawn whole.
// Needs common/render.glsl.
#include "common/grid_layout.glsl"
layout(std430, binding = PF_SSBO_CELL_COUNT) readonly buffer SprayCellCount { uint spray_cell_count[]; };

uint spray_count(ivec3 c) {
    if (!lattice_inside(rnd.grid_dims.xyz, c)) return 0u;
    return spray_cell_count[lattice_index(rnd.grid_dims.xyz, c)];
}

// Radius of the sphere drawn for a particle at `position` (simulation coordinates).
float particle_radius(vec3 position) {
    float r = rnd.sphere.x;
    if (rnd.spray.z < 0.5 || rnd.spray.x >= 1.0) return r;
    ivec3 c = clamp(ivec3(floor((position - rnd.grid_origin.xyz) / rnd.grid_origin.w)), ivec3(0),
                    rnd.grid_dims.xyz - 1);
    uint sum = spray_count(c);
    if (float(sum) >= rnd.spray.y) return r;  // most particles: their own cell decides (one read)
    for (int axis = 0; axis < 3; ++axis) {
        ivec3 d = ivec3(0);
        d[axis] = 1;
        sum += spray_count(c - d) + spray_count(c + d);
    }
    return float(sum) < rnd.spray.y ? r * rnd.spray.x : r;
}
