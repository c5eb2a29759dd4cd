// Multigrid setup, per coarse cell: its type from its (up to) 8 fine children. AIR if any
// child is AIR (the free surface is kept: a Dirichlet cell never disappears), else FLUID if
// any child is FLUID, else SOLID (McAdams et al. 2010, §3). Galerkin levels (PF_MG_GALERKIN 1,
// galerkin.glsl): FLUID if any child is FLUID, else AIR if one is, else SOLID.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_TYPE) writeonly buffer CoarseType { uint coarse_type[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/mgpcg/multigrid.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_coarse_dims.w) return;
    ivec3 cc = lattice_coord(u_coarse_dims.xyz, c);
    bool air = false, fluid = false;
    for (int n = 0; n < 8; ++n) {
        ivec3 f = 2 * cc + ivec3(n & 1, (n >> 1) & 1, (n >> 2) & 1);
        if (!level_inside(f)) continue;
        uint t = PF_CELL_KIND(cell_type[level_index(f)]);
        air = air || t == PF_CELL_AIR;
        fluid = fluid || t == PF_CELL_FLUID;
    }
#ifdef PF_MG_GALERKIN
    coarse_type[c] = fluid ? PF_CELL_FLUID : (air ? PF_CELL_AIR : PF_CELL_SOLID);
#else
    coarse_type[c] = air ? PF_CELL_AIR : (fluid ? PF_CELL_FLUID : PF_CELL_SOLID);
#endif
}
