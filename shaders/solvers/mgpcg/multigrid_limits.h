/* Sizes of the multigrid hierarchy, shared by the coarse-solve kernel and src/sim/solvers/mgpcg. */
#ifndef PF_MULTIGRID_LIMITS_H
#define PF_MULTIGRID_LIMITS_H
#define PF_MG_COARSE_CELLS 1024   /* coarsening stops at a level this small (solved in one workgroup) */
#define PF_MG_COARSE_INVOCATIONS 512 /* the coarse solve's workgroup: two cells each (PF_MG_COARSE_CELLS / 2) */
#define PF_MG_COARSE_SWEEPS 8    /* black-red half-sweep pairs of the coarsest level (after one red) */
#define PF_MG_MAX_LEVELS 12
#define PF_MG_FUSED_CELLS 131072 /* coarse levels up to this size take the fused passes (the fine level never) */
#define PF_MG_DOWN_TILE 4  /* mg_down.comp: coarse cells per tile edge (a fine block of 8^3 and its halo) */
#define PF_MG_UP_TILE 8    /* mg_up.comp: cells per tile edge */
#define PF_MG_TILE_INVOCATIONS 1024 /* the workgroup of mg_down.comp and mg_up.comp, one per tile: its loops over the staged cells are what a pass waits on (docs/notes/2026-12-06-mg-tile-invocations.md) */
#define PF_MG_BOTTOM_INVOCATIONS 1024 /* mg_bottom.comp's one workgroup (GL 4.3's least maximum); >= PF_MG_COARSE_CELLS */
#define PF_MG_BOTTOM_CELLS 4096 /* the level above the coarsest that mg_bottom.comp takes (24 KiB of shared memory) */
/* Galerkin coarse levels (galerkin.glsl): the damped Jacobi smoothing's weight, the aggregated
 * correction's scale, and the coarsest level's forward-backward Gauss-Seidel pairs, as a
 * prototype chose them (docs/notes/2026-12-06-galerkin-coarse-levels.md) */
#define PF_MG_GALERKIN_OMEGA 0.6
#define PF_MG_GALERKIN_ALPHA 1.5
#define PF_MG_GALERKIN_COARSE_PAIRS 4
#endif
