// Multigrid, per cell of a level too large for mg_up.comp (PF_MG_FUSED_CELLS) and of the fine
// level (whose red half-sweep carries CG's sums, mg_smooth_zstats.comp): the coarse correction
// and the first post-smoothing half-sweep in one pass. With c = P e_coarse (multigrid.glsl's trilinear stencil), out = e + c on red FLUID cells,
// and black FLUID cells take a Gauss-Seidel update from their red neighbours' corrected values,
// out = (r + sum of FLUID neighbours' e + c) / diag, each neighbour's c computed here; cells
// that are not FLUID get 0. The result goes to a second buffer: e is read, never written, so no
// cell sees a neighbour half updated. The arithmetic is that of a prolongation pass followed by
// a black half-sweep (same sums, same order).
// e_coarse is 0 on coarse cells that are not FLUID (every multigrid kernel writes 0 there), so
// no coarse type is read.
// A pair solve (PF_PAIR 1, solver_value.glsl) does both problems: vec2 values.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_R) readonly buffer R { value_t r[]; };
layout(std430, binding = PF_SLOT_MG_E) readonly buffer E { value_t e[]; };
layout(std430, binding = PF_SLOT_MG_TMP) writeonly buffer Out { value_t out_e[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_E) readonly buffer CoarseE { value_t coarse_e[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/mgpcg/multigrid.glsl"

// e + P e_coarse at fine cell f (a FLUID cell) of coordinates fi (passed in: a black cell
// corrects its six neighbours, whose coordinates it knows without dividing).
value_t corrected(int f, ivec3 fi) {
    ivec3 parent = fi >> 1;
    ivec3 other = parent + 2 * (fi & 1) - 1;  // parent - 1 for even, parent + 1 for odd indices
    other = clamp(other, ivec3(0), u_coarse_dims.xyz - 1);
    value_t sum = value_t(0.0);
    for (int n = 0; n < 8; ++n) {
        ivec3 pick = ivec3(n & 1, (n >> 1) & 1, (n >> 2) & 1);
        ivec3 c = parent + pick * (other - parent);
        vec3 w = vec3(0.75) - 0.5 * vec3(pick);
        sum += w.x * w.y * w.z * coarse_e[coarse_index(c)];
    }
    return e[f] + sum;
}

void main() {
    int f = int(flat_id());
    if (f >= u_dims.w) return;
    value_t v = value_t(0.0);
    if (PF_CELL_KIND(cell_type[f]) == PF_CELL_FLUID) {
        ivec3 fi = level_coord(f);
        if (cell_color_at(fi) == 0u) {
            v = corrected(f, fi);
        } else {
            PoissonStencil s = poisson_stencil_at(f, fi);
            pairs_t pair_sum = pairs_t(0.0);
            for (int n = 0; n < 6; ++n) {
                if (s.nb[n] >= 0) pair_sum[n / 2] += corrected(s.nb[n], fi + kPoissonNeighbours[n]);
            }
            v = s.diag > 0.0 ? (r[f] + pair_total(pair_sum)) / s.diag : value_t(0.0);
        }
    }
    out_e[f] = v;
}
