// Multigrid setup (Galerkin levels), per coefficient of level 1's stencils: A1 = s P^T A P with
// the fine operator A (poisson.glsl, ghost-fluid diagonal included), the trilinear P and R's
// scale s (multigrid.glsl). Invocation k * cells + c computes entry (c, c + o_k):
//   s * sum over FLUID fine f of P(f, c) (diag_f P(f, c') - sum over FLUID neighbours g P(g, c')),
// f running over the fine cells P(., c) reaches that are within one cell of those P(., c')
// reaches (none where |o|_1 > 4: galerkin.glsl's orbit_used). Every term is a multiple of 2^-28
// (weights in quarters, the surface diagonal in 1/65536) well inside double precision, so the sum
// is exact whatever its order: the stencils are exactly symmetric and mirror-exact. Entries of a
// coarse cell that is not FLUID, or toward one, are 0.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_TYPE) readonly buffer CoarseType { uint coarse_type[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_STENCIL) writeonly buffer CoarseLevelStencil { float coarse_stencil[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/mgpcg/multigrid.glsl"
#include "solvers/mgpcg/restriction.glsl"
#include "solvers/mgpcg/galerkin.glsl"

// P's weight of coarse cell c at fine cell f (both inside their levels).
float prolong_weight(ivec3 f, ivec3 c) {
    return prolong_weight_1d(f.x, c.x, u_coarse_dims.x) * prolong_weight_1d(f.y, c.y, u_coarse_dims.y) *
           prolong_weight_1d(f.z, c.z, u_coarse_dims.z);
}

bool coarse_fluid(ivec3 c) { return coarse_inside(c) && PF_CELL_KIND(coarse_type[coarse_index(c)]) == PF_CELL_FLUID; }

void main() {
    int id = int(flat_id());
    int cells = u_coarse_dims.w;
    if (id >= cells * kStencil) return;
    int k = id / cells;
    int c = id - k * cells;
    ivec3 cc = lattice_coord(u_coarse_dims.xyz, c);
    ivec3 o = stencil_offset_of(k);
    ivec3 cn = cc + o;
    double sum = 0.0;
    if (orbit_used(abs(o)) && coarse_fluid(cc) && coarse_fluid(cn)) {
        ivec3 lo = max(max(2 * cc - 1, 2 * cn - 2), ivec3(0));
        ivec3 hi = min(min(2 * cc + 2, 2 * cn + 3), u_dims.xyz - 1);
        for (int z = lo.z; z <= hi.z; ++z) {
            for (int y = lo.y; y <= hi.y; ++y) {
                for (int x = lo.x; x <= hi.x; ++x) {
                    ivec3 f = ivec3(x, y, z);
                    int fi = level_index(f);
                    if (PF_CELL_KIND(cell_type[fi]) != PF_CELL_FLUID) continue;
                    float wc = prolong_weight(f, cc);
                    if (wc == 0.0) continue;
                    PoissonStencil s = poisson_stencil_at(fi, f);
                    double t = double(s.diag) * double(prolong_weight(f, cn));
                    for (int n = 0; n < 6; ++n) {
                        if (s.nb[n] >= 0) t -= double(prolong_weight(f + kPoissonNeighbours[n], cn));
                    }
                    sum += double(wc) * t;
                }
            }
        }
    }
    coarse_stencil[id] = float(double(restrict_scale()) * sum);
}
