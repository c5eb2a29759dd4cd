// Conjugate gradients: q = A p on FLUID cells (0 elsewhere) and the partial sums of p.q.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_SOLVER_P) readonly buffer P { float p[]; };
layout(std430, binding = PF_SLOT_SOLVER_Q) writeonly buffer Q { float q[]; };
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"

vec4 cell_contribution(int c) {
    float aq = 0.0, pq = 0.0;
    if (cell_type[c] == PF_CELL_FLUID) {
        PoissonStencil s = poisson_stencil(c);
        vec3 pair_sum = vec3(0.0);
        for (int n = 0; n < 6; ++n) {
            if (s.nb[n] >= 0) pair_sum[n / 2] += p[s.nb[n]];
        }
        aq = s.diag * p[c] - pair_total(pair_sum);
        pq = p[c] * aq;
    }
    q[c] = aq;
    return vec4(pq, 0.0, 0.0, 0.0);
}
#include "solvers/common/orbit_main.glsl"
