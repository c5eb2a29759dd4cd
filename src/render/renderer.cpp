#include "render/renderer.h"

#include <string>

#include "common/render_slots.h"
#include "gl/allocation_check.h"
#include "gl/debug.h"
#include "gl/render_state_guard.h"
#include "sim/simulation.h"

namespace pf {

static_assert(PF_SSF_FILTER_BILATERAL == PF_SSF_FILTER_BILATERAL_ID, "filter ids shared with GLSL");
static_assert(PF_SSF_FILTER_NARROW_RANGE == PF_SSF_FILTER_NARROW_RANGE_ID, "filter ids shared with GLSL");
static_assert(PF_DEPTH_STANDARD == PF_DEPTH_STANDARD_ID && PF_DEPTH_ZERO_TO_ONE == PF_DEPTH_ZERO_TO_ONE_ID &&
                  PF_DEPTH_REVERSED_Z == PF_DEPTH_REVERSED_Z_ID,
              "depth convention ids shared with GLSL");
static_assert(PF_PARTICLE_COLOR_SPEED == PF_COLOR_SPEED_ID && PF_PARTICLE_COLOR_VELOCITY_X == PF_COLOR_VELOCITY_X_ID &&
                  PF_PARTICLE_COLOR_VELOCITY_Y == PF_COLOR_VELOCITY_Y_ID &&
                  PF_PARTICLE_COLOR_VELOCITY_Z == PF_COLOR_VELOCITY_Z_ID &&
                  PF_PARTICLE_COLOR_HEIGHT == PF_COLOR_HEIGHT_ID && PF_PARTICLE_COLOR_UNIFORM == PF_COLOR_UNIFORM_ID,
              "colour modes shared with GLSL");

namespace {
using gl::ProgramId;
constexpr GLenum kClipOrigin = 0x935C;  // GL 4.5 (glClipControl); the loader is generated for 4.3
constexpr GLenum kUpperLeft = 0x8CA2;

int ceil_div(int a, int b) { return (a + b - 1) / b; }

int gl_version(const gl::Api& gl) {
    GLint major = 0, minor = 0;
    gl.GetIntegerv(GL_MAJOR_VERSION, &major);
    gl.GetIntegerv(GL_MINOR_VERSION, &minor);
    return major * 10 + minor;
}

// Scope of one timed pass, inside the debug group "pflip/<render pass name>".
struct TimedPass {
    gl::TimerRing& timers;
    gl::DebugGroup group;
    TimedPass(gl::TimerRing& t, pf_render_pass pass, const gl::Api& gl)
        : timers(t), group(gl, (std::string("pflip/") + pf_render_pass_name(pass)).c_str()) {
        timers.begin_pass(pass);
    }
    ~TimedPass() { timers.end_pass(); }
};
}  // namespace

Renderer::Renderer(const Simulation& sim)
    : sim_(sim), gl_(sim.api()), gl_version_(gl_version(gl_)), programs_(gl_), timers_(gl_) {
    guard_options_.query_buffer = gl_version_ >= 44;
}

pf_result Renderer::begin(const char* fn, const pf_camera& camera, const pf_render_target& target, bool ssf,
                          TargetInfo& info, float& y_sign) {
    // The target checks read glGetError: an error the engine left pending would look like ours.
    if (GLenum pending = gl_.GetError(); pending != GL_NO_ERROR) {
        while (gl_.GetError() != GL_NO_ERROR) {
        }
        sim_.log().warning(std::string(fn) + ": a GL error (" + gl::hex(pending) +
                           ") was pending before the call; it was consumed");
    }
    if (pf_result r = check_render_target(gl_, sim_.log(), fn, target, camera, ssf, info); r != PF_OK) return r;
    y_sign = 1.0f;
    if (gl_version_ >= 45) {
        GLint origin = 0;
        gl_.GetIntegerv(kClipOrigin, &origin);
        if (GLenum(origin) == kUpperLeft) y_sign = -1.0f;
    }
    if (!uniforms_.id()) {  // first call: objects every pass uses
        uniforms_ = gl::Buffer(gl_, sizeof(RenderUniforms), GL_DYNAMIC_DRAW, "render_uniforms");
        vao_ = gl::Object(gl_, gl::ObjectKind::vertex_array);
        nearest_ = gl::Object(gl_, gl::ObjectKind::sampler);
        linear_ = gl::Object(gl_, gl::ObjectKind::sampler);
        for (const gl::Object* s : {&nearest_, &linear_}) {
            const GLint filter = s == &linear_ ? GL_LINEAR : GL_NEAREST;
            gl_.SamplerParameteri(s->id(), GL_TEXTURE_MIN_FILTER, filter);
            gl_.SamplerParameteri(s->id(), GL_TEXTURE_MAG_FILTER, filter);
            gl_.SamplerParameteri(s->id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            gl_.SamplerParameteri(s->id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            gl_.SamplerParameteri(s->id(), GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
            gl_.SamplerParameteri(s->id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
            gl::label_object(gl_, GL_SAMPLER, s->id(), s == &linear_ ? "sampler_linear" : "sampler_nearest");
        }
        // Instanced sprites: one vec4 position and one vec4 velocity per particle.
        gl_.BindVertexArray(vao_.id());
        gl::label_object(gl_, GL_VERTEX_ARRAY, vao_.id(), "particle_sprites");
        for (GLuint a : {GLuint(PF_ATTR_POSITION), GLuint(PF_ATTR_VELOCITY)}) {
            gl_.EnableVertexAttribArray(a);
            gl_.VertexAttribFormat(a, 4, GL_FLOAT, GL_FALSE, 0);
            gl_.VertexAttribBinding(a, a);
            gl_.VertexBindingDivisor(a, 1);
        }
    }
    return PF_OK;
}

pf_result Renderer::program(ProgramId id, const char* fn, GLuint& out) {
    std::string error;
    out = programs_.get(id, error);
    if (!out) return sim_.log().error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
    return PF_OK;
}

void Renderer::upload(const RenderUniforms& u) {
    uniforms_.upload(0, sizeof(u), &u);
    gl_.BindBufferBase(GL_UNIFORM_BUFFER, PF_UBO_RENDER, uniforms_.id());
}

// Every raster state a pass relies on, set explicitly (the guards put the engine's back).
void Renderer::set_fixed_state() {
    for (GLenum cap : gl::RenderStateGuard::kCapabilities) gl_.Disable(cap);
    gl_.Disable(GL_BLEND);         // every draw buffer
    gl_.Disable(GL_SCISSOR_TEST);  // every viewport
    gl_.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl_.DepthMask(GL_TRUE);
    gl_.DepthRange(0.0, 1.0);  // gl_FragDepth is clamped to the depth range
    gl_.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    gl_.BindVertexArray(vao_.id());
}

void Renderer::bind_particles() {
    pf_gl_buffers b{};
    sim_.gl_buffers(b);
    gl_.BindVertexBuffer(PF_ATTR_POSITION, b.positions, 0, GLsizei(b.stride));
    gl_.BindVertexBuffer(PF_ATTR_VELOCITY, b.velocities, 0, GLsizei(b.stride));
}

void Renderer::bind_texture(GLuint unit, GLenum target, GLuint texture, bool linear) {
    gl_.ActiveTexture(GL_TEXTURE0 + unit);
    gl_.BindTexture(target, texture);
    gl_.BindSampler(unit, linear ? linear_.id() : nearest_.id());
}

void Renderer::draw_spheres() {
    // One strip per live particle, as many as the GPU's count record says (no readback).
    gl_.BindBuffer(GL_DRAW_INDIRECT_BUFFER, sim_.count_record().id());
    gl_.DrawArraysIndirect(GL_TRIANGLE_STRIP, reinterpret_cast<const void*>(uintptr_t(PF_COUNT_STRIP_RECORD) * 4));
}

void Renderer::draw_fullscreen() { gl_.DrawArrays(GL_TRIANGLES, 0, 3); }

void Renderer::dispatch_screen(int width, int height) {
    gl_.DispatchCompute(GLuint(ceil_div(width, PF_RENDER_TILE)), GLuint(ceil_div(height, PF_RENDER_TILE)), 1);
    // Image stores are read next by texelFetch (or, after SHADE, by the resolve draw).
    gl_.MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

pf_result Renderer::finish(const char* fn, std::chrono::steady_clock::time_point started) {
    const GLenum err = gl_.GetError();
    last_cpu_ms_ = std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - started).count();
    if (err == GL_NO_ERROR) return PF_OK;
    while (gl_.GetError() != GL_NO_ERROR) {
    }
    return sim_.log().error(err == GL_OUT_OF_MEMORY ? PF_ERROR_OUT_OF_MEMORY : PF_ERROR_GL,
                            std::string(fn) + ": the GL reported error " + gl::hex(err));
}

// ---- pf_render_ssf -----------------------------------------------------------------------------

pf_result Renderer::render_ssf(const pf_camera& camera, const pf_render_target& target, const pf_ssf_params& params) {
    static constexpr const char* fn = "pf_render_ssf";
    const auto started = std::chrono::steady_clock::now();
    gl::StateGuard guard(gl_, guard_options_);
    gl::RenderStateGuard render_guard(gl_);
    const gl::DebugGroup debug_group(gl_, fn[10] == 's' ? "pflip/render_ssf" : "pflip/render_particles");
    TargetInfo info;
    float y_sign = 1.0f;
    if (pf_result r = begin(fn, camera, target, true, info, y_sign); r != PF_OK) return r;

    const bool compute = params.path == PF_SSF_PATH_COMPUTE;
    const bool narrow = params.filter == PF_SSF_FILTER_NARROW_RANGE;
    // Raster path: sphere sprites for THICKNESS / DEPTH. Compute path: splat clear, the two
    // splats and the splat resolve.
    GLuint thickness = 0, depth = 0, splat_clear = 0, splat_resolve = 0, smooth = 0, shade = 0, resolve = 0;
    for (auto [id, out] : {std::pair{compute ? ProgramId::ssf_splat_thickness_cs : ProgramId::ssf_thickness, &thickness},
                           std::pair{compute ? ProgramId::ssf_splat_depth_cs : ProgramId::ssf_depth, &depth},
                           std::pair{compute ? ProgramId::ssf_shade_cs : ProgramId::ssf_shade_fs, &shade},
                           std::pair{ProgramId::ssf_resolve, &resolve}}) {
        if (pf_result r = program(id, fn, *out); r != PF_OK) return r;
    }
    if (compute) {
        if (pf_result r = program(ProgramId::ssf_splat_clear_cs, fn, splat_clear); r != PF_OK) return r;
        if (pf_result r = program(ProgramId::ssf_splat_resolve_cs, fn, splat_resolve); r != PF_OK) return r;
    }
    if (params.filter != PF_SSF_FILTER_NONE) {
        const ProgramId id = compute ? (narrow ? ProgramId::ssf_smooth_narrow_cs : ProgramId::ssf_smooth_bilateral_cs)
                                     : (narrow ? ProgramId::ssf_smooth_narrow_fs : ProgramId::ssf_smooth_bilateral_fs);
        if (pf_result r = program(id, fn, smooth); r != PF_OK) return r;
    }

    const int w = camera.viewport[2], h = camera.viewport[3];
    if (!targets_) targets_ = std::make_unique<SsfTargets>(gl_);
    gl_.ActiveTexture(GL_TEXTURE0 + PF_TEX_SCENE_COLOR);  // ensure() binds on the active unit
    targets_->ensure(w, h, info.scene_depth_format);
    if (pf_result r = gl::check_allocated(gl_, sim_.log(), std::string(fn) + ": allocating " + std::to_string(w) + "x" +
                                                              std::to_string(h) + " render targets");
        r != PF_OK)
        return r;

    RenderUniforms u{};
    fill_camera(camera, y_sign, sim_.domain_to_world(), u);
    fill_ssf(params, target.scene_depth != 0, target.environment_cubemap != 0, u);
    ++frames_;
    timers_.begin_step(frames_, 1);
    upload(u);
    set_fixed_state();
    bind_particles();

    pass_scene_copy(camera, target, target.scene_depth != 0);
    if (compute) {
        pass_splat_thickness(splat_clear, thickness, w, h);
        pass_splat_depth(depth, splat_resolve, w, h);
    } else {
        pass_thickness(thickness, w, h);
        pass_depth(depth, w, h);
    }
    const SsfTargets::Texture surface = pass_smooth(smooth, params, w, h);
    pass_shade(shade, params, surface, target.environment_cubemap, w, h);
    pass_resolve(resolve, camera, target.framebuffer);
    return finish(fn, started);
}

// Blits rather than glCopyImageSubData: a blit needs only a complete framebuffer, not a
// complete texture (an engine attachment often has a mipmapping filter and one level), and it
// converts any colour format into the RGBA16F copy. With GL_FRAMEBUFFER_SRGB on, an sRGB scene
// is decoded to linear on the way, as sampling it would be.
void Renderer::pass_scene_copy(const pf_camera& camera, const pf_render_target& target, bool depth) {
    TimedPass timed(timers_, PF_RENDER_PASS_SCENE_COPY, gl_);
    const GLuint read = targets_->framebuffer(SsfTargets::copy_read);
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, read);
    gl_.FramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.scene_color, 0);
    gl_.FramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth ? target.scene_depth : 0, 0);
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, targets_->framebuffer(SsfTargets::copy_draw));
    gl_.Enable(GL_FRAMEBUFFER_SRGB);
    const GLint x = camera.viewport[0], y = camera.viewport[1], w = camera.viewport[2], h = camera.viewport[3];
    gl_.BlitFramebuffer(x, y, x + w, y + h, 0, 0, w, h, GL_COLOR_BUFFER_BIT | (depth ? GL_DEPTH_BUFFER_BIT : 0),
                        GL_NEAREST);
    gl_.Disable(GL_FRAMEBUFFER_SRGB);
    // Detach at once: an attachment keeps the engine's texture alive after the engine deletes it.
    gl_.FramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    gl_.FramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
}

void Renderer::pass_thickness(GLuint program, int w, int h) {
    TimedPass timed(timers_, PF_RENDER_PASS_THICKNESS, gl_);
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, targets_->framebuffer(SsfTargets::thickness_fb));
    gl_.Viewport(0, 0, w, h);
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    gl_.ClearBufferfv(GL_COLOR, 0, zero);
    gl_.Enable(GL_BLEND);
    gl_.BlendEquation(GL_FUNC_ADD);
    gl_.BlendFunc(GL_ONE, GL_ONE);
    bind_texture(PF_TEX_SCENE_DEPTH, GL_TEXTURE_2D, targets_->texture(SsfTargets::scene_depth), false);
    gl_.UseProgram(program);
    draw_spheres();
    gl_.Disable(GL_BLEND);
}

