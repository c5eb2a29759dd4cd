// Draws a simulation's particles into the engine's frame: screen-space liquid
// (pf_render_ssf: SCENE_COPY -> THICKNESS -> DEPTH -> SMOOTH -> SHADE -> RESOLVE, with SMOOTH
// and SHADE on compute or on full-screen fragment shaders) and the sphere-sprite debug view
// (pf_render_particles). Made on the first render call of a pf_sim and destroyed before its
// Simulation; holds its own programs, textures, timers. Arguments arrive validated and with
// their defaults resolved (src/api/pf_render_api.cpp); the engine's GL objects are checked here.
#pragma once
#include <chrono>
#include <cstdint>
#include <memory>

#include "gl/buffer.h"
#include "gl/gl.h"
#include "gl/objects.h"
#include "gl/program.h"
#include "gl/state_guard.h"
#include "gl/timer_ring.h"
#include "pf/pf.h"
#include "render/render_uniforms.h"
#include "render/ssf_targets.h"
#include "render/target_check.h"

namespace pf {

class Simulation;

class Renderer {
public:
    explicit Renderer(const Simulation& sim);
    ~Renderer() = default;
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    pf_result render_ssf(const pf_camera& camera, const pf_render_target& target, const pf_ssf_params& params);
    pf_result render_particles(const pf_camera& camera, const pf_render_target& target,
                               const pf_particle_params& params);
    // Fills the render_* fields of pf_stats (newest finished call; never waits).
    void stats(pf_stats& out) const;

private:

    // Checks the engine's objects and reads the clip origin (y_sign -1 for GL_UPPER_LEFT).
    pf_result begin(const char* fn, const pf_camera& camera, const pf_render_target& target, bool ssf,
                    TargetInfo& info, float& y_sign);
    pf_result program(gl::ProgramId id, const char* fn, GLuint& out);
    void upload(const RenderUniforms& u);
    void set_fixed_state();
    void bind_particles();
    void bind_texture(GLuint unit, GLenum target, GLuint texture, bool linear);
    void draw_spheres();
    void draw_fullscreen();
    void dispatch_screen(int width, int height);
    pf_result finish(const char* fn, std::chrono::steady_clock::time_point started);

    void pass_scene_copy(const pf_camera& camera, const pf_render_target& target, bool depth);
    void pass_thickness(GLuint program, int w, int h);
    void pass_depth(GLuint program, int w, int h);
    // Compute path of THICKNESS and DEPTH: clear + thickness splat, depth splat + resolve.
    void pass_splat_thickness(GLuint clear, GLuint splat, int w, int h);
    void pass_splat_depth(GLuint splat, GLuint resolve, int w, int h);
    void dispatch_particles(GLuint program);
    SsfTargets::Texture pass_smooth(GLuint program, const pf_ssf_params& params, int w, int h);
    void pass_shade(GLuint program, const pf_ssf_params& params, SsfTargets::Texture depth,
                    GLuint environment, int w, int h);
    void pass_resolve(GLuint program, const pf_camera& camera, GLuint framebuffer);

    const Simulation& sim_;
    const gl::Api& gl_;
    gl::StateGuard::Options guard_options_{};
    int gl_version_ = 0;  // major * 10 + minor
    gl::ProgramCache programs_;
    mutable gl::TimerRing timers_;  // polled by the const stats()
    gl::Buffer uniforms_;
    gl::Object vao_, nearest_, linear_;
    std::unique_ptr<SsfTargets> targets_;
    uint64_t frames_ = 0;
    float last_cpu_ms_ = 0.0f;
};

}  // namespace pf
