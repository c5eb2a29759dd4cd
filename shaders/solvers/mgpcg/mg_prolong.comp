// Multigrid, per fine cell: e += P e_coarse on FLUID cells, from the 8 coarse cells of its
// trilinear stencil (multigrid.glsl); non-FLUID coarse cells contribute 0.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_E) buffer E { float e[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_TYPE) readonly buffer CoarseType { uint coarse_type[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_E) readonly buffer CoarseE { float coarse_e[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/mgpcg/multigrid.glsl"

void main() {
    int f = int(flat_id());
    if (f >= u_dims.w || cell_type[f] != PF_CELL_FLUID) return;
    ivec3 fi = level_coord(f);
    ivec3 parent = fi >> 1;
    ivec3 other = parent + 2 * (fi & 1) - 1;  // parent - 1 for even, parent + 1 for odd indices
    other = clamp(other, ivec3(0), u_coarse_dims.xyz - 1);
    float sum = 0.0;
    for (int n = 0; n < 8; ++n) {
        ivec3 pick = ivec3(n & 1, (n >> 1) & 1, (n >> 2) & 1);
        ivec3 c = parent + pick * (other - parent);
        vec3 w = vec3(0.75) - 0.5 * vec3(pick);
        int ci = coarse_index(c);
        if (coarse_type[ci] == PF_CELL_FLUID) sum += w.x * w.y * w.z * coarse_e[ci];
    }
    e[f] += sum;
}
