// The C API of surface tension (PF_FEATURE_SURFACE_TENSION): defaults, validation, entry points.
#include <cmath>
#include <string>

#include "api/entry.h"
#include "api/field_checks.h"
#include "api/validate.h"
#include "sim/effects/surface_tension/surface_tension.h"

namespace {

pf_surface_tension full_default_surface_tension() {
    pf_surface_tension t{};
    t.struct_size = uint32_t(sizeof(pf_surface_tension));
    t.tension = 0.072f;
    return t;
}

}  // namespace

namespace pf {

pf_result validate_surface_tension(const pf_surface_tension& t, const Log& log, const char* fn) {
    if (!std::isfinite(t.tension) || t.tension < 0.0f || t.tension > SurfaceTensionEffect::kMaxTension)
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": tension = " + number_string(t.tension) +
                                                        " N/m must be finite and within 0..1000");
    return PF_OK;
}

}  // namespace pf

namespace {
// validate_surface_tension as pf::effect_object_call calls it.
pf_result validate_of(const pf_surface_tension& in, const pf::Simulation& s, const char* fn) {
    return pf::validate_surface_tension(in, s.log(), fn);
}
}  // namespace

extern "C" {

pf_result pf_init_surface_tension(pf_surface_tension* out, uint32_t struct_size) {
    return pf::init_struct(out, struct_size, full_default_surface_tension(), "pf_init_surface_tension");
}

pf_result pf_set_surface_tension(pf_sim* handle, const pf_surface_tension* tension) {
    return pf::effect_object_call(handle, tension, "pf_set_surface_tension", "tension", full_default_surface_tension(),
                                  validate_of, [](pf::Simulation& s, const pf_surface_tension& in) {
                                      s.effect<pf::SurfaceTensionEffect>().set(in);
                                      return PF_OK;
                                  });
}

pf_result pf_get_surface_tension(const pf_sim* handle, pf_surface_tension* out) {
    PF_ENTRY(sim, handle, "pf_get_surface_tension");
    if (!out) return sim->impl->log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_surface_tension: out must not be NULL");
    const pf::Simulation& s = *sim->impl;
    return pf::write_output(out, s.effect<pf::SurfaceTensionEffect>().settings(), s.log(), "pf_get_surface_tension");
}

}  // extern "C"
