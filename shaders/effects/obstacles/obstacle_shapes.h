/* Obstacle records shared by the C++ host (src/sim/effects/obstacles) and the kernels
 * (shaders/effects/obstacles). Valid C and GLSL: only #define lines. The shape ids equal the
 * pf_obstacle_shape values of pf.h (checked by static_assert). One record is 5 vec4:
 *   [0] position.xyz, shape id      [1] rotation quaternion (x, y, z, w), unit
 *   [2] box: half extents xyz; sphere: radius, 0, 0; capsule: radius, half height, 0;
 *       SDF: half extents xyz of the box the texture covers, metres per texture unit
 *   [3] linear velocity.xyz of the centre, m/s; w: SDF texture normalised (1: distance = 2 t - 1)
 *   [4] angular velocity.xyz about it, rad/s
 *   (the surface point x moves at v + w x (x - position); 0 for static obstacles)
 * The force buffer (obstacle_forces.comp) holds PF_OBSTACLE_FORCE_WORDS floats per obstacle
 * slot: force.xyz, 0, torque.xyz, 0 (N, N m). */
#ifndef PF_OBSTACLE_SHAPES_H
#define PF_OBSTACLE_SHAPES_H
#define PF_OBSTACLE_BOX_ID 0
#define PF_OBSTACLE_SPHERE_ID 1
#define PF_OBSTACLE_CAPSULE_ID 2
#define PF_OBSTACLE_SDF_ID 3
/* SDF obstacles: record k's texture is bound to texture unit PF_TEX_UNIT_SDF + k */
#define PF_TEX_UNIT_SDF 0
#define PF_OBSTACLE_VEC4S 5
/* equals PF_MAX_OBSTACLES (checked by static_assert) */
#define PF_OBSTACLE_MAX 16
#define PF_OBSTACLE_FORCE_WORDS 8
/* particles are pushed out to this distance outside the surface, in cells */
#define PF_OBSTACLE_PUSH_MARGIN 0.01
#endif
