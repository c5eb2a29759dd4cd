// The samples' view of a pf_obstacle's geometry, on the CPU: its local frame (the library's
// quaternion convention: x, y, z, w, all zeros meaning the identity), the local box that holds
// its shape, and a ray intersection for picking it with the mouse. The obstacle renderer
// (obstacle_renderer.h) draws the same shapes on the GPU; both follow the library's signed
// distances (shaders/effects/obstacles/obstacle_sdf.glsl), so what is drawn and picked is what
// the liquid meets.
#pragma once

#include <pf/pf.h>

#include "scene.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace pfs {

/// The scene's obstacles as add_scene_effects gave them to the library: SDF ones carry the
/// texture it uploaded (the parsed scene has none), so they can be drawn and set again.
std::vector<pf_obstacle> obstacles_as_added(const Scene& scene, const SceneEffectIds& ids);

/// The obstacle's orientation, normalised; the identity for (0, 0, 0, 0).
glm::quat obstacle_rotation(const pf_obstacle& o);

/// Local -> world: rotation, then translation to the obstacle's position.
glm::mat4 obstacle_model_matrix(const pf_obstacle& o);

/// Half sizes of the local axis-aligned box around the shape (box and SDF: half_extents;
/// sphere: radius; capsule: radius across, half_height + radius along y).
glm::vec3 obstacle_local_bounds(const pf_obstacle& o);

/// Signed distance (m, negative inside) of the analytic shapes at local point p; an SDF
/// obstacle counts as its box here (its texture lives on the GPU).
float obstacle_local_distance(const pf_obstacle& o, const glm::vec3& p);

/// Distance along the ray (origin, unit dir; world space) to the obstacle's surface, or -1 if
/// the ray misses it. Exact for boxes, sphere-traced for spheres and capsules; an SDF obstacle
/// is picked by its box.
float ray_obstacle(const glm::vec3& origin, const glm::vec3& dir, const pf_obstacle& o);

/// Ray / axis-aligned box [lo, hi]: entry and exit distances (entry clamped to >= 0); false
/// when the ray misses.
bool ray_box_span(const glm::vec3& origin, const glm::vec3& dir, const glm::vec3& lo, const glm::vec3& hi,
                  float& t_enter, float& t_exit);

} // namespace pfs
