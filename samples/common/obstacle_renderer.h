// Draws pflip's obstacles into the samples' world as shaded solids with depth, so the liquid
// pflip renders over the world's colour and depth is hidden behind them and refracts them.
//
// Each obstacle is drawn as the local box that holds its shape (obstacle_shapes.h); a fragment
// shader casts the eye ray through the box in the obstacle's frame and finds the surface: the
// box itself, a sphere or capsule by sphere tracing their exact distances, or for
// PF_OBSTACLE_SDF by sphere tracing the engine's own 3D texture the way the library reads it
// (texture coordinate p / (2 half_extents) + 0.5, distance = texel * sdf_scale, normalised
// formats 2 texel - 1). It writes gl_FragDepth of the hit in the camera's depth convention and
// discards rays that miss. Uses the samples' own GL (pf_glad_app).
#pragma once

#include <glad/gl.h>

#include <pf/pf.h>

#include <glm/glm.hpp>

#include <vector>

namespace pfs {

/// Where the obstacles are drawn from: the camera's matrices and conventions.
struct ObstacleView {
    glm::mat4 view_proj{1.0f};
    glm::vec3 eye{0.0f};
    glm::vec3 sun{0.0f, 1.0f, 0.0f};  ///< towards the sun, normalised
    bool zero_to_one = false;         ///< NDC z in [0, 1] (glClipControl) rather than [-1, 1]
};

class ObstacleRenderer {
public:
    /// Needs the GL context current and GLAD loaded.
    ObstacleRenderer();
    ~ObstacleRenderer();
    ObstacleRenderer(const ObstacleRenderer&) = delete;
    ObstacleRenderer& operator=(const ObstacleRenderer&) = delete;

    /// Draws every obstacle into the bound framebuffer; the caller has set the viewport, the
    /// depth test and its function. Leaves face culling off and no program bound.
    void draw(const std::vector<pf_obstacle>& obstacles, const ObstacleView& view) const;

private:
    void draw_one(const pf_obstacle& o, const ObstacleView& view) const;
    void bind_sdf_texture(const pf_obstacle& o) const;

    GLuint program_ = 0;
    GLuint vao_ = 0;       // empty: the box corners come from gl_VertexID
    GLuint sampler_ = 0;   // linear, clamped: the library's reading of an SDF texture
};

} // namespace pfs
