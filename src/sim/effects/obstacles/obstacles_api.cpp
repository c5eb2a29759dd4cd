// The C API of obstacles (PF_FEATURE_OBSTACLES): defaults, validation, entry points.
#include <cmath>
#include <string>

#include "api/entry.h"
#include "api/field_checks.h"
#include "api/validate.h"
#include "gl/state_guard.h"
#include "sim/effects/obstacles/obstacles.h"

namespace {

pf_obstacle full_default_obstacle() {
    pf_obstacle o{};
    o.struct_size = uint32_t(sizeof(pf_obstacle));
    o.shape = PF_OBSTACLE_BOX;
    o.rotation[3] = 1.0f;
    o.half_extents[0] = o.half_extents[1] = o.half_extents[2] = 0.1f;
    o.radius = 0.1f;
    o.sdf_scale = 1.0f;
    return o;
}

// The list entry of `obstacle`: an SDF obstacle's texture is checked (through GL) unless it is
// the one `current` (the entry it replaces, or nullptr) already had.
pf_result obstacle_entry(const pf::Simulation& s, const pf_obstacle& obstacle, const pf::ObstacleEntry* current,
                         const char* fn, pf::ObstacleEntry& out) {
    out = pf::ObstacleEntry{obstacle, false};
    if (obstacle.shape != PF_OBSTACLE_SDF) return PF_OK;
    if (current && current->obstacle.shape == PF_OBSTACLE_SDF && current->obstacle.sdf_texture == obstacle.sdf_texture) {
        out.sdf_normalized = current->sdf_normalized;
        return PF_OK;
    }
    pf::gl::StateGuard guard(s.api(), s.gl_state_options());
    return pf::check_sdf_texture(s.api(), s.log(), fn, obstacle.sdf_texture, out.sdf_normalized);
}

}  // namespace

namespace pf {

// Every field finite; a known shape; the shape's own sizes positive; an SDF has a texture.
pf_result validate_obstacle(const pf_obstacle& o, const Log& log, const char* fn) {
    auto bad = [&](const std::string& what) { return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what); };
    if (enum_bits(o.shape) >= PF_OBSTACLE_SHAPE_COUNT)
        return bad("unknown obstacle shape " + std::to_string(int32_t(enum_bits(o.shape))));
    if (!finite3(o.position) || !finite3(o.half_extents) || !finite4(o.rotation) ||
        !std::isfinite(o.radius) || !std::isfinite(o.half_height) || !std::isfinite(o.sdf_scale))
        return bad("every field of the obstacle must be finite");
    if (!finite3(o.velocity)) return bad("velocity must be finite");
    if (!finite3(o.angular_velocity)) return bad("angular_velocity must be finite");
    if (o.shape == PF_OBSTACLE_SDF) {
        if (!(o.sdf_scale > 0.0f)) return bad("sdf_scale must be finite and > 0, got " + number_string(o.sdf_scale));
        if (o.sdf_texture == 0) return bad("an SDF obstacle needs an sdf_texture (0 given)");
    }
    if (o.shape == PF_OBSTACLE_BOX || o.shape == PF_OBSTACLE_SDF) {
        for (int a = 0; a < 3; ++a) {
            if (!(o.half_extents[a] > 0.0f))
                return bad("half_extents[" + std::to_string(a) + "] must be > 0, got " + number_string(o.half_extents[a]));
        }
        return PF_OK;
    }
    if (!(o.radius > 0.0f)) return bad("radius must be > 0, got " + number_string(o.radius));
    if (o.shape == PF_OBSTACLE_CAPSULE && o.half_height < 0.0f)
        return bad("half_height must be >= 0, got " + number_string(o.half_height));
    return PF_OK;
}

}  // namespace pf

namespace {
// validate_obstacle as pf::effect_object_call calls it.
pf_result validate_obstacle_of(const pf_obstacle& in, const pf::Simulation& s, const char* fn) {
    return pf::validate_obstacle(in, s.log(), fn);
}
}  // namespace

extern "C" {

pf_result pf_init_obstacle(pf_obstacle* out, uint32_t struct_size) {
    return pf::init_struct(out, struct_size, full_default_obstacle(), "pf_init_obstacle");
}

pf_result pf_add_obstacle(pf_sim* handle, const pf_obstacle* obstacle, uint32_t* out_id) {
    return pf::effect_object_call(handle, obstacle, "pf_add_obstacle", "obstacle", full_default_obstacle(),
                                  validate_obstacle_of,
                                  [&](pf::Simulation& s, const pf_obstacle& in) {
                                      pf::ObstacleEntry entry;
                                      if (pf_result r = obstacle_entry(s, in, nullptr, "pf_add_obstacle", entry); r != PF_OK)
                                          return r;
                                      return s.effect<pf::ObstaclesEffect>().edit().add_checked(
                                          entry, out_id, s.log(), "pf_add_obstacle", "obstacles");
                                  });
}

pf_result pf_set_obstacle(pf_sim* handle, uint32_t id, const pf_obstacle* obstacle) {
    return pf::effect_object_call(handle, obstacle, "pf_set_obstacle", "obstacle", full_default_obstacle(),
                                  validate_obstacle_of,
                                  [&](pf::Simulation& s, const pf_obstacle& in) {
                                      pf::ObstaclesEffect& obstacles = s.effect<pf::ObstaclesEffect>();
                                      pf::ObstacleEntry entry;
                                      if (pf_result r = obstacle_entry(s, in, obstacles.list().find(id), "pf_set_obstacle",
                                                                       entry);
                                          r != PF_OK)
                                          return r;
                                      return obstacles.edit().set_checked(id, entry, s.log(), "pf_set_obstacle");
                                  });
}

pf_result pf_remove_obstacle(pf_sim* handle, uint32_t id) {
    return pf::effect_call(handle, "pf_remove_obstacle", [&](pf::Simulation& s) {
        return s.effect<pf::ObstaclesEffect>().edit().remove_checked(id, s.log(), "pf_remove_obstacle");
    });
}

pf_result pf_get_obstacle_force(const pf_sim* handle, uint32_t id, pf_obstacle_force* out) {
    PF_ENTRY(sim, handle, "pf_get_obstacle_force");
    const pf::Simulation& s = *sim->impl;
    if (!out) return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_obstacle_force: out must not be NULL");
    return pf::guarded(s.log(), "pf_get_obstacle_force", [&] {
        pf::gl::StateGuard guard(s.api(), s.gl_state_options());
        if (!s.effect<pf::ObstaclesEffect>().force(id, *out))
            return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_obstacle_force: no obstacle has id " + std::to_string(id));
        return PF_OK;
    });
}

}  // extern "C"
