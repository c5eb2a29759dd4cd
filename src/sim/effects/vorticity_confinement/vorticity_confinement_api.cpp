// The C API of vorticity confinement (PF_FEATURE_VORTICITY_CONFINEMENT): defaults, validation,
// entry points.
#include <cmath>
#include <string>

#include "api/entry.h"
#include "api/field_checks.h"
#include "api/validate.h"
#include "sim/effects/vorticity_confinement/vorticity_confinement.h"

namespace {

pf_vorticity_confinement full_default_vorticity_confinement() {
    pf_vorticity_confinement c{};
    c.struct_size = uint32_t(sizeof(pf_vorticity_confinement));
    c.strength = 0.2f;
    return c;
}

}  // namespace

namespace pf {

pf_result validate_vorticity_confinement(const pf_vorticity_confinement& c, const Log& log, const char* fn) {
    if (!std::isfinite(c.strength) || c.strength < 0.0f || c.strength > 1.0f)
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": strength = " + number_string(c.strength) +
                                                        " must be finite and within 0..1");
    return PF_OK;
}

}  // namespace pf

namespace {
// validate_vorticity_confinement as pf::effect_object_call calls it.
pf_result validate_of(const pf_vorticity_confinement& in, const pf::Simulation& s, const char* fn) {
    return pf::validate_vorticity_confinement(in, s.log(), fn);
}
}  // namespace

extern "C" {

pf_result pf_init_vorticity_confinement(pf_vorticity_confinement* out, uint32_t struct_size) {
    return pf::init_struct(out, struct_size, full_default_vorticity_confinement(), "pf_init_vorticity_confinement");
}

pf_result pf_set_vorticity_confinement(pf_sim* handle, const pf_vorticity_confinement* confinement) {
    return pf::effect_object_call(handle, confinement, "pf_set_vorticity_confinement", "confinement",
                                  full_default_vorticity_confinement(), validate_of,
                                  [](pf::Simulation& s, const pf_vorticity_confinement& in) {
                                      s.effect<pf::VorticityConfinementEffect>().set(in);
                                      return PF_OK;
                                  });
}

pf_result pf_get_vorticity_confinement(const pf_sim* handle, pf_vorticity_confinement* out) {
    PF_ENTRY(sim, handle, "pf_get_vorticity_confinement");
    if (!out)
        return sim->impl->log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_vorticity_confinement: out must not be NULL");
    const pf::Simulation& s = *sim->impl;
    return pf::write_output(out, s.effect<pf::VorticityConfinementEffect>().settings(), s.log(),
                            "pf_get_vorticity_confinement");
}

}  // extern "C"
