// The tiles of the fused multigrid kernels (mg_down.comp, mg_up.comp): workgroup g's tile, cube
// indexing of a staged block, and the Poisson stencil (poisson.glsl's, term for term) read from
// staged cell types and values in shared memory. A kernel including this file declares
// `shared uint s_type[]` and `shared float s_e[]` first; cells outside the level are staged as
// SOLID, which the stencil leaves out as poisson.glsl leaves out cells past the level's edge.

ivec3 tile_coord(int g, ivec3 tiles) { return unflatten(g, tiles); }
// Coordinates of entry i of a staged cube of edge n, and back.
ivec3 tile_local(int i, int n) { return unflatten(i, ivec3(n)); }
int tile_index(ivec3 local, int n) { return local.x + n * (local.y + n * local.z); }
// Index offsets of the six neighbours in a staged cube of edge n, in kPoissonNeighbours' order.
int[6] tile_steps(int n) { return int[6](-1, 1, -n, n, -n * n, n * n); }

// The stencil of the FLUID cell at staged index s (not on the cube's boundary): diag and the
// FLUID neighbours' values summed per axis pair.
void staged_stencil(int s, int steps[6], out float diag, out vec3 pair_sum) {
    diag = 0.0;
    pair_sum = vec3(0.0);
    for (int n = 0; n < 6; ++n) {
        uint kind = PF_CELL_KIND(s_type[s + steps[n]]);
        if (kind == PF_CELL_SOLID) continue;
        diag += 1.0;
        if (kind == PF_CELL_FLUID) pair_sum[n / 2] += s_e[s + steps[n]];
    }
    diag += surface_extra_diagonal(s_type[s]);
}
