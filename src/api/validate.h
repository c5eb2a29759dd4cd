// Argument checks of the C API, each failure a logged message: the simulation's own (its
// descriptor, parameters, features, particles) and the render calls' (camera, parameters; the
// engine's GL objects are checked by the renderer, src/render/target_check.h). Each effect validates its objects in its folder
// (src/sim/effects/<name>/<name>_api.cpp).
#pragma once
#include <cstdint>
#include <cstring>

#include "api/log.h"
#include "pf/pf.h"

namespace pf {

// An enum field's bits as the caller stored them. A C caller may store any int in it, and
// loading a value outside the enum's range through the C++ enum type is undefined behaviour,
// so validation reads the bits instead (as unsigned: negative values compare as huge).
template <typename E>
uint32_t enum_bits(const E& e) {
    static_assert(sizeof(E) == sizeof(uint32_t), "pf.h enums are 32-bit (FORCE32)");
    uint32_t bits;
    std::memcpy(&bits, &e, sizeof bits);
    return bits;
}

// Replaces zero tuning knobs by their defaults (pf.h documents which fields take 0 = default).
pf_sim_desc resolve_desc(const pf_sim_desc& desc);
pf_sim_params resolve_params(const pf_sim_params& params);

// PF_OK or PF_ERROR_INVALID_ARGUMENT with a message naming the field; `fn` prefixes messages.
pf_result validate_desc(const pf_sim_desc& desc, const Log& log);
pf_result validate_params(const pf_sim_params& params, const Log& log, const char* fn);
// Only known PF_FEATURE_* bits.
pf_result validate_features(uint32_t features, const Log& log, const char* fn);
// Positions finite and inside the domain, velocities finite and at most max_speed.
pf_result validate_particles(const pf_sim_desc& desc, const float* xyz, const float* vel, uint32_t n,
                             const Log& log);

// Render calls: the camera (finite, invertible matrices, a viewport, planes, a depth convention).
pf_result validate_camera(const pf_camera& camera, const Log& log, const char* fn);
// The look of pf_render_ssf and of pf_render_particles, after resolve_render_params.
pf_result validate_render_params(const pf_ssf_params& params, const Log& log, const char* fn);
pf_result validate_render_params(const pf_particle_params& params, const Log& log, const char* fn);
// Zero fields take their defaults (pf.h); a particle radius of 0 is half of `cell_size`.
pf_ssf_params resolve_render_params(const pf_ssf_params& params, float cell_size);
pf_particle_params resolve_render_params(const pf_particle_params& params, float cell_size);

}  // namespace pf
