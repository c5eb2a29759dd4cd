// A render layer: one thing pflip draws into the engine's frame (the liquid surface, the debug
// particle view), with its own shaders, parameters and statistics. A layer is a table of render
// passes, each timed as one pf_render_pass; the renderer checks the engine's objects, sets the
// GL state every pass relies on and runs the tables of the layers a call draws. Adding a layer
// is a folder under src/render/layers/ and shaders/render/, one RenderLayerId and one line of
// make_render_layer (docs/design.md §8).
#pragma once
#include <functional>
#include <vector>

#include "gl/gl.h"
#include "pf/pf.h"
#include "render/render_uniforms.h"

namespace pf {

class RenderContext;

enum class RenderLayerId { liquid_surface, particles, whitewater, count };

// The whitewater layer's timer: past the public pf_render_pass values (pf_stats.render_gpu_ms
// has PF_RENDER_PASS_COUNT entries), reported as pf_stats.render_whitewater_gpu_ms.
constexpr pf_render_pass kRenderPassWhitewater = pf_render_pass(PF_RENDER_PASS_COUNT);
// Timers of a render call: the public passes and the whitewater layer's.
constexpr int kRenderTimers = PF_RENDER_PASS_COUNT + 1;
// A render pass's stable short name (its debug group "pflip/<name>").
inline const char* render_pass_name(pf_render_pass pass) {
    return pass == kRenderPassWhitewater ? "whitewater" : pf_render_pass_name(pass);
}

// One render call as the layers see it: the engine's camera and target (already checked), and
// the parameters of the call (with their defaults resolved; null for a layer it does not draw).
struct RenderFrame {
    const char* fn = nullptr;  // the entry point, for messages
    const pf_camera* camera = nullptr;
    const pf_render_target* target = nullptr;
    float y_sign = 1.0f;  // -1 when the engine's clip origin is GL_UPPER_LEFT
    const pf_ssf_params* ssf = nullptr;
    double particle_volume = 0.0;  // m^3 of liquid a particle stands for (the simulation's)
    // The simulation's grid and particles per cell, for the spray test (common/ssf_spray.glsl).
    struct Cells {
        float origin[3] = {0, 0, 0};
        float cell_size = 1.0f;
        int32_t dims[3] = {1, 1, 1};
        float rest_count = 8.0f;  // particles per cell at rest density
        bool current = false;     // the counts describe the particles
        GLuint counts = 0;        // GL buffer, one uint per cell
        GLuint order = 0;         // GL buffer: the live particle slots in a spatially coherent order, or 0
    } cells;
    const pf_particle_params* particles = nullptr;
    int width() const { return camera->viewport[2]; }
    int height() const { return camera->viewport[3]; }
};

// One pass of a layer: what pf_stats.render_gpu_ms times it as, and its GL work.
struct RenderPass {
    pf_render_pass timer;
    std::function<void(RenderContext&, const RenderFrame&)> run;
};

class RenderLayer {
public:
    virtual ~RenderLayer() = default;
    // Whether the layer reads the engine's scene textures (target->scene_color, scene_depth,
    // environment_cubemap), which are then checked before anything is drawn.
    virtual bool reads_scene() const { return false; }
    // Programs and targets the frame needs (compiled and allocated on first use). Errors are
    // logged with frame.fn and returned; nothing is drawn then.
    virtual pf_result prepare(RenderContext& context, const RenderFrame& frame) = 0;
    // The layer's part of the render uniforms.
    virtual void fill(const RenderFrame& frame, RenderUniforms& u) const = 0;
    // The passes of this frame, in order (they may hand results on through the layer).
    virtual std::vector<RenderPass> passes(const RenderFrame& frame) = 0;
    // GPU memory of what the layer allocated, bytes.
    virtual uint64_t bytes() const { return 0; }
};

}  // namespace pf