void Renderer::pass_depth(GLuint program, int w, int h) {
    TimedPass timed(timers_, PF_RENDER_PASS_DEPTH, gl_);
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, targets_->framebuffer(SsfTargets::depth_fb));
    gl_.Viewport(0, 0, w, h);
    const GLfloat no_liquid[4] = {float(PF_NO_LIQUID), 0.0f, 0.0f, 0.0f}, far_depth = 1.0f;
    gl_.ClearBufferfv(GL_COLOR, 0, no_liquid);
    gl_.ClearBufferfv(GL_DEPTH, 0, &far_depth);
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(GL_LESS);
    gl_.UseProgram(program);
    draw_spheres();
    gl_.Disable(GL_DEPTH_TEST);
}

void Renderer::dispatch_particles(GLuint program) {
    const uint32_t n = sim_.particle_count();
    gl_.UseProgram(program);
    gl_.ProgramUniform1ui(program, PF_LOC_SPLAT_COUNT, n);
    if (n > 0) {  // no particles: no groups (and no division by zero groups per row)
        const int64_t groups = ceil_div(int64_t(n), PF_SPLAT_WORKGROUP);
        const int64_t gx = std::min<int64_t>(groups, 65535), gy = ceil_div(groups, gx);
        gl_.DispatchCompute(GLuint(gx), GLuint(gy), 1);
    }
    gl_.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void Renderer::pass_splat_thickness(GLuint clear, GLuint splat, int w, int h) {
    TimedPass timed(timers_, PF_RENDER_PASS_THICKNESS, gl_);
    const GLuint depth_bits = targets_->texture(SsfTargets::splat_depth_bits);
    const GLuint thickness_bits = targets_->texture(SsfTargets::splat_thickness_bits);
    gl_.BindImageTexture(PF_IMG_SPLAT_DEPTH, depth_bits, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    gl_.BindImageTexture(PF_IMG_SPLAT_THICKNESS, thickness_bits, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    gl_.UseProgram(clear);
    dispatch_screen(w, h);
    pf_gl_buffers b{};
    sim_.gl_buffers(b);
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PF_SSBO_PARTICLE_POS, b.positions);
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PF_SSBO_PARTICLE_COUNT, b.draw_indirect);
    bind_texture(PF_TEX_SCENE_DEPTH, GL_TEXTURE_2D, targets_->texture(SsfTargets::scene_depth), false);
    dispatch_particles(splat);
}

void Renderer::pass_splat_depth(GLuint splat, GLuint resolve, int w, int h) {
    TimedPass timed(timers_, PF_RENDER_PASS_DEPTH, gl_);
    dispatch_particles(splat);
    gl_.BindImageTexture(PF_IMG_RAW_DEPTH, targets_->texture(SsfTargets::raw_depth), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                         GL_R32F);
    gl_.BindImageTexture(PF_IMG_THICKNESS, targets_->texture(SsfTargets::thickness), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                         GL_R32F);
    gl_.UseProgram(resolve);
    dispatch_screen(w, h);
}

// Alternating horizontal and vertical 1D passes, filter_iterations times, ping-ponging
// between smooth_a and smooth_b. Returns the texture holding the surface to shade.
SsfTargets::Texture Renderer::pass_smooth(GLuint program, const pf_ssf_params& params, int w, int h) {
    TimedPass timed(timers_, PF_RENDER_PASS_SMOOTH, gl_);
    if (params.filter == PF_SSF_FILTER_NONE) return SsfTargets::raw_depth;
    const bool compute = params.path == PF_SSF_PATH_COMPUTE;
    gl_.UseProgram(program);
    if (!compute) gl_.Viewport(0, 0, w, h);
    SsfTargets::Texture src = SsfTargets::raw_depth;
    for (uint32_t pass = 0; pass < 2 * params.filter_iterations; ++pass) {
        const SsfTargets::Texture dst = (pass % 2 == 0) ? SsfTargets::smooth_a : SsfTargets::smooth_b;
        gl_.ProgramUniform2i(program, PF_LOC_SMOOTH_DIRECTION, pass % 2 == 0 ? 1 : 0, pass % 2 == 0 ? 0 : 1);
        bind_texture(PF_TEX_LIQUID_DEPTH, GL_TEXTURE_2D, targets_->texture(src), false);
        if (compute) {
            gl_.BindImageTexture(PF_IMG_SMOOTH_OUT, targets_->texture(dst), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
            dispatch_screen(w, h);
        } else {
            gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER,
                                targets_->framebuffer(dst == SsfTargets::smooth_a ? SsfTargets::smooth_a_fb
                                                                                  : SsfTargets::smooth_b_fb));
            draw_fullscreen();
        }
        src = dst;
    }
    return src;
}

void Renderer::pass_shade(GLuint program, const pf_ssf_params& params, SsfTargets::Texture depth, GLuint environment,
                          int w, int h) {
    TimedPass timed(timers_, PF_RENDER_PASS_SHADE, gl_);
    bind_texture(PF_TEX_SCENE_COLOR, GL_TEXTURE_2D, targets_->texture(SsfTargets::scene_color), true);
    bind_texture(PF_TEX_LIQUID_DEPTH, GL_TEXTURE_2D, targets_->texture(depth), false);
    bind_texture(PF_TEX_THICKNESS, GL_TEXTURE_2D, targets_->texture(SsfTargets::thickness), false);
    bind_texture(PF_TEX_ENVIRONMENT, GL_TEXTURE_CUBE_MAP, environment, true);
    gl_.UseProgram(program);
    if (params.path == PF_SSF_PATH_COMPUTE) {
        gl_.BindImageTexture(PF_IMG_SHADE_COLOR, targets_->texture(SsfTargets::shaded_color), 0, GL_FALSE, 0,
                             GL_WRITE_ONLY, GL_RGBA16F);
        gl_.BindImageTexture(PF_IMG_SHADE_DEPTH, targets_->texture(SsfTargets::shaded_depth), 0, GL_FALSE, 0,
                             GL_WRITE_ONLY, GL_R32F);
        dispatch_screen(w, h);
    } else {
        gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, targets_->framebuffer(SsfTargets::shade_fb));
        gl_.Viewport(0, 0, w, h);
        draw_fullscreen();
    }
}

