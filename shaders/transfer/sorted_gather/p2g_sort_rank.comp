// Sorted-gather P2G, step 4 of 5, per particle: places the particle in its half cell's segment
// of the sorted order by rank, the number of the half cell's particles that come before it in a
// fixed order: by the bits of the position, then of the velocity (then, with PF_APIC, of the affine
// vectors), then by particle index. Particles that tie on everything but the index contribute
// identical terms, so the gather (p2g_gather.comp), which sums each half cell in this order,
// gives the same bits for any order of the particle array and any order of the counting
// atomics. O(n) per particle in a half cell of n particles (O(n^2) per half cell): about one at
// the usual 8 per cell; a half cell holding thousands pays quadratically, but with no atomics.
// What the gather reads of the particle is written there in sorted order, so that neighbouring
// face samples read neighbouring memory: its grid coordinate (computed as p2g.comp does) and its
// velocity, with its index for APIC's affine vectors.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) readonly buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_SORT_CELL_SLOT) readonly buffer CellSlot { uvec2 cell_slot[]; };
layout(std430, binding = PF_SLOT_SORT_HALF_START) readonly buffer Start { uint half_start[]; };
layout(std430, binding = PF_SLOT_SORT_UNSORTED) readonly buffer Unsorted { uint unsorted[]; };
layout(std430, binding = PF_SLOT_SORT_GRID) writeonly buffer SortedGrid { vec4 sorted_grid[]; };
struct SortedParticle {
    vec3 vel;
    uint index;
};
layout(std430, binding = PF_SLOT_SORT_PARTICLE) writeonly buffer SortedParticles { SortedParticle sorted_particle[]; };
#if PF_APIC
layout(std430, binding = PF_SLOT_PARTICLE_AFFINE) readonly buffer Affine { vec4 affine[]; };
#endif

// -1, 0 or 1 as a is before, equal to or after b (lexicographic on the three words).
int compare3(uvec3 a, uvec3 b) {
    if (a.x != b.x) return a.x < b.x ? -1 : 1;
    if (a.y != b.y) return a.y < b.y ? -1 : 1;
    if (a.z != b.z) return a.z < b.z ? -1 : 1;
    return 0;
}

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    uvec2 cs = cell_slot[i];
    uint start = half_start[cs.x], n = half_start[cs.x + 1u] - start;
    uvec3 key_pos = floatBitsToUint(pos[i].xyz), key_vel = floatBitsToUint(vel[i].xyz);
#if PF_APIC
    uvec3 key_affine[3] = uvec3[3](floatBitsToUint(affine[3u * i].xyz), floatBitsToUint(affine[3u * i + 1u].xyz),
                                   floatBitsToUint(affine[3u * i + 2u].xyz));
#endif
    uint rank = 0u;
    for (uint k = 0u; k < n; ++k) {
        uint j = unsorted[start + k];
        int c = compare3(floatBitsToUint(pos[j].xyz), key_pos);
        if (c == 0) c = compare3(floatBitsToUint(vel[j].xyz), key_vel);
#if PF_APIC
        for (uint a = 0u; a < 3u && c == 0; ++a) c = compare3(floatBitsToUint(affine[3u * j + a].xyz), key_affine[a]);
#endif
        if (c < 0 || (c == 0 && j < i)) ++rank;
    }
    sorted_grid[start + rank] = vec4(grid_coord(pos[i].xyz), 0.0);
    sorted_particle[start + rank] = SortedParticle(vel[i].xyz, i);
}
