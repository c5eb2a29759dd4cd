// The C API of domain motion (PF_FEATURE_DOMAIN_MOTION): defaults, validation, entry points.
#include <cmath>
#include <string>

#include "api/entry.h"
#include "api/field_checks.h"
#include "api/validate.h"
#include "sim/effects/domain_motion/domain_motion.h"

namespace {

pf_domain_motion full_default_domain_motion() {
    pf_domain_motion m{};
    m.struct_size = uint32_t(sizeof(pf_domain_motion));
    m.rotation[3] = 1.0f;
    return m;
}

}  // namespace

namespace pf {

// Every field finite; |angular_velocity| at most 1000 rad/s.
pf_result validate_domain_motion(const pf_domain_motion& m, const Log& log, const char* fn) {
    auto bad = [&](const std::string& what) { return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what); };
    if (!finite3(m.position) || !finite4(m.rotation) || !finite3(m.velocity) || !finite3(m.angular_velocity))
        return bad("every field of the domain motion must be finite");
    const double w = std::sqrt(double(m.angular_velocity[0]) * m.angular_velocity[0] +
                               double(m.angular_velocity[1]) * m.angular_velocity[1] +
                               double(m.angular_velocity[2]) * m.angular_velocity[2]);
    if (w > 1000.0) return bad("|angular_velocity| = " + number_string(float(w)) + " rad/s exceeds 1000");
    return PF_OK;
}

}  // namespace pf

namespace {
// validate_domain_motion as pf::effect_object_call calls it.
pf_result validate_domain_motion_of(const pf_domain_motion& in, const pf::Simulation& s, const char* fn) {
    return pf::validate_domain_motion(in, s.log(), fn);
}
}  // namespace

extern "C" {

pf_result pf_init_domain_motion(pf_domain_motion* out, uint32_t struct_size) {
    return pf::init_struct(out, struct_size, full_default_domain_motion(), "pf_init_domain_motion");
}

pf_result pf_set_domain_motion(pf_sim* handle, const pf_domain_motion* motion) {
    return pf::effect_object_call(handle, motion, "pf_set_domain_motion", "motion", full_default_domain_motion(),
                                  validate_domain_motion_of, [](pf::Simulation& s, const pf_domain_motion& in) {
                                      s.effect<pf::DomainMotionEffect>().set(in);
                                      return PF_OK;
                                  });
}

pf_result pf_get_domain_motion(const pf_sim* handle, pf_domain_motion* out) {
    PF_ENTRY(sim, handle, "pf_get_domain_motion");
    if (!out) return sim->impl->log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_domain_motion: out must not be NULL");
    const pf::Simulation& s = *sim->impl;
    return pf::write_output(out, s.effect<pf::DomainMotionEffect>().motion(), s.log(), "pf_get_domain_motion");
}

}  // extern "C"
