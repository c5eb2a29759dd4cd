// Surface tension (PF_FEATURE_SURFACE_TENSION): the pressure jump sigma * kappa across the free
// surface, imposed the ghost-fluid way (Kang, Fedkiw & Liu 2000). Per substep, after the cells are
// classified and before the pressure solve, three grid passes (shaders/effects/surface_tension/): a
// liquid fraction per cell from the P2G weights (st_fraction.comp), smoothed (st_liquid.comp), then
// per liquid cell beside air the curvature of that field and the jump's term of the velocity
// update on its faces to air, added ahead of the solve (st_force.comp). Explicit in time: the substep stays below
// Brackbill's capillary limit (cfl_bound). Pass list entry "surface_tension" in the
// PF_PASS_GRID_FORCES group (docs/effects.md, docs/design.md §9.9).
#pragma once
#include "sim/effects/effect.h"

namespace pf {

// Tension finite and within 0..kMaxTension N/m; PF_OK or PF_ERROR_INVALID_ARGUMENT logged with
// `fn` first. Also checks a snapshot's value on restore. (surface_tension_api.cpp, with the
// entry points)
pf_result validate_surface_tension(const pf_surface_tension& t, const Log& log, const char* fn);

class SurfaceTensionEffect final : public Effect {
public:
    explicit SurfaceTensionEffect(const pf_sim_desc& desc);
    static constexpr uint32_t kFeature = PF_FEATURE_SURFACE_TENSION;
    static constexpr float kMaxTension = 1000.0f;  // N/m
    uint32_t feature() const override { return kFeature; }
    const char* name() const override { return "surface_tension"; }
    uint32_t stages() const override { return stage_bit(EffectStage::after_classify); }
    pf_result init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) override;
    std::vector<gl::ProgramId> programs() const override;
    void begin_step() override {}
    void begin_frame(const FrameInfo& frame) override { frame_dt_ = frame.frame_dt; }
    void run(EffectStage stage, PassRunner& runner, const EffectBuffers& buffers) override;
    // It turns surface energy into motion whenever its tension is above zero.
    bool does_work() const override { return settings_.tension > 0.0f; }
    // Capillary waves a cell long stay stable below dt = sqrt(rho_mean dx^3 / (2 pi sigma)) with
    // rho_mean the mean of the liquid's and the air's densities, rho / 2 (Brackbill, Kothe &
    // Zemach 1992, eq. 61); the substep is kept at kLimitShare of it. At the whole limit a drop in
    // zero gravity grew unstable, at 0.7 a capillary wave gained energy; at half both hold
    // (docs/notes/2026-11-27-surface-tension-choices.md).
    static constexpr float kLimitShare = 0.5f;
    CflBound cfl_bound(float speed) const override;
    // The tension a substep of dt seconds is stable at: settings().tension, or less when
    // max_substeps kept the substep above the limit (the step is flagged PF_FLAG_SUBSTEPS_CLAMPED).
    float stable_tension(float dt) const;
    void save_state(ByteWriter& out) const override { out.put(settings_); }
    pf_result restore_state(ByteReader& in, const Log& log, const char* fn) override;

    // pf_set_surface_tension (validated).
    void set(const pf_surface_tension& t) { settings_ = t; }
    const pf_surface_tension& settings() const { return settings_; }

private:
    uint64_t cells_ = 0;
    float density_ = 1000.0f;  // kg/m^3
    float dx_ = 0.0f;          // m
    float frame_dt_ = 0.0f;    // this step's, s
    pf_surface_tension settings_{};
    gl::Buffer fraction_, liquid_;  // per cell: the liquid fraction, raw and smoothed (float)
    StatId stat_ = 0;
};

}  // namespace pf
