// What every render layer draws with: the simulation's particles, the program cache, the render
// uniforms, the sprite vertex array, two samplers and the pass timers, with the GL helpers the
// layers' passes share (binding textures, drawing the particles as sprites or splatting them
// with compute, full-screen draws and screen-sized dispatches). One per pf_sim, made on its
// first render call.
#pragma once
#include <cstdint>

#include "gl/buffer.h"
#include "gl/gl.h"
#include "gl/objects.h"
#include "gl/program.h"
#include "gl/timer_ring.h"
#include "pf/pf.h"
#include "render/render_layer.h"
#include "render/render_uniforms.h"

namespace pf {

class Log;
class Simulation;

class RenderContext {
public:
    explicit RenderContext(const Simulation& sim);
    RenderContext(const RenderContext&) = delete;
    RenderContext& operator=(const RenderContext&) = delete;

    const gl::Api& gl() const { return gl_; }
    const Simulation& sim() const { return sim_; }
    const Log& log() const;
    gl::TimerRing& timers() { return timers_; }
    const gl::TimerRing& timers() const { return timers_; }

    // Objects every pass uses, made on the first call.
    void ensure_objects();
    // The program for `id` (built on first use); logs and returns PF_ERROR_SHADER_COMPILE.
    pf_result program(gl::ProgramId id, const char* fn, GLuint& out);
    void upload(const RenderUniforms& u);
    // Every raster state a pass relies on, set explicitly (the guards put the engine's back).
    void set_fixed_state();
    // Runs a layer's passes, each timed and in its debug group "pflip/<pass name>".
    void run(const std::vector<RenderPass>& passes, const RenderFrame& frame);

    // Textures a layer leaves for the layers after it in the same call (0: none): the liquid
    // surface's scene depth and liquid surface as eye depths, which the whitewater reads.
    struct Handoff {
        GLuint scene_eye_depth = 0;
        GLuint liquid_eye_depth = 0;
    };
    Handoff& handoff() { return handoff_; }
    // The simulation's particles on the sprite attributes (set_fixed_state binds them too).
    void bind_vertex_buffers();
    // Binds `texture` on `unit` with the nearest or linear sampler.
    void bind_texture(GLuint unit, GLenum target, GLuint texture, bool linear);
    // One sphere sprite per live particle, as many as the GPU's count record says (no readback).
    void draw_spheres();
    void draw_fullscreen();
    // Triangles without vertex attributes, as the glDrawArraysIndirect record at the start of
    // `record` says (instances may outnumber the particles the sprite attributes hold).
    void draw_indirect_without_attributes(GLuint record);
    // Whether vertex shaders may read storage buffers here (GL 4.3 promises none).
    bool vertex_storage_buffers();
    // One invocation per pixel, in PF_RENDER_TILE tiles, then the barriers its reader needs.
    void dispatch_screen(int width, int height);
    // One invocation per particle of `program`, then an image-access barrier.
    void dispatch_particles(GLuint program);

private:
    const Simulation& sim_;
    const gl::Api& gl_;
    gl::ProgramCache programs_;
    gl::TimerRing timers_;
    gl::Buffer uniforms_;
    gl::Object vao_, bare_vao_, nearest_, linear_;
    int vertex_storage_blocks_ = -1;  // GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS, -1 until asked
    Handoff handoff_;
};

}  // namespace pf
