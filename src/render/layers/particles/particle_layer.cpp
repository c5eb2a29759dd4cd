#include "render/layers/particles/particle_layer.h"

#include "common/render_slots.h"
#include "render/render_context.h"

namespace pf {

static_assert(PF_PARTICLE_COLOR_SPEED == PF_COLOR_SPEED_ID && PF_PARTICLE_COLOR_VELOCITY_X == PF_COLOR_VELOCITY_X_ID &&
                  PF_PARTICLE_COLOR_VELOCITY_Y == PF_COLOR_VELOCITY_Y_ID &&
                  PF_PARTICLE_COLOR_VELOCITY_Z == PF_COLOR_VELOCITY_Z_ID &&
                  PF_PARTICLE_COLOR_HEIGHT == PF_COLOR_HEIGHT_ID && PF_PARTICLE_COLOR_UNIFORM == PF_COLOR_UNIFORM_ID,
              "colour modes shared with GLSL");

pf_result ParticleLayer::prepare(RenderContext& c, const RenderFrame& f) {
    return c.program(gl::ProgramId::particles, f.fn, sprites_);
}

void ParticleLayer::fill(const RenderFrame& f, RenderUniforms& u) const { fill_particles(*f.particles, u); }

std::vector<RenderPass> ParticleLayer::passes(const RenderFrame&) {
    return {{PF_RENDER_PASS_PARTICLES, [this](RenderContext& c, const RenderFrame& f) {
                 const gl::Api& gl = c.gl();
                 const int32_t* v = f.camera->viewport;
                 gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, f.target->framebuffer);
                 gl.Viewport(v[0], v[1], v[2], v[3]);
                 gl.Enable(GL_DEPTH_TEST);
                 gl.DepthFunc(f.camera->depth_convention == PF_DEPTH_REVERSED_Z ? GL_GREATER : GL_LESS);
                 gl.UseProgram(sprites_);
                 c.draw_spheres();
             }}};
}

}  // namespace pf
