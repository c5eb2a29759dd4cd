// Whether a world position lies inside any sink of the list on PF_SLOT_SINKS; shared by
// sink_mark and sink_lists, which must agree exactly (same positions, same arithmetic).
// Requires common/sim.glsl.
#include "common/shapes.glsl"
#include "effects/sinks/sink_records.h"
layout(std430, binding = PF_SLOT_SINKS) readonly buffer Sinks { vec4 sinks[]; };
layout(location = PF_LOC_EFFECT_COUNT) uniform uint u_sinks;

bool inside_sink(vec3 x) {
    for (uint k = 0u; k < u_sinks; ++k) {
        vec4 ps = sinks[PF_SINK_VEC4S * k];
        vec3 p = quat_rotate_inverse(sinks[PF_SINK_VEC4S * k + 1u], x - ps.xyz);
        vec4 size = sinks[PF_SINK_VEC4S * k + 2u];
        float d = int(ps.w) == PF_SINK_BOX_ID ? box_distance(p, size.xyz) : sphere_distance(p, size.x);
        if (d < 0.0) return true;
    }
    return false;
}
