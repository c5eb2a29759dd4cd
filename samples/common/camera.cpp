#include "camera.h"

#include "scene.h"
#include "util.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace pfs {

namespace {
constexpr float kMaxPitch = 1.48f; // ~85 degrees
}

void OrbitCamera::look_at(const glm::vec3& e, const glm::vec3& t, float fov) {
    target = t;
    fov_deg = fov;
    const glm::vec3 d = e - t; // target -> eye
    distance = std::max(glm::length(d), 1e-3f);
    pitch = std::asin(std::clamp(d.y / distance, -1.0f, 1.0f));
    yaw = std::atan2(d.x, d.z);
    pitch = std::clamp(pitch, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::set_from_scene(const SceneCamera& c) {
    look_at(glm::vec3(c.eye[0], c.eye[1], c.eye[2]), glm::vec3(c.target[0], c.target[1], c.target[2]), c.fov_deg);
}

glm::vec3 OrbitCamera::eye() const {
    const float cp = std::cos(pitch);
    return target + distance * glm::vec3(cp * std::sin(yaw), std::sin(pitch), cp * std::cos(yaw));
}

glm::vec3 OrbitCamera::forward() const { return glm::normalize(target - eye()); }
glm::vec3 OrbitCamera::right() const { return glm::vec3(std::cos(yaw), 0.0f, -std::sin(yaw)); }
glm::vec3 OrbitCamera::up() const { return glm::normalize(glm::cross(right(), forward())); }

glm::mat4 OrbitCamera::view() const { return glm::lookAt(eye(), target, glm::vec3(0, 1, 0)); }

glm::mat4 OrbitCamera::proj(float aspect) const {
    const float fovy = glm::radians(fov_deg);
    switch (depth) {
    case PF_DEPTH_ZERO_TO_ONE: return glm::perspectiveRH_ZO(fovy, aspect, near_plane, far_plane);
    case PF_DEPTH_REVERSED_Z: return glm::perspectiveRH_ZO(fovy, aspect, far_plane, near_plane); // near->1, far->0
    default: return glm::perspectiveRH_NO(fovy, aspect, near_plane, far_plane);
    }
}

pf_camera OrbitCamera::to_pf(int x, int y, int width, int height) const {
    pf_camera c{};
    const glm::mat4 v = view(), p = proj(float(width) / float(std::max(height, 1)));
    std::memcpy(c.view, glm::value_ptr(v), sizeof c.view);
    std::memcpy(c.proj, glm::value_ptr(p), sizeof c.proj);
    c.viewport[0] = x;
    c.viewport[1] = y;
    c.viewport[2] = width;
    c.viewport[3] = height;
    c.near_plane = near_plane;
    c.far_plane = far_plane;
    c.depth_convention = depth;
    return c;
}

void OrbitCamera::ray(double px, double py, int width, int height, glm::vec3& origin, glm::vec3& dir) const {
    const float aspect = float(width) / float(std::max(height, 1));
    const float ndc_x = float(2.0 * (px + 0.5) / width - 1.0);
    const float ndc_y = float(1.0 - 2.0 * (py + 0.5) / height);
    const float t = std::tan(0.5f * glm::radians(fov_deg));
    origin = eye();
    dir = glm::normalize(forward() + right() * (ndc_x * t * aspect) + up() * (ndc_y * t));
}

bool OrbitCamera::window_position(const glm::vec3& p, int width, int height, glm::vec2& pixel,
                                  float& view_depth) const {
    const glm::vec3 d = p - eye();
    view_depth = glm::dot(d, forward());
    if (view_depth <= 0.0f) return false;
    const float aspect = float(width) / float(std::max(height, 1));
    const float t = std::tan(0.5f * glm::radians(fov_deg));
    const float ndc_x = glm::dot(d, right()) / (view_depth * t * aspect);
    const float ndc_y = glm::dot(d, up()) / (view_depth * t);
    pixel.x = 0.5f * (ndc_x + 1.0f) * float(width) - 0.5f;
    pixel.y = 0.5f * (1.0f - ndc_y) * float(height) - 0.5f;
    return true;
}

void OrbitCamera::orbit(float dx_px, float dy_px) {
    yaw -= dx_px * 0.006f;
    pitch = std::clamp(pitch + dy_px * 0.006f, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(float dx_px, float dy_px, int viewport_height) {
    const float world_per_px = 2.0f * distance * std::tan(0.5f * glm::radians(fov_deg)) / float(std::max(viewport_height, 1));
    target += (-dx_px * right() + dy_px * up()) * world_per_px;
}

void OrbitCamera::zoom(float factor) { distance = std::clamp(distance * factor, 0.05f, 0.5f * far_plane); }

const char* depth_convention_name(pf_depth_convention d) {
    switch (d) {
    case PF_DEPTH_ZERO_TO_ONE: return "zero_to_one";
    case PF_DEPTH_REVERSED_Z: return "reversed_z";
    default: return "standard";
    }
}

} // namespace pfs
