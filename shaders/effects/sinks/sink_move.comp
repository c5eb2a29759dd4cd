// Sinks, third pass: invocation k moves survivor movers[k] into hole holes[k] (position,
// velocity and, under APIC, the affine vectors), and invocation 0 writes the new live count
// into both draw records. The pairing follows the order the atomics landed in, so the order
// of the survivors may differ between runs; the set of particles does not.
#include "common/sim.glsl"
#include "effects/sinks/sink_records.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_SINK_STATE) readonly buffer State { uint state[]; };
layout(std430, binding = PF_SLOT_SINK_HOLES) readonly buffer Holes { uint holes[]; };
layout(std430, binding = PF_SLOT_SINK_MOVERS) readonly buffer Movers { uint movers[]; };
layout(std430, binding = PF_SLOT_PARTICLE_COUNT) buffer Count { uint count_record[]; };
#if PF_APIC
layout(std430, binding = PF_SLOT_PARTICLE_AFFINE) buffer Affine { vec4 affine[]; };
#endif

void main() {
    uint k = flat_id();
    if (k == 0u) {
        uint after = sim.particle_count - state[PF_SINK_REMOVED];
        count_record[PF_COUNT_LIVE] = after;
        count_record[PF_COUNT_INSTANCES] = after;
    }
    if (k >= state[PF_SINK_HOLES]) return;
    uint from = movers[k], to = holes[k];
    pos[to] = pos[from];
    vel[to] = vel[from];
#if PF_APIC
    for (uint c = 0u; c < 3u; ++c) affine[3u * to + c] = affine[3u * from + c];
#endif
}
