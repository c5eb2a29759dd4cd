// main() of the reduction kernels: one invocation per mirror orbit (poisson.glsl) runs the
// kernel's per-cell work, vec4 cell_contribution(int c, ivec3 ijk) (the cell's index and
// coordinates, known here without dividing), on the orbit's cells and adds the
// results mirror-exactly; the workgroup sums go to the partials (reduce.glsl).
// With PF_LAST_GROUP defined, the last workgroup to finish (counted with an atomic in the
// state buffer, reset by that workgroup) then adds up all the partials in a fixed order and
// calls the kernel's void last_group_step(vec4 total) in invocation 0: a scalar step without a
// pass of its own. The kernel must declare `partials` coherent (the last workgroup reads what
// the others wrote) and `state`.
// Include after defining cell_contribution (and last_group_step).
#ifdef PF_LAST_GROUP
shared bool s_last_group;
#endif

void main() {
    int o = int(flat_id());
    vec4 total = vec4(0.0);
    if (o < orbit_count()) {
        ivec3 a = orbit_origin(o);
        ivec4 cells = orbit_cells(a);
        vec4 v[4];
        for (int q = 0; q < 4; ++q) v[q] = cells[q] >= 0 ? cell_contribution(cells[q], orbit_coord(a, q)) : vec4(0.0);
        total = (v[0] + v[1]) + (v[2] + v[3]);
    }
    store_workgroup_sum(total);
#ifdef PF_LAST_GROUP
    uint groups = gl_NumWorkGroups.x * gl_NumWorkGroups.y;
    if (gl_LocalInvocationIndex == 0u) {
        memoryBarrierBuffer();  // this workgroup's partial is visible before it is counted
        s_last_group = atomicAdd(state[PF_SOLVER_ARRIVALS], 1u) + 1u == groups;
    }
    barrier();
    if (!s_last_group) return;  // uniform across the workgroup
    memoryBarrierBuffer();
    vec4 sum = sum_partials(groups);
    if (gl_LocalInvocationIndex == 0u) {
        state[PF_SOLVER_ARRIVALS] = 0u;
        last_group_step(sum);
    }
#endif
}
