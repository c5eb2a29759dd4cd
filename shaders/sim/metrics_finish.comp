// Accuracy metrics of a step, second half (docs/design.md §4.11): one workgroup adds the
// partial sums of metrics.comp in a fixed order (invocation t takes partials t, t + 256, ...,
// then a binary tree), turns them into the step's metrics and writes them to the status
// buffer, which pf_step copies into the readback ring. FLUID cells are added as integers (each
// workgroup's count, at most 256, is exact in a float), so the count is exact on any grid.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_METRICS_PARTIALS) readonly buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_STATUS) buffer Status { uint status[]; };
layout(location = PF_LOC_METRICS_GROUPS) uniform uint u_groups;

shared vec4 s_sum[PF_WORKGROUP_SIZE];   // (div^2, max |div|, volume fraction, |v|^2)
shared uint s_fluid[PF_WORKGROUP_SIZE];
shared float s_height[PF_WORKGROUP_SIZE];  // sum of -g . (x - origin)
shared float s_interior[PF_WORKGROUP_SIZE];  // sum of count / rest over interior cells
shared uint s_interior_cells[PF_WORKGROUP_SIZE];
shared float s_strain[PF_WORKGROUP_SIZE];  // sum of the strain P over interior cells

void main() {
    uint lid = gl_LocalInvocationIndex;
    vec4 sum = vec4(0.0);
    uint fluid = 0u;
    float height = 0.0;
    float interior = 0.0;
    uint interior_cells = 0u;
    float strain = 0.0;
    for (uint g = lid; g < u_groups; g += uint(PF_WORKGROUP_SIZE)) {
        vec4 grid = partials[3u * g];
        sum += vec4(grid.x, 0.0, grid.w, partials[3u * g + 1u].x);
        sum.y = max(sum.y, grid.y);
        fluid += uint(grid.z);
        vec4 particles = partials[3u * g + 1u];
        strain += partials[3u * g + 2u].x;
        height += particles.y;
        interior += particles.z;
        interior_cells += uint(particles.w);
    }
    s_sum[lid] = sum;
    s_fluid[lid] = fluid;
    s_height[lid] = height;
    s_interior[lid] = interior;
    s_interior_cells[lid] = interior_cells;
    s_strain[lid] = strain;
    barrier();
    for (uint stride = uint(PF_WORKGROUP_SIZE) / 2u; stride > 0u; stride >>= 1u) {
        if (lid < stride) {
            vec4 a = s_sum[lid], b = s_sum[lid + stride];
            s_sum[lid] = vec4(a.x + b.x, max(a.y, b.y), a.z + b.z, a.w + b.w);
            s_fluid[lid] += s_fluid[lid + stride];
            s_height[lid] += s_height[lid + stride];
            s_interior[lid] += s_interior[lid + stride];
            s_interior_cells[lid] += s_interior_cells[lid + stride];
            s_strain[lid] += s_strain[lid + stride];
        }
        barrier();
    }
    if (lid != 0u) return;
    vec4 total = s_sum[0];
    uint cells = s_fluid[0];
    float cell_volume = sim.dx * sim.dx * sim.dx;
    float particle_mass = sim.density * cell_volume / sim.rest_particles;
    status[PF_STATUS_DIVERGENCE_L2] = floatBitsToUint(cells > 0u ? sqrt(total.x / float(cells)) : 0.0);
    status[PF_STATUS_DIVERGENCE_MAX] = floatBitsToUint(total.y);
    status[PF_STATUS_KINETIC_ENERGY] = floatBitsToUint(0.5 * particle_mass * total.w);
    status[PF_STATUS_FLUID_CELLS] = cells;
    status[PF_STATUS_PARTICLE_VOLUME] = floatBitsToUint(cell_volume * total.z);
    status[PF_STATUS_POTENTIAL_ENERGY] = floatBitsToUint(particle_mass * s_height[0]);
    status[PF_STATUS_PARTICLE_COUNT] = sim.particle_count;
    uint inner = s_interior_cells[0];
    status[PF_STATUS_INTERIOR_DENSITY] = floatBitsToUint(inner > 0u ? s_interior[0] / float(inner) : 0.0);
    // Over every FLUID cell: a surface cell counts as unstrained (the straight moves' compression
    // of the whole liquid; the step clock's strain limit was measured with this mean).
    status[PF_STATUS_STRAIN] = floatBitsToUint(cells > 0u ? s_strain[0] / float(cells) : 0.0);
}
