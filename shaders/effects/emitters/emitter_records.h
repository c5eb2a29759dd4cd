/* Emitter records shared by the C++ host (src/sim/effects/emitters) and the kernels
 * (shaders/effects/emitters). Valid C and GLSL: only #define lines. The shape ids equal the
 * pf_emitter_shape values of pf.h (checked by static_assert). One record is 5 vec4, rewritten
 * every step that emits:
 *   [0] position.xyz, shape id       [1] rotation quaternion (x, y, z, w), unit
 *   [2] box: half extents xyz; sphere, disc: radius, 0, 0; w: unused
 *   [3] velocity.xyz of the new particles, m/s; w: the frame's dt, s (a disc spreads its
 *       particles over the flight of one frame)
 *   [4] x: first new particle of this emitter in the step's emission, y: how many, z: the index
 *       of its first one in the emitter's own sequence (particles it asked for before), mod 2^32
 *       (uint bits) */
#ifndef PF_EMITTER_RECORDS_H
#define PF_EMITTER_RECORDS_H
#define PF_EMITTER_BOX_ID 0
#define PF_EMITTER_SPHERE_ID 1
#define PF_EMITTER_DISC_ID 2
#define PF_EMITTER_VEC4S 5
#endif
