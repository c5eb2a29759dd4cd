// The C API of whitewater (PF_FEATURE_WHITEWATER): defaults, validation, entry points.
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "api/entry.h"
#include "api/field_checks.h"
#include "api/validate.h"
#include "sim/effects/whitewater/whitewater.h"

namespace {

pf_whitewater full_default_whitewater() {
    pf_whitewater w{};
    w.struct_size = uint32_t(sizeof(pf_whitewater));
    w.capacity = 262144;
    w.trapped_air_rate = 40.0f;
    w.wave_crest_rate = 40.0f;
    w.trapped_air_range[0] = 1.0f, w.trapped_air_range[1] = 6.0f;
    w.wave_crest_range[0] = 0.25f, w.wave_crest_range[1] = 1.0f;
    w.energy_range[0] = 0.5f, w.energy_range[1] = 5.0f;
    w.lifetime[0] = 1.0f, w.lifetime[1] = 3.0f;
    w.bubble_buoyancy = 2.0f;
    w.bubble_drag = 20.0f;
    w.spray_drag = 0.5f;
    return w;
}

// A finite value within [lo, hi], or an error naming the field.
pf_result check_within(float value, float lo, float hi, const char* field, const pf::Log& log, const char* fn) {
    if (std::isfinite(value) && value >= lo && value <= hi) return PF_OK;
    return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + field + " = " + pf::number_string(value) +
                                                    " must be finite and within " + pf::number_string(lo) + ".." +
                                                    pf::number_string(hi));
}

// A range [lo, hi] with 0 <= lo < hi, both finite.
pf_result check_range(const float r[2], const char* field, const pf::Log& log, const char* fn) {
    if (std::isfinite(r[0]) && std::isfinite(r[1]) && r[0] >= 0.0f && r[0] < r[1]) return PF_OK;
    return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + field + " = {" + pf::number_string(r[0]) + ", " +
                                                    pf::number_string(r[1]) +
                                                    "} must be finite with 0 <= [0] < [1]");
}

}  // namespace

namespace pf {

pf_result validate_whitewater(const pf_whitewater& w, const Log& log, const char* fn) {
    if (w.capacity < 1 || w.capacity > WhitewaterEffect::kMaxCapacity)
        return log.error(PF_ERROR_INVALID_ARGUMENT,
                         std::string(fn) + ": capacity = " + std::to_string(w.capacity) + " must be within 1..2^23");
    for (auto [value, lo, hi, field] : {std::tuple{w.trapped_air_rate, 0.0f, 1e4f, "trapped_air_rate"},
                                        std::tuple{w.wave_crest_rate, 0.0f, 1e4f, "wave_crest_rate"},
                                        std::tuple{w.bubble_buoyancy, 0.0f, 100.0f, "bubble_buoyancy"},
                                        std::tuple{w.bubble_drag, 0.0f, 1000.0f, "bubble_drag"},
                                        std::tuple{w.spray_drag, 0.0f, 1000.0f, "spray_drag"}}) {
        if (pf_result r = check_within(value, lo, hi, field, log, fn); r != PF_OK) return r;
    }
    for (auto [range, field] : {std::pair{w.trapped_air_range, "trapped_air_range"},
                                std::pair{w.wave_crest_range, "wave_crest_range"},
                                std::pair{w.energy_range, "energy_range"}}) {
        if (pf_result r = check_range(range, field, log, fn); r != PF_OK) return r;
    }
    if (!(std::isfinite(w.lifetime[0]) && std::isfinite(w.lifetime[1]) && w.lifetime[0] > 0.0f &&
          w.lifetime[0] <= w.lifetime[1] && w.lifetime[1] <= 1000.0f))
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": lifetime = {" + number_string(w.lifetime[0]) +
                                                        ", " + number_string(w.lifetime[1]) +
                                                        "} must be finite with 0 < [0] <= [1] <= 1000 s");
    return PF_OK;
}

}  // namespace pf

namespace {
// validate_whitewater as pf::effect_object_call calls it.
pf_result validate_of(const pf_whitewater& in, const pf::Simulation& s, const char* fn) {
    return pf::validate_whitewater(in, s.log(), fn);
}
}  // namespace

extern "C" {

pf_result pf_init_whitewater(pf_whitewater* out, uint32_t struct_size) {
    return pf::init_struct(out, struct_size, full_default_whitewater(), "pf_init_whitewater");
}

pf_result pf_set_whitewater(pf_sim* handle, const pf_whitewater* whitewater) {
    return pf::effect_object_call(handle, whitewater, "pf_set_whitewater", "whitewater", full_default_whitewater(),
                                  validate_of, [](pf::Simulation& s, const pf_whitewater& in) {
                                      s.effect<pf::WhitewaterEffect>().set(in);
                                      return PF_OK;
                                  });
}

pf_result pf_get_whitewater(const pf_sim* handle, pf_whitewater* out) {
    PF_ENTRY(sim, handle, "pf_get_whitewater");
    if (!out) return sim->impl->log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_whitewater: out must not be NULL");
    const pf::Simulation& s = *sim->impl;
    return pf::write_output(out, s.effect<pf::WhitewaterEffect>().settings(), s.log(), "pf_get_whitewater");
}

pf_result pf_get_whitewater_buffers(const pf_sim* handle, pf_whitewater_buffers* out) {
    PF_ENTRY(sim, handle, "pf_get_whitewater_buffers");
    const pf::Simulation& s = *sim->impl;
    if (!out) return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_whitewater_buffers: out must not be NULL");
    if (!(s.features() & PF_FEATURE_WHITEWATER))
        return s.log().error(PF_ERROR_INVALID_STATE, "pf_get_whitewater_buffers: PF_FEATURE_WHITEWATER is off");
    s.effect<pf::WhitewaterEffect>().buffers(*out);
    return PF_OK;
}

}  // extern "C"
