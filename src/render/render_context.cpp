#include "render/render_context.h"

#include <algorithm>
#include <string>

#include "common/render_slots.h"
#include "gl/debug.h"
#include "gl/render_state_guard.h"
#include "sim/simulation.h"

namespace pf {

namespace {
int ceil_div(int a, int b) { return (a + b - 1) / b; }
}  // namespace

RenderContext::RenderContext(const Simulation& sim)
    : sim_(sim), gl_(sim.api()), programs_(gl_, sim.program_binaries()), timers_(gl_) {}

const Log& RenderContext::log() const { return sim_.log(); }

void RenderContext::ensure_objects() {
    if (uniforms_.id()) return;
    uniforms_ = gl::Buffer(gl_, sizeof(RenderUniforms), GL_DYNAMIC_DRAW, "render_uniforms");
    vao_ = gl::Object(gl_, gl::ObjectKind::vertex_array);
    bare_vao_ = gl::Object(gl_, gl::ObjectKind::vertex_array);
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
    // Draws that read no attributes (a VAO name becomes an object, which a label needs, when bound).
    gl_.BindVertexArray(bare_vao_.id());
    gl::label_object(gl_, GL_VERTEX_ARRAY, bare_vao_.id(), "attributeless");
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

pf_result RenderContext::program(gl::ProgramId id, const char* fn, GLuint& out) {
    std::string error;
    out = programs_.get(id, error);
    if (!out) return sim_.log().error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
    return PF_OK;
}

void RenderContext::upload(const RenderUniforms& u) {
    uniforms_.upload(0, sizeof(u), &u);
    gl_.BindBufferBase(GL_UNIFORM_BUFFER, PF_UBO_RENDER, uniforms_.id());
}

void RenderContext::set_fixed_state() {
    for (GLenum cap : gl::RenderStateGuard::kCapabilities) gl_.Disable(cap);
    gl_.Disable(GL_BLEND);         // every draw buffer
    gl_.Disable(GL_SCISSOR_TEST);  // every viewport
    gl_.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl_.DepthMask(GL_TRUE);
    gl_.DepthRange(0.0, 1.0);  // gl_FragDepth is clamped to the depth range
    gl_.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    gl_.BindVertexArray(vao_.id());
    bind_vertex_buffers();
    handoff_ = Handoff{};
}

void RenderContext::bind_vertex_buffers() {
    pf_gl_buffers b{};
    sim_.gl_buffers(b);
    gl_.BindVertexBuffer(PF_ATTR_POSITION, b.positions, 0, GLsizei(b.stride));
    gl_.BindVertexBuffer(PF_ATTR_VELOCITY, b.velocities, 0, GLsizei(b.stride));
}

void RenderContext::run(const std::vector<RenderPass>& passes, const RenderFrame& frame) {
    for (const RenderPass& pass : passes) {
        const gl::DebugGroup group(gl_, (std::string("pflip/") + render_pass_name(pass.timer)).c_str());
        timers_.begin_pass(pass.timer);
        pass.run(*this, frame);
        timers_.end_pass();
    }
}

void RenderContext::bind_texture(GLuint unit, GLenum target, GLuint texture, bool linear) {
    gl_.ActiveTexture(GL_TEXTURE0 + unit);
    gl_.BindTexture(target, texture);
    gl_.BindSampler(unit, linear ? linear_.id() : nearest_.id());
}

void RenderContext::draw_spheres() {
    gl_.BindBuffer(GL_DRAW_INDIRECT_BUFFER, sim_.count_record().id());
    gl_.DrawArraysIndirect(GL_TRIANGLE_STRIP, reinterpret_cast<const void*>(uintptr_t(PF_COUNT_STRIP_RECORD) * 4));
}

void RenderContext::draw_fullscreen() { gl_.DrawArrays(GL_TRIANGLES, 0, 3); }

void RenderContext::draw_indirect_without_attributes(GLuint record) {
    gl_.BindVertexArray(bare_vao_.id());
    gl_.BindBuffer(GL_DRAW_INDIRECT_BUFFER, record);
    gl_.DrawArraysIndirect(GL_TRIANGLES, nullptr);
    gl_.BindVertexArray(vao_.id());
}

bool RenderContext::vertex_storage_buffers() {
    if (vertex_storage_blocks_ < 0) gl_.GetIntegerv(GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS, &vertex_storage_blocks_);
    return vertex_storage_blocks_ > 0;
}

void RenderContext::dispatch_screen(int width, int height) {
    gl_.DispatchCompute(GLuint(ceil_div(width, PF_RENDER_TILE)), GLuint(ceil_div(height, PF_RENDER_TILE)), 1);
    // Image stores are read next by texelFetch (or, after SHADE, by the resolve draw).
    gl_.MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void RenderContext::dispatch_particles(GLuint program) {
    const uint32_t n = sim_.particle_count();
    gl_.UseProgram(program);
    gl_.ProgramUniform1ui(program, PF_LOC_SPLAT_COUNT, n);
    if (n > 0) {  // no particles: no groups (and no division by zero groups per row)
        const int64_t groups = (int64_t(n) + PF_SPLAT_WORKGROUP - 1) / PF_SPLAT_WORKGROUP;
        const int64_t gx = std::min<int64_t>(groups, 65535), gy = (groups + gx - 1) / gx;
        gl_.DispatchCompute(GLuint(gx), GLuint(gy), 1);
    }
    gl_.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace pf
