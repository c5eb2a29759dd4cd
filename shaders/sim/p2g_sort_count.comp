// Sorted-gather P2G (pf_p2g PF_P2G_SORTED_GATHER), step 1 of 5, per particle: counts the
// particles of every cell (the cell_count that classification and the volume correction read,
// the same clamp(floor(g)) cell as p2g.comp) and keeps the particle's cell and the slot the
// counting atomic gave it among that cell's particles. The counts are integer increments, so
// they are exact and independent of order; the slots are not (they only place the particle in
// its cell's unsorted segment, p2g_sort_scatter.comp; p2g_sort_rank.comp fixes the order).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_CELL_COUNT) buffer Count { uint cell_count[]; };
layout(std430, binding = PF_SLOT_SORT_CELL_SLOT) writeonly buffer CellSlot { uvec2 cell_slot[]; };

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    ivec3 cell = clamp(ivec3(floor(grid_coord(pos[i].xyz))), ivec3(0), sim.grid.xyz - 1);
    uint c = uint(cell_index(cell));
    cell_slot[i] = uvec2(c, atomicAdd(cell_count[c], 1u));
}
