// Grid transfer of the multigrid preconditioner (McAdams et al. 2010): cell-centred trilinear
// prolongation P and restriction R = P^T / 2, so the V-cycle stays symmetric (CG needs a
// symmetric preconditioner). Per axis, fine cell f takes 3/4 of its parent coarse cell f/2 and
// 1/4 of the parent's other neighbour (f/2 - 1 for even f, f/2 + 1 for odd f); a neighbour
// outside the level is clamped back onto the parent (a zero-gradient wall). Only FLUID cells
// take part on either side: AIR is a zero correction (Dirichlet).
// The factor 1/2 of R: a coarse cell sums weights 8 over its 4x4x4 fine cells, and the coarse
// operator (unscaled, spacing 2h) is 4 times the fine one, so R of a constant is 4 times it.
// An axis of one cell is not coarsened (weight 1, not 2, per axis): with d coarsened axes the
// weights sum to 2^d and the factor is 4 / 2^d (Galerkin: P^T A P is 2^d / 4 times the coarse
// operator), 1 on a flat grid.
layout(location = PF_LOC_SOLVER_COARSE_DIMS) uniform ivec4 u_coarse_dims;

// Weight of coarse index c (of nc) in the prolongation onto fine index f, one axis.
float prolong_weight_1d(int f, int c, int nc) {
    int parent = f >> 1;
    int other = clamp((f & 1) == 0 ? parent - 1 : parent + 1, 0, nc - 1);
    return (parent == c ? 0.75 : 0.0) + (other == c ? 0.25 : 0.0);
}

int coarse_index(ivec3 c) { return lattice_index(u_coarse_dims.xyz, c); }
bool coarse_inside(ivec3 c) { return lattice_inside(u_coarse_dims.xyz, c); }
