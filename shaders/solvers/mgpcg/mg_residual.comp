// Multigrid, per cell of a level: tmp = r - A e on FLUID cells (0 elsewhere), the residual
// the next coarser level corrects.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_R) readonly buffer R { float r[]; };
layout(std430, binding = PF_SLOT_MG_E) readonly buffer E { float e[]; };
layout(std430, binding = PF_SLOT_MG_TMP) writeonly buffer Tmp { float tmp[]; };
#include "solvers/common/poisson.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_dims.w) return;
    float res = 0.0;
    if (PF_CELL_KIND(cell_type[c]) == PF_CELL_FLUID) {
        PoissonStencil s = poisson_stencil(c);
        vec3 pair_sum = vec3(0.0);
        for (int n = 0; n < 6; ++n) {
            if (s.nb[n] >= 0) pair_sum[n / 2] += e[s.nb[n]];
        }
        res = r[c] - (s.diag * e[c] - pair_total(pair_sum));
    }
    tmp[c] = res;
}
