// Multigrid, the V-cycle's last pass on the fine grid: the final red half-sweep of the
// post-smoothing on z (in place: red cells read only black neighbours, which this pass does not
// write), and, for CG, the partial sums (r.r, r.z, sum z, sum r) of the resulting z over FLUID
// cells — what cg_zstats.comp would add up in a pass of its own — and CG's scalar step
// u_cg_step in the last workgroup (cg_scalar_step.glsl). One invocation per mirror orbit
// (poisson.glsl), summed as every reduction kernel does (orbit_main.glsl).
// A pair solve (PF_PAIR 1, solver_value.glsl) does both problems, each summed in a column of its own.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#if defined(PF_PAIR) && PF_PAIR
#define PF_SUMS 2
#endif
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_REDUCTION_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_R) readonly buffer R { value_t r[]; };
layout(std430, binding = PF_SLOT_MG_E) buffer Z { value_t z[]; };
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) coherent buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
layout(location = PF_LOC_SOLVER_CG_STEP) uniform uint u_cg_step;  // run by the last workgroup
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"
#include "solvers/cg/cg_scalar_step.glsl"

sums_t cell_contribution(int c, ivec3 ijk) {
    if (PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID) return sums_t(0.0);
    value_t rc = r[c], zc;
    if (cell_color_at(ijk) == 0u) {
        PoissonStencil s = poisson_stencil_at(c, ijk);
        pairs_t pair_sum = pairs_t(0.0);
        for (int n = 0; n < 6; ++n) {
            if (s.nb[n] >= 0) pair_sum[n / 2] += z[s.nb[n]];
        }
        zc = s.diag > 0.0 ? (rc + pair_total(pair_sum)) / s.diag : value_t(0.0);
        z[c] = zc;
    } else {
        zc = z[c];
    }
#if PF_PAIR
    return mat2x4(vec4(rc.x * rc.x, rc.x * zc.x, zc.x, rc.x), vec4(rc.y * rc.y, rc.y * zc.y, zc.y, rc.y));
#else
    return vec4(rc * rc, rc * zc, zc, rc);
#endif
}
void last_group_step(sums_t t) { cg_scalar_step(u_cg_step, t); }
#define PF_LAST_GROUP 1
#include "solvers/common/orbit_main.glsl"
