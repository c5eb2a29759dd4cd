// Vorticity confinement (PF_FEATURE_VORTICITY_CONFINEMENT; Fedkiw, Stam & Jensen 2001): swirls
// that the grid's interpolation smooths away are pushed to keep spinning. Per substep, after the
// cells are classified and before the pressure solve, two grid passes: the vorticity at the
// centres of liquid cells inside the liquid (shaders/effects/vorticity_confinement/vorticity.comp)
// and the confinement acceleration strength * dx * (N x w) on the faces between them
// (confinement_force.comp). Pass list entry "vorticity_confinement" in the PF_PASS_GRID_FORCES
// group (docs/effects.md).
#pragma once
#include "sim/effects/effect.h"

namespace pf {

// Strength must be finite and within 0..1 (the range measured stable, docs/effects.md); PF_OK
// or PF_ERROR_INVALID_ARGUMENT logged with `fn` first. Also checks a snapshot's value on restore.
// (vorticity_confinement_api.cpp, with the entry points)
pf_result validate_vorticity_confinement(const pf_vorticity_confinement& c, const Log& log, const char* fn);

class VorticityConfinementEffect final : public Effect {
public:
    explicit VorticityConfinementEffect(const pf_sim_desc& desc);
    static constexpr uint32_t kFeature = PF_FEATURE_VORTICITY_CONFINEMENT;
    // A bound on a curl from face velocities of at most `speed`: each of its components is two
    // differences over 2 dx of cell-centred velocities, |w| <= sqrt(3) * 2 * speed / dx.
    static constexpr float kCurlBound = 3.4641016f;
    uint32_t feature() const override { return kFeature; }
    const char* name() const override { return "vorticity_confinement"; }
    uint32_t stages() const override { return stage_bit(EffectStage::after_classify); }
    pf_result init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) override;
    std::vector<gl::ProgramId> programs() const override;
    void begin_step() override {}
    void run(EffectStage stage, PassRunner& runner, const EffectBuffers& buffers) override;
    // It adds energy whenever its strength is above zero.
    bool does_work() const override { return settings_.strength > 0.0f; }
    // |f| = strength dx |w| <= strength * kCurlBound * speed.
    CflBound cfl_bound(float speed) const override { return {settings_.strength * kCurlBound * speed, 0.0f}; }
    void save_state(ByteWriter& out) const override { out.put(settings_); }
    pf_result restore_state(ByteReader& in, const Log& log, const char* fn) override;

    // pf_set_vorticity_confinement (validated).
    void set(const pf_vorticity_confinement& c) { settings_ = c; }
    const pf_vorticity_confinement& settings() const { return settings_; }

private:
    uint64_t cells_ = 0;
    pf_vorticity_confinement settings_{};
    gl::Buffer vorticity_;  // per cell: w (xyz), |w| (w), 1/s
    StatId stat_ = 0;
};

}  // namespace pf
