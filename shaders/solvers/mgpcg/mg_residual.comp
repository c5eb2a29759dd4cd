// Multigrid, per cell of a level: tmp = r - A e on FLUID cells (0 elsewhere), the residual
// the next coarser level corrects.
// A pair solve (PF_PAIR 1, solver_value.glsl) does both problems: vec2 values.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_R) readonly buffer R { value_t r[]; };
layout(std430, binding = PF_SLOT_MG_E) readonly buffer E { value_t e[]; };
layout(std430, binding = PF_SLOT_MG_TMP) writeonly buffer Tmp { value_t tmp[]; };
#include "solvers/common/poisson.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_dims.w) return;
    value_t res = value_t(0.0);
    if (PF_CELL_KIND(cell_type[c]) == PF_CELL_FLUID) {
        PoissonStencil s = poisson_stencil(c);
        pairs_t pair_sum = pairs_t(0.0);
        for (int n = 0; n < 6; ++n) {
            if (s.nb[n] >= 0) pair_sum[n / 2] += e[s.nb[n]];
        }
        res = r[c] - (s.diag * e[c] - pair_total(pair_sum));
    }
    tmp[c] = res;
}
