// Deterministic workgroup sums: every invocation contributes a vec4, the workgroup adds them
// as a fixed binary tree in shared memory, and invocation 0 writes one partial per workgroup.
// A single-workgroup kernel adds the partials in a fixed order (sum_partials). The same input
// therefore always gives the same bits, and no float atomics are needed.
// Requires the kernel to declare `partials` (vec4 per workgroup, two in a kernel of PF_SUMS 2)
// before including this file.
// The workgroup is PF_REDUCTION_INVOCATIONS wide (solver_state.h), PF_WORKGROUP_SIZE by default.
#ifndef PF_REDUCTION_INVOCATIONS
#define PF_REDUCTION_INVOCATIONS PF_WORKGROUP_SIZE
#endif
shared vec4 s_reduce[PF_REDUCTION_INVOCATIONS];

// Every invocation of the workgroup must call this (no early return before it). The partial
// goes to partials[offset + the workgroup's index].
void store_workgroup_sum_at(vec4 v, uint offset) {
    uint lid = gl_LocalInvocationIndex;
    s_reduce[lid] = v;
    barrier();
    for (uint stride = uint(PF_REDUCTION_INVOCATIONS) / 2u; stride > 0u; stride >>= 1u) {
        if (lid < stride) s_reduce[lid] += s_reduce[lid + stride];
        barrier();
    }
    if (lid == 0u) partials[offset + gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x] = s_reduce[0];
}
void store_workgroup_sum(vec4 v) { store_workgroup_sum_at(v, 0u); }

// In a single workgroup: the sum of partials[offset, offset + count). Every invocation gets the result.
vec4 sum_partials_at(uint count, uint offset) {
    uint lid = gl_LocalInvocationIndex;
    vec4 v = vec4(0.0);
    for (uint i = lid; i < count; i += uint(PF_REDUCTION_INVOCATIONS)) v += partials[offset + i];
    s_reduce[lid] = v;
    barrier();
    for (uint stride = uint(PF_REDUCTION_INVOCATIONS) / 2u; stride > 0u; stride >>= 1u) {
        if (lid < stride) s_reduce[lid] += s_reduce[lid + stride];
        barrier();
    }
    vec4 total = s_reduce[0];
    barrier();
    return total;
}
vec4 sum_partials(uint count) { return sum_partials_at(count, 0u); }

// A kernel's sums of two columns (PF_SUMS 2, solver_value.glsl) take two partials a workgroup:
// the first columns' at [0, groups), the second's at [groups, 2 groups).
void store_workgroup_sums(mat2x4 v, uint groups) {
    store_workgroup_sum_at(v[0], 0u);
    store_workgroup_sum_at(v[1], groups);
}
void store_workgroup_sums(vec4 v, uint groups) { store_workgroup_sum(v); }
mat2x4 sum_partial_columns(uint count) { return mat2x4(sum_partials_at(count, 0u), sum_partials_at(count, count)); }
