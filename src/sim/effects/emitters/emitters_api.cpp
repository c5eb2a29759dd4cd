// The C API of emitters (PF_FEATURE_EMITTERS): defaults, validation, entry points.
#include <cmath>
#include <string>

#include "api/entry.h"
#include "api/field_checks.h"
#include "api/validate.h"
#include "sim/effects/emitters/emitters.h"

namespace {

pf_emitter full_default_emitter() {
    pf_emitter e{};
    e.struct_size = uint32_t(sizeof(pf_emitter));
    e.shape = PF_EMITTER_SPHERE;
    e.rotation[3] = 1.0f;
    e.half_extents[0] = e.half_extents[1] = e.half_extents[2] = 0.1f;
    e.radius = 0.1f;
    e.rate_unit = PF_RATE_PARTICLES_PER_SECOND;
    return e;
}

}  // namespace

namespace pf {

// Every field finite; known shape and rate unit; sizes positive, rate >= 0; the emitter lies
// inside the domain and emits no faster than desc.max_speed.
pf_result validate_emitter(const pf_emitter& e, const pf_sim_desc& d, const Log& log, const char* fn) {
    auto bad = [&](const std::string& what) { return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what); };
    if (enum_bits(e.shape) >= PF_EMITTER_SHAPE_COUNT)
        return bad("unknown emitter shape " + std::to_string(int32_t(enum_bits(e.shape))));
    if (enum_bits(e.rate_unit) >= PF_RATE_UNIT_COUNT)
        return bad("unknown rate unit " + std::to_string(int32_t(enum_bits(e.rate_unit))));
    if (!finite3(e.position) || !finite4(e.rotation) || !finite3(e.half_extents) || !std::isfinite(e.radius) ||
        !finite3(e.velocity) || !std::isfinite(e.rate))
        return bad("every field of the emitter must be finite");
    double half[3] = {e.radius, e.radius, e.radius};
    if (e.shape == PF_EMITTER_BOX) {
        for (int a = 0; a < 3; ++a) {
            if (!(e.half_extents[a] > 0.0f))
                return bad("half_extents[" + std::to_string(a) + "] must be > 0, got " + number_string(e.half_extents[a]));
            half[a] = e.half_extents[a];
        }
    } else if (!(e.radius > 0.0f)) {
        return bad("radius must be > 0, got " + number_string(e.radius));
    }
    if (e.shape == PF_EMITTER_DISC) half[1] = 0.0;  // a disc facing local +y
    if (!(e.rate >= 0.0f)) return bad("rate must be >= 0, got " + number_string(e.rate));
    const double speed = std::sqrt(double(e.velocity[0]) * e.velocity[0] + double(e.velocity[1]) * e.velocity[1] +
                                   double(e.velocity[2]) * e.velocity[2]);
    if (speed > d.max_speed)
        return bad("|velocity| = " + number_string(float(speed)) + " exceeds desc.max_speed (" +
                   number_string(d.max_speed) + ")");
    double lo[3], hi[3];
    shape_bounds(e.position, e.rotation, half, lo, hi);
    for (int a = 0; a < 3; ++a) {
        const double dlo = d.origin[a], dhi = d.origin[a] + double(d.cell_size) * d.grid_size[a];
        if (lo[a] < dlo || hi[a] > dhi) {
            return bad("the emitter reaches outside the domain on axis " + std::to_string(a) + " ([" +
                       number_string(float(lo[a])) + ", " + number_string(float(hi[a])) + "] not within [" +
                       number_string(float(dlo)) + ", " + number_string(float(dhi)) + "])");
        }
    }
    return PF_OK;
}

}  // namespace pf

namespace {
// validate_emitter as pf::effect_object_call calls it.
pf_result validate_emitter_of(const pf_emitter& in, const pf::Simulation& s, const char* fn) {
    return pf::validate_emitter(in, s.desc(), s.log(), fn);
}
}  // namespace

extern "C" {

pf_result pf_init_emitter(pf_emitter* out, uint32_t struct_size) {
    return pf::init_struct(out, struct_size, full_default_emitter(), "pf_init_emitter");
}

pf_result pf_add_emitter(pf_sim* handle, const pf_emitter* emitter, uint32_t* out_id) {
    return pf::effect_object_call(handle, emitter, "pf_add_emitter", "emitter", full_default_emitter(), validate_emitter_of,
                                  [&](pf::Simulation& s, const pf_emitter& in) {
                                      return s.effect<pf::EmittersEffect>().list().add_checked(
                                          pf::EmittersEffect::Emitter{in, 0.0}, out_id, s.log(), "pf_add_emitter",
                                          "emitters");
                                  });
}

pf_result pf_set_emitter(pf_sim* handle, uint32_t id, const pf_emitter* emitter) {
    return pf::effect_object_call(handle, emitter, "pf_set_emitter", "emitter", full_default_emitter(), validate_emitter_of,
                                  [&](pf::Simulation& s, const pf_emitter& in) {
                                      // Keeps the emitter's owed fraction of a particle (set, not set_checked).
                                      if (s.effect<pf::EmittersEffect>().set(id, in)) return PF_OK;
                                      return pf::EmittersEffect::List::unknown_id(id, s.log(), "pf_set_emitter");
                                  });
}

pf_result pf_remove_emitter(pf_sim* handle, uint32_t id) {
    return pf::effect_call(handle, "pf_remove_emitter", [&](pf::Simulation& s) {
        return s.effect<pf::EmittersEffect>().list().remove_checked(id, s.log(), "pf_remove_emitter");
    });
}

}  // extern "C"
