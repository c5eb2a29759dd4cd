// The debug particle view of pf_render_particles: every particle a shaded sphere sprite,
// coloured by pf_particle_params.color_by and depth-tested against the engine's depth buffer.
// Its fragment shader is shaders/render/particles/particles.frag.
#pragma once
#include "render/render_layer.h"

namespace pf {

class ParticleLayer final : public RenderLayer {
public:
    pf_result prepare(RenderContext& context, const RenderFrame& frame) override;
    void fill(const RenderFrame& frame, RenderUniforms& u) const override;
    std::vector<RenderPass> passes(const RenderFrame& frame) override;

private:
    GLuint sprites_ = 0;
};

}  // namespace pf
