// Host mirror of the RenderUniforms std140 block in shaders/common/render.glsl, and how a
// render call's camera and parameters fill it. Only mat4 and 16-byte vectors, so std140
// offsets equal C++ offsets.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "pf/pf.h"

namespace pf {

struct RenderUniforms {
    float view[16];        // world -> eye
    float proj[16];        // eye -> clip (engine convention)
    float inv_proj[16];    // clip -> eye
    float inv_view[16];    // eye -> world
    float viewport[4];     // width, height, 1/width, 1/height
    float planes[4];       // near, far, depth convention, 1 if orthographic
    float sphere[4];       // particle radius, filter radius px, filter depth range m, 1 if scene depth
    float absorption[4];   // rgb per metre, refraction
    float light[4];        // world direction to the sun (unit), specular strength
    float surface[4];      // fresnel f0, shininess, 1 if environment cube map, NDC y sign
    float color_low[4];    // rgb, range[0]
    float color_high[4];   // rgb, range[1]
    int32_t modes[4];      // colour_by, -, -, -
    int32_t target[4];     // viewport x, y, -, -
    float domain_view[16]; // simulation (domain) coordinates -> eye: view * the domain's pose
    float filter[4];       // filter half-width in metres, pixels per metre at eye depth 1 (perspective) or
                           // at any depth (orthographic), -, -
    float whitewater[4];   // sprite radius of foam in metres, opacity at a sprite's centre, -, -
    float liquid[4];       // a particle's liquid volume over its sphere's (thickness scale), -, -, -
    float spray[4];        // spray's radius over a particle's, neighbourhood count below which a particle is
                           // spray, 1 if the cell counts are current, -
    float grid_origin[4];  // simulation grid origin (xyz, simulation coordinates), cell size
    int32_t grid_dims[4];  // simulation grid cells per axis, -
};
static_assert(sizeof(RenderUniforms) == 5 * 64 + 16 * 16, "RenderUniforms must match the std140 block");

// Whether the camera's projection is orthographic (else perspective).
bool camera_orthographic(const pf_camera& camera);
// Pixels a metre spans on screen at eye depth 1 (perspective) or at any depth (orthographic).
float camera_pixels_per_metre(const pf_camera& camera);

// Camera part: matrices (inverses in double precision), viewport, planes. `y_sign` is -1 when
// the engine's clip origin is GL_UPPER_LEFT. The camera must have passed validation (the
// matrices are invertible). `domain_to_world` places the particles (PF_FEATURE_DOMAIN_MOTION;
// the identity otherwise).
void fill_camera(const pf_camera& camera, float y_sign, const glm::mat4& domain_to_world, RenderUniforms& u);
// Liquid look; `params` has its defaults resolved; `has_scene_depth` / `has_environment` say
// which engine textures were given; `particle_volume` (m^3) is the liquid a particle stands for.
void fill_ssf(const pf_ssf_params& params, bool has_scene_depth, bool has_environment, double particle_volume,
              RenderUniforms& u);
// The spray test's part: the simulation's grid, its rest count and whether its counts are current.
void fill_spray(float spray_radius_scale, const float origin[3], float cell_size, const int32_t dims[3],
                float rest_count, bool counts_current, RenderUniforms& u);
// Debug view colours; `params` has its defaults resolved.
void fill_particles(const pf_particle_params& params, RenderUniforms& u);

}  // namespace pf
