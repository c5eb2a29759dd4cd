// main() of the reduction kernels: runs the kernel's per-cell work,
// sums_t cell_contribution(int c, ivec3 ijk) (the cell's index and coordinates; sums_t is a vec4,
// or a mat2x4 whose columns are summed apart in a kernel of PF_SUMS 2, solver_value.glsl), on every cell and
// adds the results mirror-exactly: each mirror orbit (poisson.glsl) as ((a + b) + (c + d)), then
// the orbits in a fixed order; the workgroup sums go to the partials (reduce.glsl).
// Two mappings, a permutation each (SolveControl picks one by the grid's size), with the same
// workgroups, each PF_WORKGROUP_SIZE orbits, and the same sums bit for bit:
// - one invocation an orbit, doing its four cells in turn;
// - PF_ONE_CELL_AN_INVOCATION 1: four times wider workgroups (PF_REDUCTION_INVOCATIONS), with
//   invocation m + PF_WORKGROUP_SIZE qq doing one cell of orbit m, placed so that the first two
//   levels of the workgroup's tree add the orbit as the first mapping does. The GPU then waits on
//   one cell's loads where it waited on four in turn, which pays where the orbits are few (a 24^3
//   grid's fill 14 workgroups) and costs where they fill the GPU
//   (docs/notes/2026-12-04-reductions-by-grid-size.md).
// With PF_LAST_GROUP defined, the last workgroup to finish (counted with an atomic in the
// state buffer, reset by that workgroup) then adds up all the partials in a fixed order and
// calls the kernel's void last_group_step(sums_t total) in invocation 0: a scalar step without a
// pass of its own. The kernel must declare `partials` coherent (the last workgroup reads what
// the others wrote) and `state`.
// Include after defining cell_contribution (and last_group_step).
#ifndef PF_VALUE_TYPES
#define sums_t vec4
#endif
#ifndef PF_ONE_CELL_AN_INVOCATION
#define PF_ONE_CELL_AN_INVOCATION 0
#endif
#if (PF_ONE_CELL_AN_INVOCATION && PF_REDUCTION_INVOCATIONS != 4 * PF_WORKGROUP_SIZE) || \
    (!PF_ONE_CELL_AN_INVOCATION && PF_REDUCTION_INVOCATIONS != PF_WORKGROUP_SIZE)
#error "a workgroup takes PF_WORKGROUP_SIZE orbits, one invocation an orbit or a cell"
#endif
#ifdef PF_LAST_GROUP
shared bool s_last_group;
#endif

// Cell q of the orbit whose origin is a (0: a, 1: its x mirror, 2: its z mirror, 3: both); 0
// where the cell repeats another (the middle column of an odd axis).
sums_t orbit_member(ivec3 a, int q) {
    ivec3 ijk = orbit_coord(a, q);
    bool repeat = ((q & 1) != 0 && ijk.x == a.x) || ((q & 2) != 0 && ijk.z == a.z);
    return repeat ? sums_t(0.0) : cell_contribution(level_index(ijk), ijk);
}

void main() {
    uint lid = gl_LocalInvocationIndex;
    uint groups = gl_NumWorkGroups.x * gl_NumWorkGroups.y;
    sums_t v = sums_t(0.0);
#if PF_ONE_CELL_AN_INVOCATION
    // The tree's first level adds invocations 2 PF_WORKGROUP_SIZE apart (qq and qq + 2), the
    // second the two pair sums: qq 0, 2 are cells 0, 1 (a, b) and qq 1, 3 cells 2, 3.
    int o = int(workgroup_index() * uint(PF_WORKGROUP_SIZE) + lid % uint(PF_WORKGROUP_SIZE));
    uint qq = lid / uint(PF_WORKGROUP_SIZE);
    if (o < orbit_count()) v = orbit_member(orbit_origin(o), int(((qq & 1u) << 1) | (qq >> 1)));
#else
    int o = int(flat_id());
    if (o < orbit_count()) {
        ivec3 a = orbit_origin(o);
        // A statement a member, not one expression of four calls: a contribution may write
        // (mg_smooth_zstats.comp's in-place half-sweep), and NVIDIA's GL ran the expression
        // slower, and summed wrongly once a contribution read back its own write
        // (docs/notes/2026-12-05-orbit-four-statements.md).
        sums_t m0 = orbit_member(a, 0);
        sums_t m1 = orbit_member(a, 1);
        sums_t m2 = orbit_member(a, 2);
        sums_t m3 = orbit_member(a, 3);
        v = (m0 + m1) + (m2 + m3);
    }
#endif
    store_workgroup_sums(v, groups);
#ifdef PF_LAST_GROUP
    if (gl_LocalInvocationIndex == 0u) {
        memoryBarrierBuffer();  // this workgroup's partial is visible before it is counted
        s_last_group = atomicAdd(state[PF_SOLVER_ARRIVALS], 1u) + 1u == groups;
    }
    barrier();
    if (!s_last_group) return;  // uniform across the workgroup
    memoryBarrierBuffer();
#if defined(PF_SUMS) && PF_SUMS == 2
    mat2x4 sum = sum_partial_columns(groups);
#else
    vec4 sum = sum_partials(groups);
#endif
    if (gl_LocalInvocationIndex == 0u) {
        state[PF_SOLVER_ARRIVALS] = 0u;
        last_group_step(sum);
    }
#endif
}
