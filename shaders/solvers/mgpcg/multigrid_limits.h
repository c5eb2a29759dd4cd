/* Sizes of the multigrid hierarchy, shared by the coarse-solve kernel and src/sim/solvers/mgpcg. */
#ifndef PF_MULTIGRID_LIMITS_H
#define PF_MULTIGRID_LIMITS_H
#define PF_MG_COARSE_CELLS 1024   /* coarsening stops at a level this small (solved in one workgroup) */
#define PF_MG_COARSE_INVOCATIONS 512 /* the coarse solve's workgroup: two cells each (PF_MG_COARSE_CELLS / 2) */
#define PF_MG_COARSE_SWEEPS 8    /* black-red half-sweep pairs of the coarsest level (after one red) */
#define PF_MG_MAX_LEVELS 12
#endif
