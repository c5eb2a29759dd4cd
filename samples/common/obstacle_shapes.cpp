#include "obstacle_shapes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace pfs {

std::vector<pf_obstacle> obstacles_as_added(const Scene& scene, const SceneEffectIds& ids) {
    std::vector<pf_obstacle> out = scene.obstacles;
    for (size_t i = 0; i < out.size() && i < ids.obstacle_textures.size(); ++i)
        if (out[i].shape == PF_OBSTACLE_SDF) out[i].sdf_texture = ids.obstacle_textures[i];
    return out;
}

glm::quat obstacle_rotation(const pf_obstacle& o) {
    const glm::quat q(o.rotation[3], o.rotation[0], o.rotation[1], o.rotation[2]); // glm: w first
    const float len = glm::length(q);
    return len > 0.0f ? q / len : glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
}

glm::mat4 obstacle_model_matrix(const pf_obstacle& o) {
    const glm::mat4 translate = glm::translate(glm::mat4(1.0f), glm::vec3(o.position[0], o.position[1], o.position[2]));
    return translate * glm::mat4_cast(obstacle_rotation(o));
}

glm::vec3 obstacle_local_bounds(const pf_obstacle& o) {
    switch (o.shape) {
    case PF_OBSTACLE_SPHERE: return glm::vec3(o.radius);
    case PF_OBSTACLE_CAPSULE: return glm::vec3(o.radius, o.half_height + o.radius, o.radius);
    default: return glm::vec3(o.half_extents[0], o.half_extents[1], o.half_extents[2]);
    }
}

float obstacle_local_distance(const pf_obstacle& o, const glm::vec3& p) {
    switch (o.shape) {
    case PF_OBSTACLE_SPHERE: return glm::length(p) - o.radius;
    case PF_OBSTACLE_CAPSULE: {
        const glm::vec3 axis_point(0.0f, std::clamp(p.y, -o.half_height, o.half_height), 0.0f);
        return glm::length(p - axis_point) - o.radius;
    }
    default: {
        const glm::vec3 q = glm::abs(p) - obstacle_local_bounds(o);
        return glm::length(glm::max(q, glm::vec3(0.0f))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
    }
    }
}

bool ray_box_span(const glm::vec3& origin, const glm::vec3& dir, const glm::vec3& lo, const glm::vec3& hi,
                  float& t_enter, float& t_exit) {
    t_enter = 0.0f;
    t_exit = 1e30f;
    for (int a = 0; a < 3; ++a) {
        if (std::fabs(dir[a]) < 1e-12f) {
            if (origin[a] < lo[a] || origin[a] > hi[a]) return false;
            continue;
        }
        float ta = (lo[a] - origin[a]) / dir[a], tb = (hi[a] - origin[a]) / dir[a];
        if (ta > tb) std::swap(ta, tb);
        t_enter = std::max(t_enter, ta);
        t_exit = std::min(t_exit, tb);
        if (t_enter > t_exit) return false;
    }
    return true;
}

float ray_obstacle(const glm::vec3& origin, const glm::vec3& dir, const pf_obstacle& o) {
    // In the obstacle's frame the shape is axis-aligned and centred; the rotation keeps
    // distances, so t is the same in both frames.
    const glm::quat inv = glm::conjugate(obstacle_rotation(o));
    const glm::vec3 lo = inv * (origin - glm::vec3(o.position[0], o.position[1], o.position[2]));
    const glm::vec3 ld = inv * dir;
    const glm::vec3 bounds = obstacle_local_bounds(o);
    float t = 0.0f, t_exit = 0.0f;
    if (!ray_box_span(lo, ld, -bounds, bounds, t, t_exit)) return -1.0f;
    if (o.shape == PF_OBSTACLE_BOX || o.shape == PF_OBSTACLE_SDF) return t;
    // Sphere tracing: the distance never overshoots the surface; a thousandth of the shape's
    // size is far below a pixel at any useful zoom.
    const float eps = 1e-3f * std::max(bounds.x, bounds.y);
    for (int i = 0; i < 128 && t <= t_exit; ++i) {
        const float d = obstacle_local_distance(o, lo + t * ld);
        if (d < eps) return t;
        t += d;
    }
    return -1.0f;
}

} // namespace pfs
