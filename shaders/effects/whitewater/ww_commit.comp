// Whitewater (PF_FEATURE_WHITEWATER), fourth pass, one invocation: the step's output count
// (survivors plus new particles, capped at the capacity) becomes the live count in both draw
// records, the per-particle dispatch record and the status word PF_STATUS_WHITEWATER_COUNT, and
// the next step's output count starts at 0. A separate dispatch because every emit invocation
// reads the running count.
#include "common/sim.glsl"
layout(local_size_x = 1) in;
layout(std430, binding = PF_SLOT_WW_STATE) buffer State { uint state[]; };
layout(std430, binding = PF_SLOT_WW_STATUS) buffer Status { uint status[]; };
layout(location = PF_LOC_WW_CAPACITY) uniform uint u_capacity;

void main() {
    uint live = min(state[PF_WW_NEXT], u_capacity);
    state[PF_WW_LIVE] = live;
    state[PF_WW_LIVE + 1] = 1u;
    state[PF_WW_LIVE + 2] = 0u;
    state[PF_WW_LIVE + 3] = 0u;
    state[PF_WW_STRIP_RECORD] = 4u;
    state[PF_WW_INSTANCES] = live;
    state[PF_WW_STRIP_RECORD + 2] = 0u;
    state[PF_WW_STRIP_RECORD + 3] = 0u;
    state[PF_WW_NEXT] = 0u;
    state[PF_WW_GROUPS] = (live + uint(PF_WORKGROUP_SIZE) - 1u) / uint(PF_WORKGROUP_SIZE);
    state[PF_WW_GROUPS + 1] = 1u;
    state[PF_WW_GROUPS + 2] = 1u;
    status[PF_STATUS_WHITEWATER_COUNT] = live;
}
