/* Words of a solver's state buffer, shared by the solver kernels (GLSL) and their C++ owners
 * (src/sim/solvers/common/convergence.*). One uint array; floats are stored as their bits.
 * Scalars live on the GPU so convergence is decided there: the kernel that tests it rewrites
 * the indirect-dispatch records that follow the scalars to zero workgroups, and every later
 * iteration of that solve dispatches nothing. The CPU never waits for a solve. */
#ifndef PF_SOLVER_STATE_H
#define PF_SOLVER_STATE_H

#define PF_SOLVER_BB 0           /* float: b.b over FLUID cells (after the null-space projection) */
#define PF_SOLVER_B_MEAN 1       /* float: mean of b removed when the system is singular */
#define PF_SOLVER_SINGULAR 2     /* uint: 1 when no cell is AIR (pure Neumann: constants are a null space) */
#define PF_SOLVER_FLUID_CELLS 3  /* uint: FLUID cells of this solve */
#define PF_SOLVER_RZ 4           /* float: r.z of the current Krylov iterate */
#define PF_SOLVER_ARRIVALS 5     /* uint: workgroups of the current reduction pass that have finished (orbit_main.glsl) */
#define PF_SOLVER_ALPHA 6        /* float: CG step length */
#define PF_SOLVER_BETA 7         /* float: CG direction update */
#define PF_SOLVER_Z_MEAN 8       /* float: mean of z removed when singular */
#define PF_SOLVER_ITERATIONS 9   /* uint: iterations done in this solve */
#define PF_SOLVER_CONVERGED 10   /* uint: 1 once the tolerance is met (or the search breaks down) */
#define PF_SOLVER_RESIDUAL 11    /* float: relative residual of the newest check */
#define PF_SOLVER_TOLERANCE 12   /* float: stop when the relative residual is at or below this */
#define PF_SOLVER_PARTIALS 13    /* uint: partial sums written by the cell-wide reduction kernels */
#define PF_SOLVER_RECORDS 14     /* uint: indirect-dispatch records in use */
#define PF_SOLVER_ROUND_START 15 /* uint: ITERATIONS when the current round (of an active-set solve) began */
#define PF_SOLVER_ROUND 16       /* uint: index of the current round (0: the first solve) */
#define PF_SOLVER_FIRST_ROUND 17 /* uint: iterations of round 0, once it is finished */
#define PF_SOLVER_LATER_ROUNDS 18 /* uint: most iterations of a finished later round */
#define PF_SOLVER_NONNEGATIVE 19 /* uint: 1 when this problem asks p >= 0 (its params' separation) */
#define PF_SOLVER_ITERATION_CAP 20 /* uint: a pair's problem stops after this many iterations (else ~0u) */
#define PF_SOLVER_SCALARS 24     /* words before the first indirect record (a multiple of 4) */

/* Indirect-dispatch record k: words PF_SOLVER_SCALARS + 4k .. +2 = workgroups (x, y, z); its
 * full size, restored at the start of every solve, at PF_SOLVER_SCALARS + 4 (PF_SOLVER_MAX_RECORDS + k). */
#define PF_SOLVER_MAX_RECORDS 32
#define PF_SOLVER_WORDS (PF_SOLVER_SCALARS + 8 * PF_SOLVER_MAX_RECORDS)

/* A pair solve (shaders/solvers/common/solver_value.glsl, PF_PAIR 1) keeps its second problem's
 * scalars, words 0 .. PF_SOLVER_SCALARS - 1 as above, after the records; the records are shared. */
#define PF_SOLVER_SECOND PF_SOLVER_WORDS
#define PF_SOLVER_PAIR_WORDS (PF_SOLVER_WORDS + PF_SOLVER_SCALARS)

/* The reduction kernels' workgroup (orbit_main.glsl): PF_WORKGROUP_SIZE invocations, one a mirror
 * orbit of 4 cells, or 4 times as many in the permutations that run one invocation a cell, so
 * that a workgroup still covers PF_WORKGROUP_SIZE orbits and forms the same sums bit for bit (and
 * the last workgroup's adding of up to 512 partials, reduce.glsl's sum_partials, too). */
#if defined(PF_ONE_CELL_AN_INVOCATION) && PF_ONE_CELL_AN_INVOCATION
#define PF_REDUCTION_INVOCATIONS 1024 /* 4 PF_WORKGROUP_SIZE, a literal as GLSL 4.30's layout asks */
#else
#define PF_REDUCTION_INVOCATIONS PF_WORKGROUP_SIZE
#endif

/* Explicit uniform locations of the solver kernels (set by glProgramUniform before each pass). */
#define PF_LOC_SOLVER_DIMS 0     /* ivec4: cells per axis and cell count of the level worked on */
#define PF_LOC_SOLVER_COLOR 1    /* uint: red-black colour (0: i+j+k even) */
#define PF_LOC_SOLVER_OMEGA 2    /* float: relaxation weight */
#define PF_LOC_SOLVER_RECORD 3   /* uint: indirect record a kernel reads or writes */
#define PF_LOC_SOLVER_COUNT 4    /* uint: iterations, sweeps or partial sums, per kernel */
#define PF_LOC_SOLVER_TOLERANCE 5 /* float: relative residual to reach */
#define PF_LOC_SOLVER_ITERATIONS 6 /* uint: iterations done since the previous convergence check */
#define PF_LOC_SOLVER_COARSE_DIMS 7 /* ivec4: the next coarser multigrid level's size */
#define PF_LOC_SOLVER_CG_STEP 8  /* uint: the CG scalar step a z-summing pass runs last (cg_scalar_step.glsl) */
#define PF_LOC_SOLVER_NONNEGATIVE 9 /* uint: begin_solve's copy of the problem's separation */
/* begin_solve's pair permutation: the second problem's tolerance, and each problem's iteration cap */
#define PF_LOC_SOLVER_TOLERANCE_SECOND 10 /* float */
#define PF_LOC_SOLVER_CAP 11     /* uint */
#define PF_LOC_SOLVER_CAP_SECOND 12 /* uint */

/* CG's scalar steps (shaders/solvers/cg/cg_scalar_step.glsl). */
#define PF_CG_STEP_START 0u      /* after the first r and z: residual test, beta = 0 */
#define PF_CG_STEP_ALPHA 1u      /* after p.A p: alpha */
#define PF_CG_STEP_BETA 2u       /* after an update's r and z: residual test, beta */

#endif
