#include "sim/effects/domain_motion/domain_motion.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/quaternion.hpp>

#include "api/validate.h"
#include "common/slots.h"

namespace pf {

namespace {
glm::dquat rotation_of(const pf_domain_motion& m) {
    glm::dquat q(m.rotation[3], m.rotation[0], m.rotation[1], m.rotation[2]);  // (w, x, y, z)
    const double n = glm::length(q);
    return n > 0.0 ? q / n : glm::dquat(1.0, 0.0, 0.0, 0.0);
}
glm::dvec3 vec(const float v[3]) { return glm::dvec3(v[0], v[1], v[2]); }
}  // namespace

DomainMotionEffect::DomainMotionEffect(const pf_sim_desc& desc) {
    motion_ = pf_default_domain_motion();
    previous_ = motion_;
    params_changed(desc.params);
    for (int corner = 0; corner < 8; ++corner) {
        glm::dvec3 c;
        for (int a = 0; a < 3; ++a) c[a] = desc.origin[a] + ((corner >> a) & 1 ? double(desc.cell_size) * desc.grid_size[a] : 0.0);
        reach_ = std::max(reach_, glm::length(c));
    }
}

std::vector<gl::ProgramId> DomainMotionEffect::programs() const {
    return {gl::ProgramId::domain_forces};
}

pf_result DomainMotionEffect::init(const gl::Api&, PassRunner& runner, const Log& log, const char* fn) {
    if (pf_result r = prepare_programs(runner, log, fn); r != PF_OK) return r;
    stat_ = runner.add_stat("domain_motion", PF_PASS_GRID_FORCES);
    return PF_OK;
}

void DomainMotionEffect::begin_frame(const FrameInfo& frame) {
    const glm::dquat q = rotation_of(motion_);
    const glm::dquat to_domain = glm::conjugate(q);
    glm::dvec3 accel(0.0), angular_accel(0.0);
    if (has_previous_ && frame.frame_dt > 0.0f) {
        accel = (vec(motion_.velocity) - vec(previous_.velocity)) / double(frame.frame_dt);
        angular_accel = (vec(motion_.angular_velocity) - vec(previous_.angular_velocity)) / double(frame.frame_dt);
    }
    previous_ = motion_;
    has_previous_ = true;
    const glm::dvec3 linear = to_domain * (gravity_ - accel) - gravity_;
    const glm::dvec3 omega = to_domain * vec(motion_.angular_velocity);
    const glm::dvec3 alpha = to_domain * angular_accel;
    linear_ = glm::vec3(linear);
    omega_ = glm::vec3(omega);
    alpha_ = glm::vec3(alpha);
    // At rest where the world is (or turned only: gravity then acts along another axis, which
    // the pass adds) the pass is skipped; otherwise the frame does work on the liquid.
    moving_ = glm::length(linear) > 0.0 || glm::length(omega) > 0.0 || glm::length(alpha) > 0.0;
}

void DomainMotionEffect::run(EffectStage stage, PassRunner& runner, const EffectBuffers& b) {
    if (stage != EffectStage::after_grid_forces || !moving_) return;
    runner.run({gl::ProgramId::domain_forces, stat_, b.layout.faces(),
                {{PF_SLOT_FACE_ACCUM, &b.face_accum}, {PF_SLOT_FACE_VEL, &b.face_vel}, {PF_SLOT_FACE_VEL_OLD, &b.face_vel_old}},
                {},
                {Uniform::vec4(PF_LOC_DOMAIN_LINEAR, linear_.x, linear_.y, linear_.z, 0.0f),
                 Uniform::vec4(PF_LOC_DOMAIN_OMEGA, omega_.x, omega_.y, omega_.z, 0.0f),
                 Uniform::vec4(PF_LOC_DOMAIN_ALPHA, alpha_.x, alpha_.y, alpha_.z, 0.0f)}});
}

void DomainMotionEffect::save_state(ByteWriter& out) const {
    out.put(motion_);
    out.put(previous_);
    out.put(uint32_t(has_previous_));
}

pf_result DomainMotionEffect::restore_state(ByteReader& in, const Log& log, const char* fn) {
    pf_domain_motion motion{}, previous{};
    uint32_t has_previous = 0;
    if (!in.get(motion) || !in.get(previous) || !in.get(has_previous))
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": the domain motion in the snapshot is truncated");
    const Log silent;
    if (validate_domain_motion(motion, silent, fn) != PF_OK || validate_domain_motion(previous, silent, fn) != PF_OK ||
        has_previous > 1)
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": the domain motion in the snapshot is invalid");
    motion_ = motion;
    previous_ = previous;
    has_previous_ = has_previous != 0;
    return PF_OK;
}

glm::mat4 DomainMotionEffect::domain_to_world() const {
    glm::dmat4 m = glm::mat4_cast(rotation_of(motion_));
    m[3] = glm::dvec4(vec(motion_.position), 1.0);
    return glm::mat4(m);
}

float DomainMotionEffect::max_acceleration(float speed) const {
    const double w = glm::length(glm::dvec3(omega_));
    return float(glm::length(glm::dvec3(linear_)) + glm::length(glm::dvec3(alpha_)) * reach_ + w * w * reach_ +
                 2.0 * w * speed);
}

}  // namespace pf
