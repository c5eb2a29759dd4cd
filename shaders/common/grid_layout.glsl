// Where a grid's cells live in storage: every lattice (the cells, each face lattice, the
// multigrid levels, viscosity's nodes, tiles and staged blocks) is a dense box of dims d, x
// fastest. Pure functions of d, with no uniform block, so that render shaders can include it.
// Kernels reach cells through these and the wrappers built on them (common/sim.glsl's cell_*,
// face_* and node_*, solvers/common/poisson.glsl's level_*, solvers/mgpcg/multigrid.glsl's
// coarse_*, multigrid_tile.glsl's staged cubes, common/ssf_spray.glsl's reads of the cell
// counts): the one place a sparse layout would change.

// The flat index of c in a box of d.
int lattice_index(ivec3 d, ivec3 c) { return c.x + d.x * (c.y + d.y * c.z); }

// The coordinates of flat index i in a box of d, with two integer divisions (each a long
// instruction sequence on GPUs); i % d.x, (i / d.x) % d.y, i / (d.x d.y) takes three divisions
// and two modulos (docs/notes/2026-11-27-kernel-profile-and-gaps.md).
ivec3 lattice_coord(ivec3 d, int i) {
    int row = i / d.x;
    int k = row / d.y;
    return ivec3(i - row * d.x, row - k * d.y, k);
}

int lattice_total(ivec3 d) { return d.x * d.y * d.z; }
bool lattice_inside(ivec3 d, ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, d)); }

// Index offsets of the six face neighbours in a box of d: -x, +x, -y, +y, -z, +z.
int[6] lattice_steps(ivec3 d) { return int[6](-1, 1, -d.x, d.x, -d.x * d.y, d.x * d.y); }

// Tiles of `edge` cells a side over a box of d (the last ones partly outside it): their count
// per axis, the tile holding cell c, and a tile's first cell.
ivec3 tile_dims(ivec3 d, int edge) { return (d + edge - 1) / edge; }
ivec3 tile_of(ivec3 c, int edge) { return c / edge; }
ivec3 tile_first_cell(ivec3 t, int edge) { return t * edge; }

// Red-black colour of a cell: 0 when i + j + k is even.
uint cell_color_at(ivec3 ijk) { return uint(ijk.x + ijk.y + ijk.z) & 1u; }
