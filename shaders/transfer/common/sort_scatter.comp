// Counting sort of the particles by a key (the sorted gather's half cell, the tiled scheme's
// tile), per particle: writes the particle's index into its key's segment of the index list, at
// the key's start (exclusive prefix sum of the counts, scan_blocks.comp / scan_add.comp) plus
// the slot the counting atomic gave it. Within a key the order is that of the atomics, which is
// not reproducible (the sorted gather's p2g_sort_rank.comp fixes it; the tiled scheme's integer
// sums do not depend on it).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_SORT_CELL_SLOT) readonly buffer CellSlot { uvec2 cell_slot[]; };
layout(std430, binding = PF_SLOT_SORT_HALF_START) readonly buffer Start { uint half_start[]; };
layout(std430, binding = PF_SLOT_SORT_UNSORTED) writeonly buffer Unsorted { uint unsorted[]; };

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    uvec2 cs = cell_slot[i];
    unsorted[half_start[cs.x] + cs.y] = i;
}
