// What the restriction needs besides P's weights (multigrid.glsl), shared by mg_restrict.comp
// and mg_down.comp. Requires u_dims (the fine level), u_coarse_dims, the `coarse_type` buffer
// and kPoissonNeighbours (poisson_neighbours.glsl) to be declared first.

// R's factor 4 / 2^d for the d axes this level coarsens (multigrid.glsl): 1/2 on a 3D grid.
float restrict_scale() {
    ivec3 coarsened = ivec3(lessThan(u_coarse_dims.xyz, u_dims.xyz));
    return 4.0 / float(1 << (coarsened.x + coarsened.y + coarsened.z));
}

// The diagonal of the coarse Poisson operator at cc: in-level neighbours that are not SOLID
// (poisson.glsl's diag over the coarse level, whose words carry no surface term).
float coarse_diag(ivec3 cc) {
    float diag = 0.0;
    for (int n = 0; n < 6; ++n) {
        ivec3 q = cc + kPoissonNeighbours[n];
        if (!coarse_inside(q)) continue;
        if (PF_CELL_KIND(coarse_type[coarse_index(q)]) != PF_CELL_SOLID) diag += 1.0;
    }
    return diag;
}
