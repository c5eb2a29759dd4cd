// The pressure Poisson operator shared by every solver, on any grid level (dims from the
// u_dims uniform): for a FLUID cell i,  (A p)_i = diag_i p_i - sum over FLUID neighbours p_j,
// where diag_i counts the in-domain neighbours that are not SOLID (FLUID and AIR: p = 0 in
// AIR, a Dirichlet free surface) plus the extra diagonal of the ghost-fluid surface that a fine
// level's FLUID word carries (common/free_surface.glsl; coarser levels' words carry none);
// domain walls and SOLID cells are left out (Neumann).
// Requires the kernel to declare `cell_type` (uint per cell) before including this file.
#include "common/slots.h"
#include "common/dispatch.glsl"
#include "solvers/common/solver_state.h"
#include "common/free_surface.glsl"

layout(location = PF_LOC_SOLVER_DIMS) uniform ivec4 u_dims;  // nx, ny, nz, cells of this level

#include "solvers/common/poisson_neighbours.glsl"

ivec3 level_coord(int c) { return lattice_coord(u_dims.xyz, c); }
int level_index(ivec3 ijk) { return lattice_index(u_dims.xyz, ijk); }
bool level_inside(ivec3 ijk) { return lattice_inside(u_dims.xyz, ijk); }

// The stencil of FLUID cell c: neighbour indices (-1 where the neighbour is not FLUID) and diag.
struct PoissonStencil {
    int nb[6];
    float diag;
};

// The same for cell c at coordinates ijk (kernels that know them need not divide again).
PoissonStencil poisson_stencil_at(int c, ivec3 ijk) {
    PoissonStencil s;
    s.diag = 0.0;
    for (int n = 0; n < 6; ++n) {
        s.nb[n] = -1;
        ivec3 q = ijk + kPoissonNeighbours[n];
        if (!level_inside(q)) continue;
        int nc = level_index(q);
        uint t = PF_CELL_KIND(cell_type[nc]);
        if (t == PF_CELL_SOLID) continue;
        s.diag += 1.0;
        if (t == PF_CELL_FLUID) s.nb[n] = nc;
    }
    s.diag += surface_extra_diagonal(cell_type[c]);
    return s;
}
PoissonStencil poisson_stencil(int c) { return poisson_stencil_at(c, level_coord(c)); }

// Neighbour values summed per axis pair, then across axes: mirrored inputs give bit-mirrored
// sums (as common/sim.glsl's mirror_sum), so the solvers keep the scheme's mirror symmetry.
float pair_total(vec3 pair_sum) { return (pair_sum.x + pair_sum.y) + pair_sum.z; }
// The same for a pair's values (solver_value.glsl): a column per axis pair.
vec2 pair_total(mat3x2 pair_sum) { return (pair_sum[0] + pair_sum[1]) + pair_sum[2]; }

// Index of a workgroup in a (possibly 2D) dispatch: one partial sum each.
uint workgroup_index() { return gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x; }

// Mirror orbits: the cell (i, j, k) and its images under the x and z mirrors (the scheme is
// mirror symmetric across both; gravity breaks y). A reduction that adds each orbit's 4 cells
// as ((a + b) + (c + d)) — pairs that swap under one mirror, and pair sums that swap under the
// other — and then the orbit sums in a fixed order gives bit-identical totals for mirrored
// inputs (orbit_main.glsl): the solvers' convergence decisions and Krylov scalars stay mirror-exact.
int orbit_count() { return lattice_total(ivec3((u_dims.x + 1) / 2, u_dims.y, (u_dims.z + 1) / 2)); }

// The orbit's first cell (i, j, k) with i and k in the lower halves of their axes.
ivec3 orbit_origin(int o) { return lattice_coord(ivec3((u_dims.x + 1) / 2, u_dims.y, u_dims.z), o); }
// The coordinates of the orbit's cells: a, its x-mirror, its z-mirror, both.
ivec3 orbit_coord(ivec3 a, int q) {
    return ivec3((q & 1) != 0 ? u_dims.x - 1 - a.x : a.x, a.y, (q & 2) != 0 ? u_dims.z - 1 - a.z : a.z);
}
