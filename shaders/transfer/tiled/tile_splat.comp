// Tiled P2G (pf_p2g PF_P2G_TILED), step 4 of 4, one workgroup per tile of PF_P2G_TILE^3 cells:
// its particles (grouped by the counting sort) add the same rounded fixed-point terms as
// transfer/atomic/p2g.comp, but into shared memory, over a window of PF_P2G_TILE_WINDOW^3 face
// samples per lattice (the tile's and one around it, which holds every stencil node of a particle
// in the tile); then each nonzero window sum is added to the face accumulators with one global
// atomic, and the tile's cells get their counts. Integer sums wrap the same way in any grouping,
// so the accumulators are bit-identical to p2g.comp's, with about 30 times fewer global atomics
// at 8 particles per cell. An overflow is flagged wherever an addition overflows (shared or
// global), as in p2g.comp: a sum that does not fit is always caught at its last addition.
// Permutation PF_APIC: affine contributions. Both kernels take their terms from
// transfer/common/p2g_terms.glsl.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) readonly buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_TILE_START) readonly buffer Start { uint tile_start[]; };
layout(std430, binding = PF_SLOT_TILE_ORDER) readonly buffer Order { uint order[]; };
layout(std430, binding = PF_SLOT_FACE_ACCUM) buffer Accum { int accum[]; };  // 2 words per face
layout(std430, binding = PF_SLOT_CELL_COUNT) writeonly buffer Count { uint cell_count[]; };
layout(std430, binding = PF_SLOT_STATUS) buffer Status { uint status[]; };
#if PF_APIC
layout(std430, binding = PF_SLOT_PARTICLE_AFFINE) readonly buffer Affine { vec4 affine[]; };
#endif
#include "transfer/common/p2g_terms.glsl"

const int kWindowSamples = PF_P2G_TILE_WINDOW * PF_P2G_TILE_WINDOW * PF_P2G_TILE_WINDOW;
const int kTileCells = PF_P2G_TILE * PF_P2G_TILE * PF_P2G_TILE;
shared int s_accum[3 * kWindowSamples * 2];  // per lattice, per window sample: momentum, weight
shared uint s_count[kTileCells];
shared uint s_overflow;

// Whether adding `value` to `old` wrapped past the int range.
bool overflowed(int old, int value) {
    int sum = int(uint(old) + uint(value));
    return (old >= 0) == (value >= 0) && (sum >= 0) != (old >= 0);
}

void add_global(int word, int value) {
    if (value == 0) return;
    if (overflowed(atomicAdd(accum[word], value), value)) atomicOr(status[PF_STATUS_FLAGS], PF_GPU_FLAG_P2G_OVERFLOW);
}

void add_shared(int slot, int value) {
    if (value == 0) return;  // zero weights (clamped stencil edges) cost no atomic
    if (overflowed(atomicAdd(s_accum[slot], value), value)) s_overflow = 1u;
}

// The tile's cell counts (those inside the grid): the shared counts, or 0 for an empty tile.
void write_counts(ivec3 first_cell, int lane, bool counted) {
    for (int k = lane; k < kTileCells; k += PF_WORKGROUP_SIZE) {
        ivec3 cell = first_cell + lattice_coord(ivec3(PF_P2G_TILE), k);
        if (cell_inside(cell)) cell_count[cell_index(cell)] = counted ? s_count[k] : 0u;
    }
}

void main() {
    ivec3 tiles = tile_dims(sim.grid.xyz, PF_P2G_TILE);
    uint tile = flat_id() / uint(PF_WORKGROUP_SIZE);
    if (tile >= uint(lattice_total(tiles))) return;  // the whole workgroup
    int lane = int(gl_LocalInvocationID.x);
    ivec3 first_cell = tile_first_cell(lattice_coord(tiles, int(tile)), PF_P2G_TILE);
    ivec3 origin = first_cell - 1;  // the window's first face sample, on every lattice
    uint begin = tile_start[tile], end = tile_start[tile + 1u];
    if (begin == end) {
        // No particles (most of a tank's air): its cells count 0 and its window adds nothing.
        write_counts(first_cell, lane, false);
        return;  // the whole workgroup
    }
    for (int k = lane; k < 3 * kWindowSamples * 2; k += PF_WORKGROUP_SIZE) s_accum[k] = 0;
    for (int k = lane; k < kTileCells; k += PF_WORKGROUP_SIZE) s_count[k] = 0u;
    if (lane == 0) s_overflow = 0u;
    barrier();

    for (uint k = begin + uint(lane); k < end; k += uint(PF_WORKGROUP_SIZE)) {
        uint i = order[k];
        vec3 g = grid_coord(pos[i].xyz);
        vec3 v = vel[i].xyz;
        ivec3 cell = cell_of(g);
        ivec3 c = clamp(cell - first_cell, ivec3(0), ivec3(PF_P2G_TILE - 1));  // the same cell tile_count gave this tile
        atomicAdd(s_count[lattice_index(ivec3(PF_P2G_TILE), c)], 1u);
        for (int axis = 0; axis < 3; ++axis) {
            LatticeTerms t = lattice_terms(i, axis, g, v);
            for (int n = 0; n < 8; ++n) {
                float w = term_weight(t, n);
                int momentum = fixed_momentum(w, term_velocity(t, n)), weight = fixed_weight(w);
                ivec3 node = term_node(t, n);
                ivec3 s = node - origin;
                if (lattice_inside(ivec3(PF_P2G_TILE_WINDOW), s)) {
                    int slot = 2 * (axis * kWindowSamples + lattice_index(ivec3(PF_P2G_TILE_WINDOW), s));
                    add_shared(slot, momentum);
                    add_shared(slot + 1, weight);
                } else {  // not expected (the window holds every node); correct either way
                    int face = face_index(axis, node);
                    add_global(accum_word(face, 0), momentum);
                    add_global(accum_word(face, 1), weight);
                }
            }
        }
    }
    barrier();

    for (int k = lane; k < 3 * kWindowSamples * 2; k += PF_WORKGROUP_SIZE) {
        int value = s_accum[k];
        if (value == 0) continue;  // also every window sample outside its lattice
        int window_index = k / 2, axis = window_index / kWindowSamples, w = window_index % kWindowSamples;
        ivec3 node = origin + lattice_coord(ivec3(PF_P2G_TILE_WINDOW), w);
        add_global(accum_word(face_index(axis, node), k & 1), value);
    }
    write_counts(first_cell, lane, true);
    if (lane == 0 && s_overflow != 0u) atomicOr(status[PF_STATUS_FLAGS], PF_GPU_FLAG_P2G_OVERFLOW);
}
