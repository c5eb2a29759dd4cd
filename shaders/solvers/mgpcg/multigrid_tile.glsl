// The tiles of the fused multigrid kernels (mg_down.comp, mg_up.comp): workgroup g's tile, cube
// indexing of a staged block, the staged cell types, and the Poisson stencil (poisson.glsl's,
// term for term) read from staged cell types and values in shared memory. A kernel including
// this file declares `const int kStagedCells` and `shared value_t s_e[]` first
// (solver_value.glsl); cells outside the level are staged as SOLID, which the stencil leaves out
// as poisson.glsl leaves out cells past the level's edge.

// Staged type words. A pair's tiles (PF_PAIR 1) keep only each cell's kind, 16 a word: with two
// values a cell, whole words would not fit GL 4.3's 32 KiB of shared memory, and these kernels
// run on coarse levels only, whose words carry nothing but the kind (no surface term).
#if PF_PAIR
shared uint s_kind[(kStagedCells + 15) / 16];
uint staged_type(int i) { return (s_kind[i >> 4] >> (2 * (i & 15))) & 3u; }
void stage_type(int i, uint word) { atomicOr(s_kind[i >> 4], PF_CELL_KIND(word) << (2 * (i & 15))); }
#else
shared uint s_type[kStagedCells];
uint staged_type(int i) { return s_type[i]; }
void stage_type(int i, uint word) { s_type[i] = word; }
#endif
// Every invocation calls this before staging types (a pair's packed kinds start from 0).
void clear_staged_types() {
#if PF_PAIR
    for (int w = int(gl_LocalInvocationIndex); w < (kStagedCells + 15) / 16; w += PF_MG_TILE_INVOCATIONS) s_kind[w] = 0u;
    barrier();
#endif
}

ivec3 tile_coord(int g, ivec3 tiles) { return lattice_coord(tiles, g); }
// Coordinates of entry i of a staged cube of edge n, and back.
ivec3 tile_local(int i, int n) { return lattice_coord(ivec3(n), i); }
int tile_index(ivec3 local, int n) { return lattice_index(ivec3(n), local); }
// Index offsets of the six neighbours in a staged cube of edge n, in kPoissonNeighbours' order.
int[6] tile_steps(int n) { return lattice_steps(ivec3(n)); }

// The stencil of the FLUID cell at staged index s (not on the cube's boundary): diag and the
// FLUID neighbours' values summed per axis pair.
void staged_stencil(int s, int steps[6], out float diag, out pairs_t pair_sum) {
    diag = 0.0;
    pair_sum = pairs_t(0.0);
    for (int n = 0; n < 6; ++n) {
        uint kind = PF_CELL_KIND(staged_type(s + steps[n]));
        if (kind == PF_CELL_SOLID) continue;
        diag += 1.0;
        if (kind == PF_CELL_FLUID) pair_sum[n / 2] += s_e[s + steps[n]];
    }
    diag += surface_extra_diagonal(staged_type(s));
}
