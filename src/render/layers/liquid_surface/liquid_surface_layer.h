// The liquid surface of pf_render_ssf: screen-space fluid rendering over the engine's scene,
// SCENE_COPY -> THICKNESS -> DEPTH -> SMOOTH -> SHADE -> RESOLVE, with THICKNESS and DEPTH as
// compute splats or sphere sprites and SMOOTH and SHADE as compute kernels or full-screen
// fragment shaders (pf_ssf_path). Its shaders are in shaders/render/liquid_surface/.
#pragma once
#include <memory>

#include "gl/buffer.h"
#include "render/layers/liquid_surface/ssf_targets.h"
#include "render/render_layer.h"

namespace pf {

class LiquidSurfaceLayer final : public RenderLayer {
public:
    bool reads_scene() const override { return true; }
    pf_result prepare(RenderContext& context, const RenderFrame& frame) override;
    void fill(const RenderFrame& frame, RenderUniforms& u) const override;
    std::vector<RenderPass> passes(const RenderFrame& frame) override;
    // The textures; the buffers are in the simulation's memory tally (gl/memory_tally.h).
    uint64_t bytes() const override { return targets_ ? targets_->bytes() : 0; }

private:
    void scene_copy(RenderContext& c, const RenderFrame& f);
    void thickness(RenderContext& c, const RenderFrame& f);
    void depth(RenderContext& c, const RenderFrame& f);
    // Compute path of THICKNESS and DEPTH: clear + the splat of both, then their resolve.
    void splat(RenderContext& c, const RenderFrame& f);
    void splat_resolve(RenderContext& c, const RenderFrame& f);
    void smooth(RenderContext& c, const RenderFrame& f);
    void shade(RenderContext& c, const RenderFrame& f);
    void resolve(RenderContext& c, const RenderFrame& f);

    std::unique_ptr<SsfTargets> targets_;
    // Compute path: SHADE's dispatch and RESOLVE's draw records and the PF_RENDER_TILE tiles
    // holding liquid (PF_SSBO_LIQUID_TILES), sized for the largest viewport so far.
    gl::Buffer liquid_tiles_;
    // This frame's programs (raster or compute, by pf_ssf_path: the sprites of thickness_ and
    // depth_ or the splat; smooth_ 0 without a filter).
    GLuint scene_copy_ = 0, thickness_ = 0, depth_ = 0, splat_clear_ = 0, splat_ = 0, splat_resolve_ = 0, smooth_ = 0,
           shade_ = 0, resolve_ = 0;
    SsfTargets::Texture surface_ = SsfTargets::raw_depth;  // what SMOOTH left for SHADE
    // RESOLVE draws the liquid tiles (compute path, where vertex shaders may read storage
    // buffers), else a full-screen triangle.
    bool tiled_resolve_ = false;
};

}  // namespace pf
