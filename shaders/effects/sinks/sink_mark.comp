// Sinks, once per step after the last substep, first of three passes (docs/design.md §9.4):
// counts the live particles inside a sink. The live count after removal follows from it.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_SINK_STATE) buffer State { uint state[]; };
#include "effects/sinks/sink_inside.glsl"

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    if (inside_sink(pos[i].xyz)) atomicAdd(state[PF_SINK_REMOVED], 1u);
}
