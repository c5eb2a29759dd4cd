// The C API of sinks (PF_FEATURE_SINKS): defaults, validation, entry points.
#include <cmath>
#include <string>

#include "api/entry.h"
#include "api/field_checks.h"
#include "api/validate.h"
#include "sim/effects/sinks/sinks.h"

namespace {

pf_sink full_default_sink() {
    pf_sink k{};
    k.struct_size = uint32_t(sizeof(pf_sink));
    k.shape = PF_SINK_BOX;
    k.rotation[3] = 1.0f;
    k.half_extents[0] = k.half_extents[1] = k.half_extents[2] = 0.1f;
    k.radius = 0.1f;
    return k;
}

}  // namespace

namespace pf {

// Every field finite; a known shape with positive sizes; the sink overlaps the domain.
pf_result validate_sink(const pf_sink& k, const pf_sim_desc& d, const Log& log, const char* fn) {
    auto bad = [&](const std::string& what) { return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what); };
    if (enum_bits(k.shape) >= PF_SINK_SHAPE_COUNT)
        return bad("unknown sink shape " + std::to_string(int32_t(enum_bits(k.shape))));
    if (!finite3(k.position) || !finite4(k.rotation) || !finite3(k.half_extents) || !std::isfinite(k.radius))
        return bad("every field of the sink must be finite");
    double half[3] = {k.radius, k.radius, k.radius};
    if (k.shape == PF_SINK_BOX) {
        for (int a = 0; a < 3; ++a) {
            if (!(k.half_extents[a] > 0.0f))
                return bad("half_extents[" + std::to_string(a) + "] must be > 0, got " + number_string(k.half_extents[a]));
            half[a] = k.half_extents[a];
        }
    } else if (!(k.radius > 0.0f)) {
        return bad("radius must be > 0, got " + number_string(k.radius));
    }
    double lo[3], hi[3];
    shape_bounds(k.position, k.rotation, half, lo, hi);
    for (int a = 0; a < 3; ++a) {
        const double dlo = d.origin[a], dhi = d.origin[a] + double(d.cell_size) * d.grid_size[a];
        if (hi[a] <= dlo || lo[a] >= dhi) return bad("the sink does not overlap the domain (axis " + std::to_string(a) + ")");
    }
    return PF_OK;
}

}  // namespace pf

namespace {
// validate_sink as pf::effect_object_call calls it.
pf_result validate_sink_of(const pf_sink& in, const pf::Simulation& s, const char* fn) {
    return pf::validate_sink(in, s.desc(), s.log(), fn);
}
}  // namespace

extern "C" {

pf_result pf_init_sink(pf_sink* out, uint32_t struct_size) {
    return pf::init_struct(out, struct_size, full_default_sink(), "pf_init_sink");
}

pf_result pf_add_sink(pf_sim* handle, const pf_sink* sink, uint32_t* out_id) {
    return pf::effect_object_call(handle, sink, "pf_add_sink", "sink", full_default_sink(), validate_sink_of,
                                  [&](pf::Simulation& s, const pf_sink& in) {
                                      return s.effect<pf::SinksEffect>().edit().add_checked(in, out_id, s.log(),
                                                                                            "pf_add_sink", "sinks");
                                  });
}

pf_result pf_set_sink(pf_sim* handle, uint32_t id, const pf_sink* sink) {
    return pf::effect_object_call(handle, sink, "pf_set_sink", "sink", full_default_sink(), validate_sink_of,
                                  [&](pf::Simulation& s, const pf_sink& in) {
                                      return s.effect<pf::SinksEffect>().edit().set_checked(id, in, s.log(), "pf_set_sink");
                                  });
}

pf_result pf_remove_sink(pf_sim* handle, uint32_t id) {
    return pf::effect_call(handle, "pf_remove_sink", [&](pf::Simulation& s) {
        return s.effect<pf::SinksEffect>().edit().remove_checked(id, s.log(), "pf_remove_sink");
    });
}

}  // extern "C"
