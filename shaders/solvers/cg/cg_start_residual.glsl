// CG's starting residual at FLUID cell c: r = (b - mean) - A x from the warm-started pressure
// x. Shared by cg_init.comp and cg_init_stored.comp. Requires `x` and `rhs` (and poisson.glsl,
// state.glsl) before including this file.
float start_residual(int c, PoissonStencil s) {
    vec3 pair_sum = vec3(0.0);
    for (int n = 0; n < 6; ++n) {
        if (s.nb[n] >= 0) pair_sum[n / 2] += x[s.nb[n]];
    }
    return (rhs[c] - rhs_mean()) - (s.diag * x[c] - pair_total(pair_sum));
}
