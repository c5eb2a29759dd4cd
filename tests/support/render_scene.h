// What the rendering tests need from an engine: a target FBO with colour and depth textures it
// owns, a camera in each depth convention, scene depth written directly per convention, and a
// double-precision CPU model of where each sphere projects and how deep it is.
#pragma once
#include <glad/gl.h>

#include <glm/glm.hpp>
#include <vector>

#include "pf/pf.h"

namespace pf::test {

// The engine's render target: FBO with a colour texture (any colour format) and optionally a
// DEPTH_COMPONENT32F texture, both width x height.
class EngineTarget {
public:
    EngineTarget(int width, int height, GLenum color_format, bool with_depth = true);
    ~EngineTarget();
    EngineTarget(const EngineTarget&) = delete;
    EngineTarget& operator=(const EngineTarget&) = delete;

    // RGBA floats, row-major from the bottom row, width*height*4.
    void write_color(const std::vector<float>& rgba);
    void write_depth(const std::vector<float>& depth);
    std::vector<float> read_color() const;
    std::vector<float> read_depth() const;

    GLuint fbo = 0, color = 0, depth = 0;
    int width, height;
};

// A look-at camera. viewport: x, y, w, h. Projection per convention (reversed-Z maps near to 1).
struct TestCamera {
    glm::dmat4 view, proj;
    pf_camera cam{};
};
TestCamera make_camera(glm::dvec3 eye, glm::dvec3 at, double fovy_deg, const int viewport[4], double near_plane,
                       double far_plane, pf_depth_convention convention);

// Window depth (engine convention) of an eye-space point; eye depth of a window depth at a pixel.
double window_depth_of(const TestCamera& c, const glm::dvec3& eye_point);
double eye_depth_of(const TestCamera& c, double px, double py, double window);
// Window depth of eye depth `depth` on the ray of target pixel (x, y) (centre).
double window_depth_at(const TestCamera& c, int x, int y, double depth);
// The convention's far-plane window depth (what a cleared depth buffer holds).
double far_window_depth(pf_depth_convention convention);

// CPU projection of spheres: per target pixel inside the viewport, the nearest front-hit eye
// depth of the ray through the pixel centre (0: no hit), and whether the ray passes within
// `margin` (fraction of the radius) of a silhouette (ambiguous for a rasteriser).
struct SphereCoverage {
    std::vector<double> depth;     // target-sized, 0 where no sphere
    std::vector<uint8_t> ambiguous;
    int covered = 0;
};
SphereCoverage project_spheres(const TestCamera& c, int target_w, int target_h, const std::vector<float>& xyz,
                               double radius, double margin = 0.01);

// A solid scene colour pattern (checkerboard of two colours plus a gradient), opaque.
std::vector<float> checkerboard(int width, int height, int cell);

}  // namespace pf::test
