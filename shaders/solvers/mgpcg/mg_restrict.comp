// Multigrid, per coarse cell: r_coarse = (1/2) P^T tmp, gathered from the 4x4x4 fine cells
// whose prolongation stencil reaches it (multigrid.glsl). Summed per axis pair in a fixed
// order, so the result does not depend on scheduling.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_TMP) readonly buffer Tmp { float tmp[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_TYPE) readonly buffer CoarseType { uint coarse_type[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_R) writeonly buffer CoarseR { float coarse_r[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/mgpcg/multigrid.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_coarse_dims.w) return;
    if (coarse_type[c] != PF_CELL_FLUID) {
        coarse_r[c] = 0.0;
        return;
    }
    ivec3 cc = ivec3(c % u_coarse_dims.x, (c / u_coarse_dims.x) % u_coarse_dims.y, c / (u_coarse_dims.x * u_coarse_dims.y));
    float sum = 0.0;
    for (int dz = -1; dz <= 2; ++dz) {
        int fz = 2 * cc.z + dz;
        if (fz < 0 || fz >= u_dims.z) continue;
        float wz = prolong_weight_1d(fz, cc.z, u_coarse_dims.z);
        for (int dy = -1; dy <= 2; ++dy) {
            int fy = 2 * cc.y + dy;
            if (fy < 0 || fy >= u_dims.y) continue;
            float wyz = wz * prolong_weight_1d(fy, cc.y, u_coarse_dims.y);
            for (int dx = -1; dx <= 2; ++dx) {
                int fx = 2 * cc.x + dx;
                if (fx < 0 || fx >= u_dims.x) continue;
                int f = level_index(ivec3(fx, fy, fz));
                if (cell_type[f] != PF_CELL_FLUID) continue;
                sum += wyz * prolong_weight_1d(fx, cc.x, u_coarse_dims.x) * tmp[f];
            }
        }
    }
    coarse_r[c] = 0.5 * sum;
}
