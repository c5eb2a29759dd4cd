// Multigrid, per coarse cell: r_coarse = (1/2) P^T tmp, gathered from the 4x4x4 fine cells
// whose prolongation stencil reaches it (multigrid.glsl). tmp is the fine residual, 0 on cells
// that are not FLUID, so no fine type is read. The 64 terms are unrolled with their weights
// made per axis first (0 outside the level): the loads are independent and issue together
// (a loop that skipped cells serialised them: ~21 us a pass even on the smallest levels, H100).
// Summed in a fixed order, so the result does not depend on scheduling.
// PF_MG_START 1 also begins the coarse level's V-cycle: its first red half-sweep from zero,
// e = r / diag on red FLUID cells and 0 elsewhere (gauss_seidel.comp's PF_GS_FROM_ZERO),
// which needs nothing but this cell's r — one pass less per level.
// A pair solve (PF_PAIR 1, solver_value.glsl) does both problems: vec2 values.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_MG_TMP) readonly buffer Tmp { value_t tmp[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_TYPE) readonly buffer CoarseType { uint coarse_type[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_R) writeonly buffer CoarseR { value_t coarse_r[]; };
#if PF_MG_START
layout(std430, binding = PF_SLOT_MG_COARSE_E) writeonly buffer CoarseE { value_t coarse_e[]; };
#endif
#include "common/slots.h"
#include "common/dispatch.glsl"
#include "solvers/mgpcg/multigrid.glsl"
#include "solvers/common/poisson_neighbours.glsl"

layout(location = PF_LOC_SOLVER_DIMS) uniform ivec4 u_dims;  // the fine level

#include "solvers/mgpcg/restriction.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_coarse_dims.w) return;
    ivec3 cc = lattice_coord(u_coarse_dims.xyz, c);
    value_t r = value_t(0.0);
    bool fluid = PF_CELL_KIND(coarse_type[c]) == PF_CELL_FLUID;
    if (fluid) {
        // Per axis: the fine indices 2 cc - 1 .. 2 cc + 2 (clamped into the level) and weights.
        ivec4 fx, fy, fz;
        vec4 wx, wy, wz;
        for (int d = 0; d < 4; ++d) {
            ivec3 f = 2 * cc + (d - 1);
            bvec3 in_level = bvec3(f.x >= 0 && f.x < u_dims.x, f.y >= 0 && f.y < u_dims.y, f.z >= 0 && f.z < u_dims.z);
            fx[d] = clamp(f.x, 0, u_dims.x - 1);
            fy[d] = clamp(f.y, 0, u_dims.y - 1);
            fz[d] = clamp(f.z, 0, u_dims.z - 1);
            wx[d] = in_level.x ? prolong_weight_1d(f.x, cc.x, u_coarse_dims.x) : 0.0;
            wy[d] = in_level.y ? prolong_weight_1d(f.y, cc.y, u_coarse_dims.y) : 0.0;
            wz[d] = in_level.z ? prolong_weight_1d(f.z, cc.z, u_coarse_dims.z) : 0.0;
        }
        value_t sum = value_t(0.0);
        for (int dz = 0; dz < 4; ++dz) {
            for (int dy = 0; dy < 4; ++dy) {
                float wyz = wz[dz] * wy[dy];
                int row = u_dims.x * (fy[dy] + u_dims.y * fz[dz]);
                for (int dx = 0; dx < 4; ++dx) sum += wyz * wx[dx] * tmp[row + fx[dx]];
            }
        }
        r = restrict_scale() * sum;
    }
    coarse_r[c] = r;
#if PF_MG_START
    bool red = cell_color_at(cc) == 0u;
    float diag = fluid && red ? coarse_diag(cc) : 0.0;
    coarse_e[c] = diag > 0.0 ? r / diag : value_t(0.0);
#endif
}
