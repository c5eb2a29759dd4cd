// Orbit camera for the samples: yaw/pitch/distance around a target point, producing the
// view/projection matrices the sample draws with and the pf_camera pflip renders with.
//
// Depth conventions (pf_depth_convention):
//   standard      glm::perspective, NDC z in [-1, 1], depth cleared to 1, GL_LESS
//   zero_to_one   glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), perspectiveRH_ZO, cleared to 1, GL_LESS
//   reversed_z    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), near -> 1, far -> 0, cleared to 0, GL_GREATER
// The last two need GL 4.5 (or ARB_clip_control) and a floating-point depth buffer to pay off.
#pragma once

#include <pf/pf.h>

#include <glm/glm.hpp>

#include <string>

namespace pfs {

struct SceneCamera;

class OrbitCamera {
public:
    glm::vec3 target{0.0f};
    float yaw = 0.0f;        ///< radians, around +y; 0 looks along -z (eye on the +z side)
    float pitch = 0.3f;      ///< radians above the horizon, clamped to about +-85 degrees
    float distance = 3.0f;   ///< eye to target, metres
    float fov_deg = 45.0f;   ///< vertical field of view
    float near_plane = 0.01f, far_plane = 100.0f;
    pf_depth_convention depth = PF_DEPTH_STANDARD;

    /// Places the camera at eye looking at target (yaw/pitch/distance derived from them).
    void look_at(const glm::vec3& eye, const glm::vec3& target, float fov_deg);
    /// look_at from a scene file's camera.
    void set_from_scene(const SceneCamera& c);

    glm::vec3 eye() const;
    glm::vec3 forward() const;   ///< unit, eye -> target
    glm::vec3 right() const;     ///< unit, horizontal
    glm::vec3 up() const;        ///< unit, perpendicular to forward and right
    glm::mat4 view() const;
    glm::mat4 proj(float aspect) const;   ///< in this camera's depth convention

    /// pflip's camera for a viewport of width x height pixels at (x, y).
    pf_camera to_pf(int x, int y, int width, int height) const;

    /// Ray through window pixel (px, py) (origin top-left, as GLFW reports the cursor) of a
    /// width x height window: origin at the eye, unit direction.
    void ray(double px, double py, int width, int height, glm::vec3& origin, glm::vec3& dir) const;
    /// The inverse of ray(): the window pixel (origin top-left) whose ray passes through world
    /// point p, and p's distance along forward(); false when p is not in front of the eye.
    bool window_position(const glm::vec3& p, int width, int height, glm::vec2& pixel, float& view_depth) const;

    /// Mouse helpers: orbit by pixel deltas, pan the target in the view plane, zoom by factor.
    void orbit(float dx_px, float dy_px);
    void pan(float dx_px, float dy_px, int viewport_height);
    void zoom(float factor);

    /// Window depth the depth buffer is cleared to and the depth test function.
    float clear_depth() const { return depth == PF_DEPTH_REVERSED_Z ? 0.0f : 1.0f; }
    bool greater_is_nearer() const { return depth == PF_DEPTH_REVERSED_Z; }
    /// Whether the convention needs glClipControl(.., GL_ZERO_TO_ONE).
    bool zero_to_one() const { return depth != PF_DEPTH_STANDARD; }
};

/// "standard", "zero_to_one", "reversed_z".
const char* depth_convention_name(pf_depth_convention d);

} // namespace pfs
