// How smooth a rendered liquid surface is: the angle between the surface normal that the
// rendered depth implies and the true normal (for a resting pool, straight up), over the liquid's
// pixels; and the resting pool and camera it is measured on. Shared by pf_surface_bench
// (docs/rendering.md's bounds) and the engine tests. No GL: it reads a depth image the caller
// read back.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <pf/pf.h>

namespace pfs {

struct NormalError {
    double rms_deg = 0.0;  // RMS angle to the true normal (normal_roughness: the local mean) over the measured pixels
    double p95_deg = 0.0;  // 95th percentile of the angle
    int pixels = 0;        // pixels measured
};

// `window_depth`: the target's depth (engine convention, row-major from the bottom row,
// width*height values), `liquid`: which pixels hold liquid. Normals are formed as the shading
// forms them (shaders/render/liquid_surface/ssf_shade.glsl: of the two one-sided differences per
// axis, the one with the smaller depth step), in world space through `view`, and turned towards
// the camera. Measured are the pixels whose (2 border + 1)^2 neighbourhood is all liquid, so a
// silhouette is not taken for a bump; `true_normal` is a world direction.
// The resting pool: a cube of `box` metres in `cells`^3 cells, liquid up to kPoolDepth of it
// (8 particles a cell: 13k particles at 16^3, 105k at 32^3, 1.19M at 72^3, 9.6M at 144^3).
constexpr double kPoolDepth = 0.4;
pf_sim_desc pool_desc(uint32_t cells, float box);

// The camera that measures it: 45 degrees above the pool's centre, 30 degrees of vertical field
// of view, so at 16:9 only the inside of the liquid's top surface is seen; the standard depth
// convention, near 0.1 m, far 10 m.
pf_camera pool_camera(float box, int width, int height, glm::dmat4& view, glm::dmat4& proj);

// The dam break the roughness is measured on: a 2 x 1 x 1 m tank in `cells` x cells/2 x cells/2
// cells, a kDamBreakColumn column against the x = 0 wall at 8 particles a cell (18k particles at
// 32 cells, 62k at 48, 1.2M at 128, 9.4M at 256), kDamBreakFrames frames of 1/60 s after the
// release: the column falling, its front running along the floor.
constexpr float kDamBreakColumn[3] = {0.75f, 0.75f, 1.0f};
constexpr int kDamBreakFrames = 30;
pf_sim_desc dam_break_desc(uint32_t cells);
// Its camera: from the front and above the tank, 40 degrees of vertical field of view.
pf_camera dam_break_camera(int width, int height, glm::dmat4& view, glm::dmat4& proj);
// The roughness window of a width-pixel image: width / 64 pixels.
inline int roughness_window(int width) { return width / 64; }

NormalError normal_error(const std::vector<float>& window_depth, const std::vector<uint8_t>& liquid, int width,
                         int height, const glm::dmat4& view, const glm::dmat4& proj, pf_depth_convention convention,
                         glm::dvec3 true_normal, int border);

// For a surface with no one true normal (a dam break): the angle between each measured pixel's
// normal and the mean of the measured normals within `window` pixels of it (a square of 2 window
// + 1) — the normal map's energy at scales below the window, what crinkles a curved surface. A
// smooth curve turns little within a window; particle-sized bumps turn the normal by tens of
// degrees from pixel to pixel.
NormalError normal_roughness(const std::vector<float>& window_depth, const std::vector<uint8_t>& liquid, int width,
                             int height, const glm::dmat4& view, const glm::dmat4& proj, pf_depth_convention convention,
                             int border, int window);

}  // namespace pfs
