// Tiled P2G (pf_p2g PF_P2G_TILED), step 1 of 4, per particle: counts the particles of every tile
// (PF_P2G_TILE^3 cells, of the same clamp(floor(g)) cell as transfer/atomic/p2g.comp) and keeps
// the particle's tile and the slot the count gave it, for the counting sort
// (transfer/common/scan_blocks.comp, scan_add.comp, sort_scatter.comp).
// Neighbours in the particle buffer are mostly neighbours in space, so a workgroup's particles
// fall in a few tiles: they are counted per tile in shared memory first (a small hash table),
// and each of those tiles takes one global atomic for all of them. One global atomic per
// particle made a warp's 32 additions to one counter wait on each other. The slots a tile hands
// out differ from run to run either way; the splat's integer sums do not depend on them.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_SORT_HALF_COUNT) buffer TileCount { uint tile_count[]; };
layout(std430, binding = PF_SLOT_SORT_CELL_SLOT) writeonly buffer TileSlot { uvec2 tile_slot[]; };

// Open addressing over as many entries as the workgroup has particles, so a free entry is always
// found: the tile + 1 (0: free), the workgroup's particles in it, the tile's first global slot.
shared uint s_key[PF_WORKGROUP_SIZE];
shared uint s_count[PF_WORKGROUP_SIZE];
shared uint s_base[PF_WORKGROUP_SIZE];

void main() {
    uint i = flat_id();
    uint lane = gl_LocalInvocationID.x;
    s_key[lane] = 0u;
    s_count[lane] = 0u;
    barrier();
    bool live = i < sim.particle_count;  // no early return: every invocation reaches the barriers
    uint tile = 0u, entry = 0u, rank = 0u;
    if (live) {
        ivec3 cell = cell_of(grid_coord(pos[i].xyz));
        tile = uint(lattice_index(tile_dims(sim.grid.xyz, PF_P2G_TILE), tile_of(cell, PF_P2G_TILE)));
        entry = tile % uint(PF_WORKGROUP_SIZE);
        for (;;) {
            uint held = atomicCompSwap(s_key[entry], 0u, tile + 1u);
            if (held == 0u || held == tile + 1u) break;
            entry = (entry + 1u) % uint(PF_WORKGROUP_SIZE);
        }
        rank = atomicAdd(s_count[entry], 1u);
    }
    barrier();
    if (s_count[lane] != 0u) s_base[lane] = atomicAdd(tile_count[s_key[lane] - 1u], s_count[lane]);
    barrier();
    if (live) tile_slot[i] = uvec2(tile, s_base[entry] + rank);
}
