#include "api/abi.h"

#include <algorithm>
#include <string>

namespace pf {

static_assert(sizeof(pf_sim_params) >= kSimParamsV1 && sizeof(pf_sim_desc) >= kSimDescV1 && sizeof(pf_stats) >= kStatsV1 &&
                  sizeof(pf_ssf_params) >= kSsfParamsV1 && sizeof(pf_particle_params) >= kParticleParamsV1,
              "structs only grow");
static_assert(offsetof(pf_sim_params, struct_size) == 0 && offsetof(pf_sim_desc, struct_size) == 0 &&
                  offsetof(pf_stats, struct_size) == 0 && offsetof(pf_ssf_params, struct_size) == 0 &&
                  offsetof(pf_particle_params, struct_size) == 0,
              "struct_size leads");
static_assert(sizeof(pf_force_field) >= kForceFieldV1 && sizeof(pf_obstacle) >= kObstacleV1 && sizeof(pf_emitter) >= kEmitterV1 &&
                  sizeof(pf_sink) >= kSinkV1 && sizeof(pf_domain_motion) >= kDomainMotionV1 &&
                  sizeof(pf_vorticity_confinement) >= kVorticityConfinementV1 && sizeof(pf_whitewater) >= kWhitewaterV1 &&
                  sizeof(pf_viscosity) >= kViscosityV1 && sizeof(pf_surface_tension) >= kSurfaceTensionV1,
              "effect descriptors only grow");
static_assert(offsetof(pf_force_field, struct_size) == 0 && offsetof(pf_obstacle, struct_size) == 0 &&
                  offsetof(pf_emitter, struct_size) == 0 && offsetof(pf_sink, struct_size) == 0 &&
                  offsetof(pf_domain_motion, struct_size) == 0 && offsetof(pf_vorticity_confinement, struct_size) == 0 &&
                  offsetof(pf_whitewater, struct_size) == 0 && offsetof(pf_viscosity, struct_size) == 0 &&
                  offsetof(pf_surface_tension, struct_size) == 0,
              "struct_size leads");

pf_result read_desc(const pf_sim_desc* in, pf_sim_desc& out, const Log& log) {
    const uint32_t size = struct_size_of(in);
    if (!valid_struct_size(size) || (size != 0 && size < 8)) {
        return log.error(PF_ERROR_INVALID_ARGUMENT, "pf_create: pf_sim_desc.struct_size " + std::to_string(size) +
                                                        " is not 0 or a multiple of 4 of at least 8 (start from "
                                                        "pf_default_sim_desc())");
    }
    const pf_sim_desc defaults = pf_default_sim_desc();
    const auto* src = reinterpret_cast<const uint8_t*>(in);
    const size_t avail = size ? size : kSimDescV1;
    // The head (struct_size .. seed) has the same offsets in every version.
    constexpr size_t head = offsetof(pf_sim_desc, params);
    pf_sim_desc raw{};  // what the caller passed, zero where it passed nothing
    std::memcpy(&raw, src, avail < head ? avail : head);
    // params: as long as the caller's pf_sim_params says (0: the v1 layout).
    uint32_t params_size = 0;
    if (avail >= head + 4) std::memcpy(&params_size, src + head, 4);
    if (!valid_struct_size(params_size)) {
        return log.error(PF_ERROR_INVALID_ARGUMENT, "pf_create: desc.params.struct_size " + std::to_string(params_size) +
                                                        " is not 0 or a multiple of 4");
    }
    const size_t caller_params = params_size ? params_size : kSimParamsV1;
    pf_sim_params params_raw{};
    if (avail > head) {
        const size_t n = std::min({avail - head, caller_params, sizeof(pf_sim_params)});
        std::memcpy(&params_raw, src + head, n);
    }
    // The tail (gl_get_proc_address, logger, features, later fields) follows the caller's params,
    // aligned as its first member.
    constexpr size_t tail_mine = offsetof(pf_sim_desc, gl_get_proc_address);
    constexpr size_t align = alignof(pf_gl_get_proc_address_fn);
    const size_t tail_caller = (head + caller_params + align - 1) / align * align;
    if (avail > tail_caller) {
        const size_t n = std::min(avail - tail_caller, sizeof(pf_sim_desc) - tail_mine);
        std::memcpy(reinterpret_cast<uint8_t*>(&raw) + tail_mine, src + tail_caller, n);
    }
    // Assemble over the defaults: the head literally (a zero-initialised desc: its zero words take
    // their defaults), params by their own rule, the tail as passed (its defaults are zero).
    out = defaults;
    constexpr size_t first_field = offsetof(pf_sim_desc, grid_size);
    for (size_t at = first_field; at + 4 <= head; at += 4) {
        uint32_t w = 0;
        std::memcpy(&w, reinterpret_cast<const uint8_t*>(&raw) + at, 4);
        // Beyond what the caller passed the defaults stay; a zero-initialised desc keeps them for
        // its zero words too.
        if (at + 4 <= avail && (size != 0 || w != 0)) std::memcpy(reinterpret_cast<uint8_t*>(&out) + at, &w, 4);
    }
    out.header_version = raw.header_version;
    if (avail > head) {
        if (pf_result r = read_input(&params_raw, defaults.params, out.params, log, "pf_create"); r != PF_OK) return r;
    }
    std::memcpy(reinterpret_cast<uint8_t*>(&out) + tail_mine, reinterpret_cast<const uint8_t*>(&raw) + tail_mine,
                sizeof(pf_sim_desc) - tail_mine);
    out.struct_size = uint32_t(sizeof(pf_sim_desc));
    return PF_OK;
}

pf_result check_header_version(uint32_t header_version, const Log& log) {
    if (header_version == 0 || header_version / 100 == PF_VERSION / 100) return PF_OK;
    const auto text = [](uint32_t v) {
        return std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." + std::to_string(v % 100);
    };
    return log.error(PF_ERROR_INVALID_ARGUMENT, "pf_create: the program was compiled against pf.h " + text(header_version) +
                                                    " but the library is " + text(PF_VERSION) +
                                                    " (major.minor must match): rebuild against this library's header");
}

}  // namespace pf
