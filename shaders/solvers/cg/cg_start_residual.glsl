// CG's starting residual at FLUID cell c: r = (b - mean) - A x from the warm-started pressure
// x. Shared by cg_init.comp and cg_init_stored.comp. Requires `x` and `rhs` (and poisson.glsl,
// state.glsl) before including this file; a pair kernel (PF_PAIR 1) also x_second and rhs_second
// (problem_values.glsl).
#include "solvers/common/problem_values.glsl"

value_t start_residual(int c, PoissonStencil s) {
    pairs_t pair_sum = pairs_t(0.0);
    for (int n = 0; n < 6; ++n) {
        if (s.nb[n] >= 0) pair_sum[n / 2] += x_at(s.nb[n]);
    }
    return b_at(c) - (s.diag * x_at(c) - pair_total(pair_sum));
}
