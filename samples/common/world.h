// The samples' "engine world": what a game engine would have drawn before asking pflip for
// the liquid. A sky, a checkered floor, a cut-away tile tank around the simulation domain (the
// far walls and low rims are opaque, the near walls left out so the liquid stays visible, thin
// corner posts and top bars frame it), an opaque crate in front of the tank so occlusion
// shows, and the scene's obstacles at the poses the application last gave pflip
// (set_obstacles; obstacle_renderer.h draws them, SDF obstacles ray-marched in their texture).
// Everything is drawn with the samples' own GL (pf_glad_app) into the world's own
// framebuffer: a colour texture and a depth texture, exactly the pair pf_render_target wants.
//
// Per frame:
//     world.set_obstacles(poses);                 // what pf_set_obstacle last received
//     world.draw(camera);                         // sky + geometry into world.framebuffer()
//     pf_render_target t = world.render_target(); // colour/depth textures, the same FBO as target
//     pf_render_ssf(sim, &pfcam, &t, &ssf);       // liquid drawn over it
//     world.end_frame();                          // back to the default clip control
//     ...blit world.framebuffer() to the window, or glReadPixels it
#pragma once

#include <glad/gl.h>

#include <pf/pf.h>

#include "camera.h"
#include "gl_util.h"
#include "obstacle_renderer.h"
#include "scene.h"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace pfs {

class World {
public:
    /// Builds the geometry around scene's domain. Needs the GL context current and GLAD loaded;
    /// get_proc is used for glClipControl (GL 4.5) only.
    World(const Scene& scene, GLADloadfunc get_proc);
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    /// (Re)creates the framebuffer's textures at width x height (no-op if unchanged).
    void resize(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }

    /// Direction towards the sun (world space); lights the world and the sky. Give pflip the same.
    void set_sun(const glm::vec3& towards_sun);
    glm::vec3 sun() const { return sun_; }

    /// Whether depth conventions other than standard can be used (glClipControl present).
    bool has_clip_control() const { return clip_control_ != nullptr; }

    /// The obstacles draw() shows from now on, at these poses (the library has no getter: pass
    /// what pf_add_obstacle / pf_set_obstacle last received). Empty by default.
    void set_obstacles(const std::vector<pf_obstacle>& obstacles) { obstacles_ = obstacles; }

    /// Clears and draws the world into framebuffer() with camera (viewport = whole framebuffer).
    /// For zero_to_one / reversed_z cameras sets glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE),
    /// which stays set (pflip renders under it) until end_frame(). Leaves framebuffer() bound.
    void draw(const OrbitCamera& camera);
    /// Restores the default clip control if draw() changed it.
    void end_frame();

    GLuint framebuffer() const { return fbo_; }
    GLuint color_texture() const { return color_tex_; }
    GLuint depth_texture() const { return depth_tex_; }
    /// The sky rendered into a cube map once (128^2 faces), for pf_render_target.environment_cubemap.
    GLuint sky_cubemap() const { return sky_cube_; }

    /// framebuffer() as target and its own colour/depth textures as the scene pflip draws over;
    /// environment_cubemap is the sky cube map when use_sky_cubemap, else 0 (pflip's built-in sky).
    pf_render_target render_target(bool use_sky_cubemap) const;

    /// Sets camera.near_plane / far_plane so the whole world (out to the fogged floor edge) is in view.
    void fit_clip_planes(OrbitCamera& camera) const;

    /// World-space bounds of the tank's inside (the simulation domain).
    glm::vec3 tank_min() const { return tank_min_; }
    glm::vec3 tank_max() const { return tank_max_; }

private:
    void build_geometry(const Scene& scene);
    void build_sky_cubemap();
    void draw_sky(const glm::mat3& inv_view_rot, float tan_x, float tan_y);

    std::unique_ptr<ObstacleRenderer> obstacle_renderer_;
    std::vector<pf_obstacle> obstacles_;
    GLuint fbo_ = 0, color_tex_ = 0, depth_tex_ = 0;
    GLuint sky_cube_ = 0;
    GLuint lit_prog_ = 0, sky_prog_ = 0;
    GLuint vao_ = 0, vbo_ = 0, empty_vao_ = 0;
    GLsizei vertex_count_ = 0;
    int width_ = 0, height_ = 0;
    glm::vec3 tank_min_{0.0f}, tank_max_{1.0f};
    glm::vec3 sun_{0.4f, 0.8f, 0.45f};
    float tile_ = 0.1f, checker_ = 0.25f, fog_start_ = 5.0f, fog_end_ = 20.0f;
    ClipControlFn clip_control_ = nullptr;
    bool clip_changed_ = false;
    bool sky_dirty_ = true;
};

/// How the samples draw the liquid: pflip's screen-space fluid or its debug particles.
struct LiquidLook {
    bool ssf = true;                 ///< pf_render_ssf, else pf_render_particles
    bool sky_cubemap = true;         ///< give pflip the world's sky cube map (else its built-in sky)
    pf_ssf_params ssf_params = pf_default_ssf_params();
    pf_particle_params particle_params = pf_default_particle_params();
};

/// One frame the way an engine does it: world.draw(camera), then pflip draws the liquid into the
/// world's framebuffer over its colour and depth textures, then world.end_frame(). Returns the
/// pf_render_* result (the world is drawn either way).
pf_result draw_frame(World& world, pf_sim* sim, const OrbitCamera& camera, const LiquidLook& look);

/// "P2G_OVERFLOW SPEED_CLAMPED" etc. for pf_stats.flags; "none" for 0.
std::string flag_names(uint32_t flags);

} // namespace pfs
