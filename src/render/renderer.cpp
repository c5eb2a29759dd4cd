#include "render/renderer.h"

#include <string>

#include "gl/debug.h"
#include "gl/render_state_guard.h"
#include "render/layers/registry.h"
#include "render/target_check.h"
#include "sim/simulation.h"

namespace pf {

static_assert(PF_DEPTH_STANDARD == PF_DEPTH_STANDARD_ID && PF_DEPTH_ZERO_TO_ONE == PF_DEPTH_ZERO_TO_ONE_ID &&
                  PF_DEPTH_REVERSED_Z == PF_DEPTH_REVERSED_Z_ID,
              "depth convention ids shared with GLSL");

namespace {
constexpr GLenum kClipOrigin = 0x935C;  // GL 4.5 (glClipControl); the loader is generated for 4.3
constexpr GLenum kUpperLeft = 0x8CA2;

int gl_version(const gl::Api& gl) {
    GLint major = 0, minor = 0;
    gl.GetIntegerv(GL_MAJOR_VERSION, &major);
    gl.GetIntegerv(GL_MINOR_VERSION, &minor);
    return major * 10 + minor;
}
}  // namespace

Renderer::Renderer(const Simulation& sim) : sim_(sim), gl_version_(gl_version(sim.api())), context_(sim) {
    guard_options_.query_buffer = gl_version_ >= 44;
}

RenderLayer& Renderer::layer(RenderLayerId id) {
    std::unique_ptr<RenderLayer>& l = layers_[size_t(id)];
    if (!l) l = make_render_layer(id);
    return *l;
}

pf_result Renderer::begin(RenderFrame& frame, bool scene) {
    const gl::Api& gl = context_.gl();
    // The target checks read glGetError: an error the engine left pending would look like ours.
    if (GLenum pending = gl.GetError(); pending != GL_NO_ERROR) {
        while (gl.GetError() != GL_NO_ERROR) {
        }
        sim_.log().warning(std::string(frame.fn) + ": a GL error (" + gl::hex(pending) +
                           ") was pending before the call; it was consumed");
    }
    if (pf_result r = check_render_target(gl, sim_.log(), frame.fn, *frame.target, *frame.camera, scene);
        r != PF_OK)
        return r;
    frame.y_sign = 1.0f;
    if (gl_version_ >= 45) {
        GLint origin = 0;
        gl.GetIntegerv(kClipOrigin, &origin);
        if (GLenum(origin) == kUpperLeft) frame.y_sign = -1.0f;
    }
    context_.ensure_objects();
    return PF_OK;
}

pf_result Renderer::finish(const char* fn, std::chrono::steady_clock::time_point started) {
    const gl::Api& gl = context_.gl();
    const GLenum err = gl.GetError();
    last_cpu_ms_ = std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - started).count();
    if (err == GL_NO_ERROR) return PF_OK;
    while (gl.GetError() != GL_NO_ERROR) {
    }
    return sim_.log().error(err == GL_OUT_OF_MEMORY ? PF_ERROR_OUT_OF_MEMORY : PF_ERROR_GL,
                            std::string(fn) + ": the GL reported error " + gl::hex(err));
}

pf_result Renderer::render(RenderFrame frame, std::initializer_list<RenderLayerId> ids) {
    const auto started = std::chrono::steady_clock::now();
    const gl::Api& gl = context_.gl();
    gl::StateGuard guard(gl, guard_options_);
    gl::RenderStateGuard render_guard(gl);
    const gl::DebugGroup debug_group(gl, (std::string("pflip/") + (frame.fn + 3)).c_str());
    bool scene = false;
    for (RenderLayerId id : ids) scene = scene || layer(id).reads_scene();
    if (pf_result r = begin(frame, scene); r != PF_OK) return r;
    for (RenderLayerId id : ids) {
        if (pf_result r = layer(id).prepare(context_, frame); r != PF_OK) return r;
    }
    RenderUniforms u{};
    fill_camera(*frame.camera, frame.y_sign, sim_.domain_to_world(), u);
    for (RenderLayerId id : ids) layer(id).fill(frame, u);
    ++frames_;
    context_.timers().begin_step(frames_, 1);
    context_.upload(u);
    context_.set_fixed_state();
    for (RenderLayerId id : ids) context_.run(layer(id).passes(frame), frame);
    return finish(frame.fn, started);
}

pf_result Renderer::render_ssf(const pf_camera& camera, const pf_render_target& target, const pf_ssf_params& params) {
    RenderFrame frame;
    frame.fn = "pf_render_ssf";
    frame.camera = &camera;
    frame.target = &target;
    frame.ssf = &params;
    frame.particle_volume = sim_.particle_volume();
    const pf_sim_desc& d = sim_.desc();
    for (int a = 0; a < 3; ++a) {
        frame.cells.origin[a] = d.origin[a];
        frame.cells.dims[a] = int32_t(d.grid_size[a]);
    }
    frame.cells.cell_size = d.cell_size;
    frame.cells.rest_count = float(d.fill_particles_per_cell);
    frame.cells.current = sim_.cell_counts_current();
    frame.cells.counts = sim_.cell_count().id();
    frame.cells.order = sim_.particle_order();
    if ((sim_.features() & PF_FEATURE_WHITEWATER) && params.skip_whitewater == 0)
        return render(frame, {RenderLayerId::liquid_surface, RenderLayerId::whitewater});
    return render(frame, {RenderLayerId::liquid_surface});
}

pf_result Renderer::render_particles(const pf_camera& camera, const pf_render_target& target,
                                     const pf_particle_params& params) {
    RenderFrame frame;
    frame.fn = "pf_render_particles";
    frame.camera = &camera;
    frame.target = &target;
    frame.particles = &params;
    return render(frame, {RenderLayerId::particles});
}

void Renderer::stats(pf_stats& out) const {
    gl::StateGuard guard(context_.gl(), guard_options_);
    context_.timers().poll();
    const auto& r = context_.timers().latest();
    out.render_frame = r.step;
    out.render_gpu_total_ms = 0.0f;
    for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p) {
        out.render_gpu_ms[p] = r.at(size_t(p));
        out.render_gpu_total_ms += r.at(size_t(p));
    }
    out.render_whitewater_gpu_ms = r.at(size_t(kRenderPassWhitewater));
    out.render_gpu_total_ms += out.render_whitewater_gpu_ms;
    out.render_cpu_ms = last_cpu_ms_;
    for (const auto& l : layers_) {
        if (l) out.gpu_memory_bytes += l->bytes();  // their buffers are in the simulation's tally
    }
}

}  // namespace pf
