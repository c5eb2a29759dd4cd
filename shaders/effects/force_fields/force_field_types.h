/* Force-field records shared by the C++ host (src/sim/effects/force_fields) and the kernel
 * (force_fields.comp). Valid C and GLSL: only #define lines. The type ids equal the
 * pf_force_field_type values of pf.h (checked by static_assert). One record is 3 vec4:
 *   [0] position.xyz, radius        [1] vector.xyz (a vortex axis normalised), strength
 *   [2] type id, drag, 0, 0 */
#ifndef PF_FORCE_FIELD_TYPES_H
#define PF_FORCE_FIELD_TYPES_H
#define PF_FORCE_FIELD_DIRECTIONAL_ID 0
#define PF_FORCE_FIELD_POINT_ID 1
#define PF_FORCE_FIELD_VORTEX_ID 2
#define PF_FORCE_FIELD_VEC4S 3
#endif
