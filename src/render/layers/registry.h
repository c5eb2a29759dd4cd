// Makes a render layer by its id (src/render/layers/registry.cpp: one line a layer).
#pragma once
#include <memory>

#include "render/render_layer.h"

namespace pf {

std::unique_ptr<RenderLayer> make_render_layer(RenderLayerId id);

}  // namespace pf
