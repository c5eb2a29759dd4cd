// Galerkin coarse levels of the multigrid (PF_PRESSURE_SOLVER_MGPCG_GALERKIN): each coarse
// level's operator is the product R A P of the finer one's, stored per cell as a stencil, so the
// coarse problem sees the free surface and the walls as the fine operator does (the geometric
// levels rebuild a Poisson operator from coarsened cell types, which loses them). Level 1 comes
// from the fine level through the trilinear P and R = restrict_scale() P^T (multigrid.glsl): a
// 5^3 stencil whose entries with |o|_1 > 4 are zero. Deeper levels aggregate: P copies a
// parent's value to its 2x2x2 children, R = P^T, and a 5^3 or 3^3 stencil aggregates to 3^3. A
// coarse cell is FLUID (active) if a child is. Smoothing on these levels is damped Jacobi (a
// wide stencil has no two-colouring) and the aggregated correction is scaled up (a piecewise
// constant correction falls short of a smooth error): multigrid_limits.h's
// PF_MG_GALERKIN_OMEGA and _ALPHA. PF_MG_RADIUS: the stencil radius of the level the kernel
// works on (2: level 1, 1: deeper). Stencils are stored coefficient-major: stencil[k * cells +
// c], k the offset's index. Requires u_dims (poisson.glsl) for the level the stencil belongs to.

#include "solvers/mgpcg/multigrid_limits.h"
const float kGalerkinOmega = PF_MG_GALERKIN_OMEGA;
const float kGalerkinAlpha = PF_MG_GALERKIN_ALPHA;

const int kRadius = PF_MG_RADIUS;
const int kSpan = 2 * kRadius + 1;
const int kStencil = kSpan * kSpan * kSpan;
const int kCentre = (kStencil - 1) / 2;

int stencil_slot(ivec3 o) { return (o.x + kRadius) + kSpan * ((o.y + kRadius) + kSpan * (o.z + kRadius)); }
ivec3 stencil_offset_of(int k) { return ivec3(k % kSpan, (k / kSpan) % kSpan, k / (kSpan * kSpan)) - kRadius; }

// The parent of cell q on the next coarser level: halved on the axes that level coarsens.
ivec3 parent_of(ivec3 q, ivec3 coarsened) { return ivec3(q.x >> coarsened.x, q.y >> coarsened.y, q.z >> coarsened.z); }

// Whether offset o's mirror orbit (+-o.x, o.y, +-o.z) can hold nonzero coefficients: level 1's
// entries with |o|_1 > 4 are zero (two of the axes would need a fine face between the supports);
// an aggregated 3^3 stencil uses all 27.
bool orbit_used(ivec3 o) { return kRadius == 1 || o.x + abs(o.y) + o.z <= 4; }
