// Draws a simulation into the engine's frame through render layers (src/render/layers/): the
// liquid surface for pf_render_ssf, the debug particle view for pf_render_particles. Made on
// the first render call of a pf_sim and destroyed before its Simulation. Each call checks the
// engine's objects, saves the engine's GL state (restored when the call returns), fills the
// render uniforms from the camera and the layers' parameters and runs the layers' passes.
// Arguments arrive validated and with their defaults resolved (src/api/pf_render_api.cpp).
#pragma once
#include <array>
#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <memory>

#include "gl/state_guard.h"
#include "pf/pf.h"
#include "render/render_context.h"
#include "render/render_layer.h"

namespace pf {

class Simulation;

class Renderer {
public:
    explicit Renderer(const Simulation& sim);
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    pf_result render_ssf(const pf_camera& camera, const pf_render_target& target, const pf_ssf_params& params);
    pf_result render_particles(const pf_camera& camera, const pf_render_target& target,
                               const pf_particle_params& params);
    // Fills the render_* fields of pf_stats (newest finished call; never waits).
    void stats(pf_stats& out) const;

private:
    // Draws `layers`, in order, for one call whose fn, camera, target and parameters `frame` holds.
    pf_result render(RenderFrame frame, std::initializer_list<RenderLayerId> layers);
    // Checks the engine's objects and reads the clip origin into frame.y_sign.
    pf_result begin(RenderFrame& frame, bool scene);
    RenderLayer& layer(RenderLayerId id);
    pf_result finish(const char* fn, std::chrono::steady_clock::time_point started);

    const Simulation& sim_;
    gl::StateGuard::Options guard_options_{};
    int gl_version_ = 0;  // major * 10 + minor
    mutable RenderContext context_;  // its timers are polled by the const stats()
    std::array<std::unique_ptr<RenderLayer>, size_t(RenderLayerId::count)> layers_;  // made on first use
    uint64_t frames_ = 0;
    float last_cpu_ms_ = 0.0f;
};

}  // namespace pf
