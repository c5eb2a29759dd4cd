// The render layers pflip can draw: one line each.
#include "render/layers/liquid_surface/liquid_surface_layer.h"
#include "render/layers/particles/particle_layer.h"
#include "render/layers/registry.h"
#include "render/layers/whitewater/whitewater_layer.h"

namespace pf {

std::unique_ptr<RenderLayer> make_render_layer(RenderLayerId id) {
    switch (id) {
        case RenderLayerId::liquid_surface: return std::make_unique<LiquidSurfaceLayer>();
        case RenderLayerId::particles: return std::make_unique<ParticleLayer>();
        case RenderLayerId::whitewater: return std::make_unique<WhitewaterLayer>();
        case RenderLayerId::count: break;
    }
    return nullptr;
}

}  // namespace pf
