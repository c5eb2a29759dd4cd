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
    double rms_deg = 0.0;  // RMS angle to the true normal over the measured pixels
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

NormalError normal_error(const std::vector<float>& window_depth, const std::vector<uint8_t>& liquid, int width,
                         int height, const glm::dmat4& view, const glm::dmat4& proj, pf_depth_convention convention,
                         glm::dvec3 true_normal, int border);

}  // namespace pfs
