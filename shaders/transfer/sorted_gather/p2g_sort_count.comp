// Sorted-gather P2G (pf_p2g PF_P2G_SORTED_GATHER), step 1 of 5, per particle: counts the
// particles of every cell (the cell_count that classification and the volume correction read,
// the same clamp(floor(g)) cell as p2g.comp) and of every half cell (2 x 2 x 2 per cell,
// h = clamp(floor(2 g), 0, 2 n - 1): every stencil base of every lattice is a function of h,
// see p2g_gather.comp), and keeps the particle's half cell and the slot the counting atomic gave
// it among that half cell's particles. The counts are integer increments, so they are exact and
// independent of order; the slots are not (they only place the particle in its half cell's
// unsorted segment, transfer/common/sort_scatter.comp; p2g_sort_rank.comp fixes the order).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_CELL_COUNT) buffer Count { uint cell_count[]; };
layout(std430, binding = PF_SLOT_SORT_HALF_COUNT) buffer HalfCount { uint half_count[]; };
layout(std430, binding = PF_SLOT_SORT_CELL_SLOT) writeonly buffer CellSlot { uvec2 cell_slot[]; };

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    // 2 g is exact in float, so floor(h / 2) is the cell p2g.comp computes from floor(g).
    ivec3 h = half_cell_of(grid_coord(pos[i].xyz));
    atomicAdd(cell_count[cell_index(h >> 1)], 1u);
    uint half_cell = uint(half_cell_index(h));
    cell_slot[i] = uvec2(half_cell, atomicAdd(half_count[half_cell], 1u));
}
