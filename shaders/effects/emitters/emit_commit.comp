// Emitters, after emit: one invocation raises the live count by the step's emission, capped at
// the capacity (raising PF_GPU_FLAG_EMITTERS_FULL when the cap cut it), in both draw records.
// A separate dispatch because every emit invocation reads the old count.
#include "common/sim.glsl"
layout(local_size_x = 1) in;
layout(std430, binding = PF_SLOT_PARTICLE_COUNT) buffer Count { uint count_record[]; };
layout(std430, binding = PF_SLOT_STATUS) buffer Status { uint status[]; };
layout(location = PF_LOC_EMIT_TOTAL) uniform uint u_total;
layout(location = PF_LOC_EMIT_CAPACITY) uniform uint u_capacity;

void main() {
    uint live = count_record[PF_COUNT_LIVE];
    uint room = u_capacity - min(live, u_capacity);
    if (u_total > room) atomicOr(status[PF_STATUS_FLAGS], PF_GPU_FLAG_EMITTERS_FULL);
    uint after = live + min(u_total, room);
    count_record[PF_COUNT_LIVE] = after;
    count_record[PF_COUNT_INSTANCES] = after;
}
