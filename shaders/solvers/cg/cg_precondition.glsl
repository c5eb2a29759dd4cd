// The preconditioned residual z = M^-1 r of one FLUID cell, for the CG permutations that
// compute it on the fly: PF_PRECOND 0 (none: z = r) or 1 (Jacobi: z = r / diag). PF_PRECOND 2
// (multigrid) stores z in a buffer instead (cg_zstats.comp).
#define PF_PRECOND_NONE 0
#define PF_PRECOND_JACOBI 1
#define PF_PRECOND_STORED 2

float precondition(float r, PoissonStencil s) {
#if PF_PRECOND == PF_PRECOND_JACOBI
    return s.diag > 0.0 ? r / s.diag : 0.0;
#else
    return r;
#endif
}
