// The C API of viscosity (PF_FEATURE_VISCOSITY): defaults, validation, entry points.
#include <cmath>
#include <string>

#include "api/entry.h"
#include "api/field_checks.h"
#include "api/validate.h"
#include "sim/effects/viscosity/viscosity.h"

namespace {

pf_viscosity full_default_viscosity() {
    pf_viscosity v{};
    v.struct_size = uint32_t(sizeof(pf_viscosity));
    v.viscosity = 1.0f;
    v.iterations = 60;
    v.tolerance = 1e-3f;
    v.free_slip = 0;
    v.coupling_rounds = 1;
    return v;
}

}  // namespace

namespace pf {

pf_result validate_viscosity(const pf_viscosity& v, const Log& log, const char* fn) {
    const std::string f = std::string(fn) + ": ";
    if (!std::isfinite(v.viscosity) || v.viscosity <= 0.0f || v.viscosity > ViscosityEffect::kMaxViscosity)
        return log.error(PF_ERROR_INVALID_ARGUMENT, f + "viscosity = " + number_string(v.viscosity) +
                                                        " Pa s must be finite, above 0 and at most 1e5");
    if (v.iterations < 1 || v.iterations > 1000)
        return log.error(PF_ERROR_INVALID_ARGUMENT,
                         f + "iterations = " + std::to_string(v.iterations) + " must be within 1..1000");
    if (!std::isfinite(v.tolerance) || v.tolerance < 1e-8f || v.tolerance > 0.5f)
        return log.error(PF_ERROR_INVALID_ARGUMENT,
                         f + "tolerance = " + number_string(v.tolerance) + " must be within 1e-8..0.5");
    if (v.free_slip > 1)
        return log.error(PF_ERROR_INVALID_ARGUMENT,
                         f + "free_slip = " + std::to_string(v.free_slip) + " must be 0 or 1");
    if (v.coupling_rounds < 1 || v.coupling_rounds > ViscosityEffect::kMaxCouplingRounds)
        return log.error(PF_ERROR_INVALID_ARGUMENT, f + "coupling_rounds = " + std::to_string(v.coupling_rounds) +
                                                        " must be within 1.." + std::to_string(ViscosityEffect::kMaxCouplingRounds));
    return PF_OK;
}

}  // namespace pf

namespace {
// validate_viscosity as pf::effect_object_call calls it.
pf_result validate_of(const pf_viscosity& in, const pf::Simulation& s, const char* fn) {
    return pf::validate_viscosity(in, s.log(), fn);
}
}  // namespace

extern "C" {

pf_result pf_init_viscosity(pf_viscosity* out, uint32_t struct_size) {
    return pf::init_struct(out, struct_size, full_default_viscosity(), "pf_init_viscosity");
}

pf_result pf_set_viscosity(pf_sim* handle, const pf_viscosity* viscosity) {
    return pf::effect_object_call(handle, viscosity, "pf_set_viscosity", "viscosity", full_default_viscosity(),
                                  validate_of, [](pf::Simulation& s, const pf_viscosity& in) {
                                      return s.effect<pf::ViscosityEffect>().set(in, s.log(), "pf_set_viscosity");
                                  });
}

pf_result pf_get_viscosity(const pf_sim* handle, pf_viscosity* out) {
    PF_ENTRY(sim, handle, "pf_get_viscosity");
    if (!out) return sim->impl->log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_viscosity: out must not be NULL");
    const pf::Simulation& s = *sim->impl;
    return pf::write_output(out, s.effect<pf::ViscosityEffect>().settings(), s.log(), "pf_get_viscosity");
}

}  // extern "C"
