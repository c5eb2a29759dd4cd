// Conjugate gradients: the new search direction and its product with A in one pass. On FLUID
// cells p = (z - m) + beta p_old, where m is the mean of z removed when the system is singular
// (keeps p out of the null space) and beta = 0 starts afresh (p_old is not read then, so stale
// values cannot leak in); 0 elsewhere. Then q = A p, each neighbour's p formed here from its z
// and p_old, so p goes to a second buffer (CG alternates the two) and no cell sees a neighbour
// half updated; and the partial sums of p.q, whose last workgroup forms alpha
// (cg_scalar_step.glsl). z is r (PF_PRECOND 0), or read from the z buffer: r / diag written by
// init and update (1), or the multigrid's (2).
// A pair solve (PF_PAIR 1, with the multigrid's z) does both problems: vec2 values, and
// (p.q, p'.q', 0, 0) summed.
// Folding the direction update in saves a pass per iteration (on the H100 every pass costs a
// few microseconds whatever its size); the arithmetic is that of the two passes it replaces.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_REDUCTION_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
#if PF_PRECOND == 0
layout(std430, binding = PF_SLOT_SOLVER_R) readonly buffer R { value_t z_in[]; };  // z = r
#else
layout(std430, binding = PF_SLOT_SOLVER_Z) readonly buffer Z { value_t z_in[]; };
#endif
layout(std430, binding = PF_SLOT_SOLVER_P) readonly buffer P { value_t p_old[]; };
layout(std430, binding = PF_SLOT_SOLVER_P_NEXT) writeonly buffer PNext { value_t p_next[]; };
layout(std430, binding = PF_SLOT_SOLVER_Q) writeonly buffer Q { value_t q[]; };
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) coherent buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"
#include "solvers/cg/cg_scalar_step.glsl"

// The new direction at FLUID cell c (a problem of a pair that has stopped takes beta 0: its p
// stays z, which its alpha of 0 leaves unused).
#if PF_PAIR
vec2 direction(int c) {
    vec2 beta = live_state_value(PF_SOLVER_BETA);
    vec2 d = z_in[c] - state_value(PF_SOLVER_Z_MEAN);
    return vec2(beta.x == 0.0 ? d.x : d.x + beta.x * p_old[c].x, beta.y == 0.0 ? d.y : d.y + beta.y * p_old[c].y);
}
#else
float direction(int c) {
    float beta = state_float(PF_SOLVER_BETA);
    float d = z_in[c] - state_float(PF_SOLVER_Z_MEAN);
    return beta == 0.0 ? d : d + beta * p_old[c];
}
#endif

vec4 cell_contribution(int c, ivec3 ijk) {
    value_t pc = value_t(0.0), aq = value_t(0.0);
    if (PF_CELL_KIND(cell_type[c]) == PF_CELL_FLUID) {
        PoissonStencil s = poisson_stencil_at(c, ijk);
        pc = direction(c);
        pairs_t pair_sum = pairs_t(0.0);
        for (int n = 0; n < 6; ++n) {
            if (s.nb[n] >= 0) pair_sum[n / 2] += direction(s.nb[n]);
        }
        aq = s.diag * pc - pair_total(pair_sum);
    }
    p_next[c] = pc;
    q[c] = aq;
#if PF_PAIR
    return vec4(pc.x * aq.x, pc.y * aq.y, 0.0, 0.0);
#else
    return vec4(pc * aq, 0.0, 0.0, 0.0);
#endif
}
void last_group_step(vec4 t) { cg_scalar_step(PF_CG_STEP_ALPHA, t); }
#define PF_LAST_GROUP 1
#include "solvers/common/orbit_main.glsl"
