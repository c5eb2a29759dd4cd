// main() of the reduction kernels: one invocation per mirror orbit (poisson.glsl) runs the
// kernel's per-cell work, vec4 cell_contribution(int c), on the orbit's cells and adds the
// results mirror-exactly; the workgroup sums go to the partials (reduce.glsl).
// Include after defining cell_contribution.
void main() {
    int o = int(flat_id());
    vec4 total = vec4(0.0);
    if (o < orbit_count()) {
        ivec4 cells = orbit_cells(o);
        vec4 v[4];
        for (int q = 0; q < 4; ++q) v[q] = cells[q] >= 0 ? cell_contribution(cells[q]) : vec4(0.0);
        total = (v[0] + v[1]) + (v[2] + v[3]);
    }
    store_workgroup_sum(total);
}
