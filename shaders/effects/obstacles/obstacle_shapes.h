/* Obstacle records shared by the C++ host (src/sim/effects/obstacles) and the kernels
 * (shaders/effects/obstacles). Valid C and GLSL: only #define lines. The shape ids equal the
 * pf_obstacle_shape values of pf.h (checked by static_assert). One record is 4 vec4:
 *   [0] position.xyz, shape id      [1] rotation quaternion (x, y, z, w), unit
 *   [2] box: half extents xyz; sphere: radius, 0, 0; capsule: radius, half height, 0
 *   [3] velocity.xyz of the obstacle's surface, m/s: 0 for static obstacles (the solid faces
 *       take its normal component, so moving obstacles only have to fill it) */
#ifndef PF_OBSTACLE_SHAPES_H
#define PF_OBSTACLE_SHAPES_H
#define PF_OBSTACLE_BOX_ID 0
#define PF_OBSTACLE_SPHERE_ID 1
#define PF_OBSTACLE_CAPSULE_ID 2
#define PF_OBSTACLE_VEC4S 4
/* particles are pushed out to this distance outside the surface, in cells */
#define PF_OBSTACLE_PUSH_MARGIN 0.01
#endif
