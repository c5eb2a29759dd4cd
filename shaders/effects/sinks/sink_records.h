/* Sink records shared by the C++ host (src/sim/effects/sinks) and the kernels
 * (shaders/effects/sinks). Valid C and GLSL: only #define lines. The shape ids equal the
 * pf_sink_shape values of pf.h (checked by static_assert). One record is 3 vec4:
 *   [0] position.xyz, shape id   [1] rotation quaternion (x, y, z, w), unit
 *   [2] box: half extents xyz; sphere: radius, 0, 0
 * The compaction counters (PF_SLOT_SINK_STATE), zeroed by the host before each step's passes: */
#ifndef PF_SINK_RECORDS_H
#define PF_SINK_RECORDS_H
#define PF_SINK_BOX_ID 0
#define PF_SINK_SPHERE_ID 1
#define PF_SINK_VEC4S 3
#define PF_SINK_REMOVED 0   /* particles inside a sink */
#define PF_SINK_HOLES 1     /* removed particles below the new count (slots to fill) */
#define PF_SINK_MOVERS 2    /* kept particles at or above the new count (to move down) */
#define PF_SINK_STATE_WORDS 4
#endif
