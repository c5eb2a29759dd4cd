// The C API of force fields (PF_FEATURE_FORCE_FIELDS): defaults, validation, entry points.
#include <cmath>
#include <string>

#include "api/entry.h"
#include "api/field_checks.h"
#include "api/validate.h"
#include "sim/effects/force_fields/force_fields.h"

namespace {

pf_force_field full_default_force_field() {
    pf_force_field f{};
    f.struct_size = uint32_t(sizeof(pf_force_field));
    f.type = PF_FORCE_FIELD_DIRECTIONAL;
    f.radius = 1.0f;
    return f;
}

}  // namespace

namespace pf {

// Every field finite; a known type; drag >= 0 (directional); radius > 0 and, for a vortex, a
// non-zero axis (the others).
pf_result validate_force_field(const pf_force_field& f, const Log& log, const char* fn) {
    auto bad = [&](const std::string& what) { return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what); };
    if (enum_bits(f.type) >= PF_FORCE_FIELD_TYPE_COUNT)
        return bad("unknown force field type " + std::to_string(int32_t(enum_bits(f.type))));
    if (!finite3(f.position) || !finite3(f.vector) || !std::isfinite(f.strength) || !std::isfinite(f.radius) ||
        !std::isfinite(f.drag))
        return bad("every field of the force field must be finite");
    if (f.type == PF_FORCE_FIELD_DIRECTIONAL) {
        if (f.drag < 0.0f) return bad("drag must be >= 0, got " + number_string(f.drag));
        return PF_OK;
    }
    if (!(f.radius > 0.0f)) return bad("radius must be > 0, got " + number_string(f.radius));
    if (f.type == PF_FORCE_FIELD_VORTEX) {
        const double n2 = double(f.vector[0]) * f.vector[0] + double(f.vector[1]) * f.vector[1] + double(f.vector[2]) * f.vector[2];
        if (!(n2 > 1e-20)) return bad("a vortex needs a non-zero axis (vector)");
    }
    return PF_OK;
}

}  // namespace pf

namespace {
// validate_force_field as pf::effect_object_call calls it.
pf_result validate_force_field_of(const pf_force_field& in, const pf::Simulation& s, const char* fn) {
    return pf::validate_force_field(in, s.log(), fn);
}
}  // namespace

extern "C" {

pf_result pf_init_force_field(pf_force_field* out, uint32_t struct_size) {
    return pf::init_struct(out, struct_size, full_default_force_field(), "pf_init_force_field");
}

pf_result pf_add_force_field(pf_sim* handle, const pf_force_field* field, uint32_t* out_id) {
    return pf::effect_object_call(handle, field, "pf_add_force_field", "field", full_default_force_field(),
                                  validate_force_field_of,
                                  [&](pf::Simulation& s, const pf_force_field& in) {
                                      return s.effect<pf::ForceFieldsEffect>().edit().add_checked(
                                          in, out_id, s.log(), "pf_add_force_field", "force fields");
                                  });
}

pf_result pf_set_force_field(pf_sim* handle, uint32_t id, const pf_force_field* field) {
    return pf::effect_object_call(handle, field, "pf_set_force_field", "field", full_default_force_field(),
                                  validate_force_field_of,
                                  [&](pf::Simulation& s, const pf_force_field& in) {
                                      return s.effect<pf::ForceFieldsEffect>().edit().set_checked(id, in, s.log(),
                                                                                                  "pf_set_force_field");
                                  });
}

pf_result pf_remove_force_field(pf_sim* handle, uint32_t id) {
    return pf::effect_call(handle, "pf_remove_force_field", [&](pf::Simulation& s) {
        return s.effect<pf::ForceFieldsEffect>().edit().remove_checked(id, s.log(), "pf_remove_force_field");
    });
}

}  // extern "C"