void Renderer::pass_resolve(GLuint program, const pf_camera& camera, GLuint framebuffer) {
    TimedPass timed(timers_, PF_RENDER_PASS_RESOLVE, gl_);
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    gl_.Viewport(camera.viewport[0], camera.viewport[1], camera.viewport[2], camera.viewport[3]);
    // ALWAYS with writes on: the liquid already passed the scene-depth test; this only stores
    // its depth (a target without depth attachment simply has none to write).
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(GL_ALWAYS);
    gl_.Enable(GL_FRAMEBUFFER_SRGB);  // encode into an sRGB target, matching the decoded copy
    bind_texture(PF_TEX_SHADED_COLOR, GL_TEXTURE_2D, targets_->texture(SsfTargets::shaded_color), false);
    bind_texture(PF_TEX_SHADED_DEPTH, GL_TEXTURE_2D, targets_->texture(SsfTargets::shaded_depth), false);
    gl_.UseProgram(program);
    draw_fullscreen();
}

// ---- pf_render_particles -----------------------------------------------------------------------

pf_result Renderer::render_particles(const pf_camera& camera, const pf_render_target& target,
                                     const pf_particle_params& params) {
    static constexpr const char* fn = "pf_render_particles";
    const auto started = std::chrono::steady_clock::now();
    gl::StateGuard guard(gl_, guard_options_);
    gl::RenderStateGuard render_guard(gl_);
    const gl::DebugGroup debug_group(gl_, fn[10] == 's' ? "pflip/render_ssf" : "pflip/render_particles");
    TargetInfo info;
    float y_sign = 1.0f;
    if (pf_result r = begin(fn, camera, target, false, info, y_sign); r != PF_OK) return r;
    GLuint sprites = 0;
    if (pf_result r = program(ProgramId::particles, fn, sprites); r != PF_OK) return r;

    RenderUniforms u{};
    fill_camera(camera, y_sign, sim_.domain_to_world(), u);
    fill_particles(params, u);
    ++frames_;
    timers_.begin_step(frames_, 1);
    {
        TimedPass timed(timers_, PF_RENDER_PASS_PARTICLES, gl_);
        upload(u);
        set_fixed_state();
        bind_particles();
        gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, target.framebuffer);
        gl_.Viewport(camera.viewport[0], camera.viewport[1], camera.viewport[2], camera.viewport[3]);
        gl_.Enable(GL_DEPTH_TEST);
        gl_.DepthFunc(camera.depth_convention == PF_DEPTH_REVERSED_Z ? GL_GREATER : GL_LESS);
        gl_.UseProgram(sprites);
        draw_spheres();
    }
    return finish(fn, started);
}

void Renderer::stats(pf_stats& out) const {
    gl::StateGuard guard(gl_, guard_options_);
    timers_.poll();
    const auto& r = timers_.latest();
    out.render_frame = r.step;
    out.render_gpu_total_ms = 0.0f;
    for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p) {
        out.render_gpu_ms[p] = r.at(size_t(p));
        out.render_gpu_total_ms += r.at(size_t(p));
    }
    out.render_cpu_ms = last_cpu_ms_;
    if (targets_) out.gpu_memory_bytes += targets_->bytes();  // its buffers are in the simulation's tally
}

}  // namespace pf
