// Multigrid setup (Galerkin levels), per coefficient of the stencils of a level
// below level 1: A_coarse = P^T A P with the aggregation P (galerkin.glsl), from the finer level's
// stencils of radius PF_MG_RADIUS. Invocation K * coarse cells + C computes entry (C, C + O_K), a
// 3^3 stencil: the sum of A(c, o) over the children c of C and the offsets o whose cell c + o has
// the parent C + O_K. Summed in double: the float entries span far fewer than double's 53 bits,
// so the sum is exact in practice and the stencils stay symmetric and mirror-exact. Children that
// are not FLUID have zero stencils (mg_galerkin_first.comp, this kernel), as have entries toward
// them.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };  // poisson.glsl asks for it
layout(std430, binding = PF_SLOT_MG_STENCIL) readonly buffer LevelStencil { float stencil[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_STENCIL) writeonly buffer CoarseLevelStencil { float coarse_stencil[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/mgpcg/multigrid.glsl"
#include "solvers/mgpcg/galerkin.glsl"

void main() {
    int id = int(flat_id());
    int coarse_cells = u_coarse_dims.w;
    if (id >= coarse_cells * 27) return;
    int k = id / coarse_cells;
    int C = id - k * coarse_cells;
    ivec3 cc = lattice_coord(u_coarse_dims.xyz, C);
    ivec3 target = cc + ivec3(k % 3, (k / 3) % 3, k / 9) - 1;
    ivec3 coarsened = ivec3(lessThan(u_coarse_dims.xyz, u_dims.xyz));
    double sum = 0.0;
    if (coarse_inside(target)) {
        for (int dz = 0; dz <= coarsened.z; ++dz) {
            for (int dy = 0; dy <= coarsened.y; ++dy) {
                for (int dx = 0; dx <= coarsened.x; ++dx) {
                    ivec3 child = (cc << coarsened) + ivec3(dx, dy, dz);
                    if (!level_inside(child)) continue;
                    int ci = level_index(child);
                    for (int j = 0; j < kStencil; ++j) {
                        ivec3 q = child + stencil_offset_of(j);
                        if (!level_inside(q) || parent_of(q, coarsened) != target) continue;
                        sum += double(stencil[j * u_dims.w + ci]);
                    }
                }
            }
        }
    }
    coarse_stencil[id] = float(sum);
}
