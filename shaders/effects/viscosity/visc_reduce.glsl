// The viscosity solve's sums (shaders/effects/viscosity/visc_apply.comp, visc_update.comp): each
// workgroup stores its partial sum (solvers/common/reduce.glsl, a fixed order, so reruns give
// the same bits), and the last workgroup to finish adds them all up and takes CG's scalar step
// itself, without a pass of its own. Requires `partials` (coherent vec4[]) and `state` (uint[]),
// and reduce.glsl included.
shared bool s_last_group;

// Every invocation calls this (no early return before it). True in the last workgroup to
// finish, whose invocations then all get the total in `sum`.
bool visc_reduce(vec4 v, out vec4 sum) {
    sum = vec4(0.0);
    store_workgroup_sum(v);
    uint groups = gl_NumWorkGroups.x * gl_NumWorkGroups.y;
    if (gl_LocalInvocationIndex == 0u) {
        memoryBarrierBuffer();  // this workgroup's partial is visible before it is counted
        s_last_group = atomicAdd(state[PF_VISC_ARRIVALS], 1u) + 1u == groups;
    }
    barrier();
    if (!s_last_group) return false;  // uniform across the workgroup
    memoryBarrierBuffer();
    sum = sum_partials(groups);
    if (gl_LocalInvocationIndex == 0u) state[PF_VISC_ARRIVALS] = 0u;
    return true;
}

float visc_state_float(int word) { return uintBitsToFloat(state[word]); }
void visc_set_state_float(int word, float v) { state[word] = floatBitsToUint(v); }

// Ends the solve: every later pass of it (indirect) dispatches no workgroups.
void visc_stop() {
    state[PF_VISC_CONVERGED] = 1u;
    state[PF_VISC_FACE_RECORD] = 0u;
    state[PF_VISC_NODE_RECORD] = 0u;
}
