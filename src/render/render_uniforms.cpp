#include "render/render_uniforms.h"

#include <cmath>
#include <cstring>
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

namespace pf {

namespace {
glm::dmat4 to_dmat4(const float m[16]) {
    glm::dmat4 r;
    for (int c = 0; c < 4; ++c) {
        for (int row = 0; row < 4; ++row) r[c][row] = m[c * 4 + row];
    }
    return r;
}

void store(const glm::dmat4& m, float out[16]) {
    for (int c = 0; c < 4; ++c) {
        for (int row = 0; row < 4; ++row) out[c * 4 + row] = float(m[c][row]);
    }
}
}  // namespace

bool camera_orthographic(const pf_camera& camera) {
    // Perspective projections put -z into clip w (row 3 = 0 0 -1 0); orthographic ones keep w = 1.
    return camera.proj[3] == 0.0f && camera.proj[7] == 0.0f && camera.proj[11] == 0.0f && camera.proj[15] != 0.0f;
}

float camera_pixels_per_metre(const pf_camera& camera) {
    // proj[1][1] maps eye y over depth (or eye y, orthographic) to NDC y: half the height in pixels.
    return std::fabs(camera.proj[5]) * 0.5f * float(camera.viewport[3]);
}

void fill_camera(const pf_camera& camera, float y_sign, const glm::mat4& domain_to_world, RenderUniforms& u) {
    std::memcpy(u.view, camera.view, sizeof(u.view));
    store(to_dmat4(camera.view) * glm::dmat4(domain_to_world), u.domain_view);
    std::memcpy(u.proj, camera.proj, sizeof(u.proj));
    store(glm::inverse(to_dmat4(camera.proj)), u.inv_proj);
    store(glm::inverse(to_dmat4(camera.view)), u.inv_view);
    const float w = float(camera.viewport[2]), h = float(camera.viewport[3]);
    u.viewport[0] = w;
    u.viewport[1] = h;
    u.viewport[2] = 1.0f / w;
    u.viewport[3] = 1.0f / h;
    u.planes[0] = camera.near_plane;
    u.planes[1] = camera.far_plane;
    u.planes[2] = float(camera.depth_convention);
    u.planes[3] = camera_orthographic(camera) ? 1.0f : 0.0f;
    u.filter[1] = camera_pixels_per_metre(camera);
    u.surface[3] = y_sign;
    u.target[0] = camera.viewport[0];
    u.target[1] = camera.viewport[1];
}

void fill_ssf(const pf_ssf_params& p, bool has_scene_depth, bool has_environment, double particle_volume,
              RenderUniforms& u) {
    u.sphere[0] = p.particle_radius;
    // The thickness pass sums the chords of overlapping spheres, each larger than the liquid it
    // stands for (at the default radius of half a cell and 8 a cell, 4.19 times): scaled by the
    // ratio, a column's sum is its depth of liquid.
    const double r = double(p.particle_radius);
    u.liquid[0] = float(particle_volume / (4.0 / 3.0 * glm::pi<double>() * r * r * r));
    u.sphere[1] = float(p.filter_radius);
    u.sphere[2] = p.filter_depth_range;
    u.filter[0] = p.filter_world_radius;
    u.sphere[3] = has_scene_depth ? 1.0f : 0.0f;
    for (int c = 0; c < 3; ++c) u.absorption[c] = p.absorption[c];
    u.absorption[3] = p.refraction;
    const double len = std::sqrt(double(p.light_direction[0]) * p.light_direction[0] +
                                 double(p.light_direction[1]) * p.light_direction[1] +
                                 double(p.light_direction[2]) * p.light_direction[2]);
    for (int c = 0; c < 3; ++c) u.light[c] = float(p.light_direction[c] / len);
    u.light[3] = p.specular;
    u.surface[0] = p.fresnel_f0;
    u.surface[1] = p.shininess;
    u.surface[2] = has_environment ? 1.0f : 0.0f;
}

void fill_spray(float spray_radius_scale, const float origin[3], float cell_size, const int32_t dims[3],
                float rest_count, bool counts_current, RenderUniforms& u) {
    u.spray[0] = spray_radius_scale;
    u.spray[1] = 0.5f * rest_count;  // fewer than half a cell's rest count in seven cells: spray
    u.spray[2] = counts_current ? 1.0f : 0.0f;
    for (int a = 0; a < 3; ++a) {
        u.grid_origin[a] = origin[a];
        u.grid_dims[a] = dims[a];
    }
    u.grid_origin[3] = cell_size;
}

void fill_particles(const pf_particle_params& p, RenderUniforms& u) {
    u.sphere[0] = p.particle_radius;
    for (int c = 0; c < 3; ++c) {
        u.color_low[c] = p.color_low[c];
        u.color_high[c] = p.color_high[c];
    }
    u.color_low[3] = p.range[0];
    u.color_high[3] = p.range[1];
    u.modes[0] = int32_t(p.color_by);
}

}  // namespace pf
