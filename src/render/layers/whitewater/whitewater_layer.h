// Whitewater (PF_FEATURE_WHITEWATER) as pf_render_ssf draws it after the liquid surface: every
// live whitewater particle a soft lit sprite blended over the engine's target, hidden behind
// the scene and seen through the liquid below its surface (shaders/render/whitewater/). It
// reads the scene and liquid depths the liquid surface layer leaves in the render context, so
// it is drawn only with that layer, in the same call.
#pragma once
#include "render/render_layer.h"

namespace pf {

class WhitewaterLayer final : public RenderLayer {
public:
    pf_result prepare(RenderContext& context, const RenderFrame& frame) override;
    void fill(const RenderFrame& frame, RenderUniforms& u) const override;
    std::vector<RenderPass> passes(const RenderFrame& frame) override;

private:
    void draw(RenderContext& c, const RenderFrame& f);
    GLuint sprites_ = 0;
};

}  // namespace pf
