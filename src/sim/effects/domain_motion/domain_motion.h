// Domain motion (PF_FEATURE_DOMAIN_MOTION): the engine places and moves the whole domain (a
// tank on a ship, a glass in a hand) with pf_set_domain_motion. The liquid is simulated in the
// domain's own frame; at the start of each step the host turns the motion into the frame's
// apparent accelerations (gravity turned into the frame, the linear acceleration and the
// angular acceleration from the change of the velocities since the previous step), and one pass
// per substep right after gravity adds them with the centrifugal and Coriolis terms
// (shaders/effects/domain_motion/domain_forces.comp; pass list entry "domain_motion" in the
// PF_PASS_GRID_FORCES group). The renderer draws the domain at its pose (docs/design.md §9.5).
#pragma once
#include <glm/glm.hpp>

#include "sim/effects/effect.h"

namespace pf {

// A domain motion's arguments: every field finite, |angular_velocity| <= 1000 rad/s; PF_OK or
// PF_ERROR_INVALID_ARGUMENT logged with `fn` first. Also checks a snapshot's motion on restore.
// (domain_motion_api.cpp, with the entry points)
pf_result validate_domain_motion(const pf_domain_motion& motion, const Log& log, const char* fn);

class DomainMotionEffect final : public Effect {
public:
    explicit DomainMotionEffect(const pf_sim_desc& desc);
    static constexpr uint32_t kFeature = PF_FEATURE_DOMAIN_MOTION;
    uint32_t feature() const override { return kFeature; }
    const char* name() const override { return "domain_motion"; }
    uint32_t stages() const override {
        return stage_bit(EffectStage::after_grid_forces);
    }
    pf_result init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) override;
    std::vector<gl::ProgramId> programs() const override;
    void begin_frame(const FrameInfo& frame) override;
    void begin_step() override {}
    void run(EffectStage stage, PassRunner& runner, const EffectBuffers& buffers) override;
    // The frame adds energy to the liquid whenever it is not an inertial one at rest in gravity.
    bool does_work() const override { return moving_; }
    // The motion, the previous step's motion (the next acceleration) and whether there is one.
    void save_state(ByteWriter& out) const override;
    pf_result restore_state(ByteReader& in, const Log& log, const char* fn) override;

    // pf_set_domain_motion (validated); the next step's accelerations follow from it.
    void set(const pf_domain_motion& motion) { motion_ = motion; }
    const pf_domain_motion& motion() const { return motion_; }
    // The next step's accelerations start from zero.
    void turned_on() override { has_previous_ = false; }
    // Domain -> world transform of the current pose (the renderer's model matrix).
    glm::mat4 domain_to_world() const override;
    // params.gravity (world), which the frame turns.
    void params_changed(const pf_sim_params& params) override {
        gravity_ = glm::dvec3(params.gravity[0], params.gravity[1], params.gravity[2]);
    }
    // The largest apparent acceleration it may add for liquid at most `speed` m/s.
    CflBound cfl_bound(float speed) const override { return {max_acceleration(speed), 0.0f}; }

private:
    // The largest apparent acceleration it may add, m/s^2, for liquid at most `speed` m/s.
    float max_acceleration(float speed) const;

    glm::dvec3 gravity_;        // params.gravity of the step (world)
    double reach_ = 0.0;        // farthest domain point from the frame's origin, m
    pf_domain_motion motion_{};
    pf_domain_motion previous_{};  // the motion of the previous step
    bool has_previous_ = false;
    bool moving_ = false;
    glm::vec3 linear_{0.0f}, omega_{0.0f}, alpha_{0.0f};  // this step's, in the domain's axes
    StatId stat_ = 0;
};

}  // namespace pf
