// Sinks, second pass: with n live particles of which `removed` are inside a sink, the survivors
// must end in slots [0, n - removed). Removed particles below that bound leave holes; kept
// particles at or above it must move down. Both lists have the same length (each hole below
// the bound is matched by a survivor above it), so sink_move pairs them up one to one.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_SINK_STATE) buffer State { uint state[]; };
layout(std430, binding = PF_SLOT_SINK_HOLES) writeonly buffer Holes { uint holes[]; };
layout(std430, binding = PF_SLOT_SINK_MOVERS) writeonly buffer Movers { uint movers[]; };
#include "effects/sinks/sink_inside.glsl"

void main() {
    uint i = flat_id();
    uint n = sim.particle_count;
    if (i >= n) return;
    uint after = n - state[PF_SINK_REMOVED];
    bool inside = inside_sink(pos[i].xyz);
    if (i < after && inside) holes[atomicAdd(state[PF_SINK_HOLES], 1u)] = i;
    if (i >= after && !inside) movers[atomicAdd(state[PF_SINK_MOVERS], 1u)] = i;
}
