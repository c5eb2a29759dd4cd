// Tiled P2G (pf_p2g PF_P2G_TILED), step 1 of 4, per particle: counts the particles of every tile
// (PF_P2G_TILE^3 cells, of the same clamp(floor(g)) cell as transfer/atomic/p2g.comp) and keeps
// the particle's tile and the slot the counting atomic gave it, for the counting sort
// (transfer/common/scan_blocks.comp, scan_add.comp, sort_scatter.comp).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_SORT_HALF_COUNT) buffer TileCount { uint tile_count[]; };
layout(std430, binding = PF_SLOT_SORT_CELL_SLOT) writeonly buffer TileSlot { uvec2 tile_slot[]; };

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    ivec3 cell = clamp(ivec3(floor(grid_coord(pos[i].xyz))), ivec3(0), sim.grid.xyz - 1);
    ivec3 tiles = (sim.grid.xyz + PF_P2G_TILE - 1) / PF_P2G_TILE;
    ivec3 t = cell / PF_P2G_TILE;
    uint tile = uint(t.x + tiles.x * (t.y + tiles.y * t.z));
    tile_slot[i] = uvec2(tile, atomicAdd(tile_count[tile], 1u));
}
