#include "render/layers/whitewater/whitewater_layer.h"

#include "common/render_slots.h"
#include "render/render_context.h"
#include "sim/effects/whitewater/whitewater.h"
#include "sim/simulation.h"

namespace pf {

pf_result WhitewaterLayer::prepare(RenderContext& c, const RenderFrame& f) {
    return c.program(gl::ProgramId::whitewater_sprites, f.fn, sprites_);
}

void WhitewaterLayer::fill(const RenderFrame& f, RenderUniforms& u) const {
    u.whitewater[0] = f.ssf->whitewater_radius;
    u.whitewater[1] = f.ssf->whitewater_opacity;
}

std::vector<RenderPass> WhitewaterLayer::passes(const RenderFrame&) {
    return {{kRenderPassWhitewater, [this](RenderContext& c, const RenderFrame& f) { draw(c, f); }}};
}

void WhitewaterLayer::draw(RenderContext& c, const RenderFrame& f) {
    const gl::Api& gl = c.gl();
    const WhitewaterEffect& whitewater = c.sim().effect<WhitewaterEffect>();
    pf_whitewater_buffers b{};
    whitewater.buffers(b);
    const int32_t* v = f.camera->viewport;
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, f.target->framebuffer);
    gl.Viewport(v[0], v[1], v[2], v[3]);
    gl.Enable(GL_BLEND);
    gl.BlendEquation(GL_FUNC_ADD);
    gl.BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied
    gl.Enable(GL_FRAMEBUFFER_SRGB);
    gl.DepthMask(GL_FALSE);
    c.bind_texture(PF_TEX_SCENE_DEPTH, GL_TEXTURE_2D, c.handoff().scene_eye_depth, false);
    c.bind_texture(PF_TEX_LIQUID_DEPTH, GL_TEXTURE_2D, c.handoff().liquid_eye_depth, false);
    gl.BindVertexBuffer(PF_ATTR_POSITION, b.positions, 0, GLsizei(b.stride));
    gl.BindVertexBuffer(PF_ATTR_VELOCITY, b.velocities, 0, GLsizei(b.stride));
    gl.UseProgram(sprites_);
    gl.BindBuffer(GL_DRAW_INDIRECT_BUFFER, b.draw_indirect);
    gl.DrawArraysIndirect(GL_TRIANGLE_STRIP, reinterpret_cast<const void*>(uintptr_t(PF_WW_STRIP_RECORD) * 4));
    gl.Disable(GL_BLEND);
    gl.DepthMask(GL_TRUE);
    c.bind_vertex_buffers();  // the simulation's particles again, for any later layer
}

}  // namespace pf
