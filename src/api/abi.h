// The ABI rules of pf.h: structs that may grow start with struct_size (the caller's sizeof),
// fields are only appended, so the library reads the first struct_size bytes of an input and
// takes defaults for the rest, and writes at most struct_size bytes of an output. struct_size 0
// marks a zero-initialised struct: every zero field (each 4-byte word) takes its default, and
// the struct is read with the layout of the release that introduced struct_size (kV1).
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "api/log.h"
#include "pf/pf.h"

namespace pf {

// Sizes of the structs in the release that introduced struct_size (pflip 0.1). Frozen: when a
// struct grows, these stay, so a zero-initialised struct of an older caller is never over-read.
constexpr uint32_t kSimParamsV1 = 80;
constexpr uint32_t kSimDescV1 = 176;
constexpr uint32_t kStatsV1 = 240;
constexpr uint32_t kSsfParamsV1 = 68;
constexpr uint32_t kParticleParamsV1 = 44;
// The effect descriptors took struct_size in pflip 0.2, with these sizes.
constexpr uint32_t kForceFieldV1 = 44;
constexpr uint32_t kObstacleV1 = 88;
constexpr uint32_t kEmitterV1 = 72;
constexpr uint32_t kSinkV1 = 52;
constexpr uint32_t kDomainMotionV1 = 56;
// Introduced in pflip 0.2 with struct_size.
constexpr uint32_t kVorticityConfinementV1 = 8;
constexpr uint32_t kWhitewaterV1 = 60;
constexpr uint32_t kViscosityV1 = 20;
constexpr uint32_t kSurfaceTensionV1 = 8;

template <typename T> struct AbiInfo;
template <> struct AbiInfo<pf_sim_params> { static constexpr uint32_t v1 = kSimParamsV1; static constexpr const char* name = "pf_sim_params"; };
template <> struct AbiInfo<pf_sim_desc> { static constexpr uint32_t v1 = kSimDescV1; static constexpr const char* name = "pf_sim_desc"; };
template <> struct AbiInfo<pf_stats> { static constexpr uint32_t v1 = kStatsV1; static constexpr const char* name = "pf_stats"; };
template <> struct AbiInfo<pf_ssf_params> { static constexpr uint32_t v1 = kSsfParamsV1; static constexpr const char* name = "pf_ssf_params"; };
template <> struct AbiInfo<pf_particle_params> { static constexpr uint32_t v1 = kParticleParamsV1; static constexpr const char* name = "pf_particle_params"; };
template <> struct AbiInfo<pf_force_field> { static constexpr uint32_t v1 = kForceFieldV1; static constexpr const char* name = "pf_force_field"; };
template <> struct AbiInfo<pf_obstacle> { static constexpr uint32_t v1 = kObstacleV1; static constexpr const char* name = "pf_obstacle"; };
template <> struct AbiInfo<pf_emitter> { static constexpr uint32_t v1 = kEmitterV1; static constexpr const char* name = "pf_emitter"; };
template <> struct AbiInfo<pf_sink> { static constexpr uint32_t v1 = kSinkV1; static constexpr const char* name = "pf_sink"; };
template <> struct AbiInfo<pf_domain_motion> { static constexpr uint32_t v1 = kDomainMotionV1; static constexpr const char* name = "pf_domain_motion"; };
template <> struct AbiInfo<pf_vorticity_confinement> { static constexpr uint32_t v1 = kVorticityConfinementV1; static constexpr const char* name = "pf_vorticity_confinement"; };
template <> struct AbiInfo<pf_whitewater> { static constexpr uint32_t v1 = kWhitewaterV1; static constexpr const char* name = "pf_whitewater"; };
template <> struct AbiInfo<pf_viscosity> { static constexpr uint32_t v1 = kViscosityV1; static constexpr const char* name = "pf_viscosity"; };
template <> struct AbiInfo<pf_surface_tension> { static constexpr uint32_t v1 = kSurfaceTensionV1; static constexpr const char* name = "pf_surface_tension"; };

// A struct_size a caller may pass: 0, or at least 4 and a multiple of 4.
inline bool valid_struct_size(uint32_t size) { return size == 0 || (size >= 4 && size % 4 == 0); }

// The caller's struct_size (the first 4 bytes, whatever the struct).
inline uint32_t struct_size_of(const void* s) {
    uint32_t size = 0;
    std::memcpy(&size, s, sizeof size);
    return size;
}

// pf_init_*: writes the first `size` bytes of the caller's struct from `full` (this build's
// defaults), zero beyond this build's size, and struct_size = size.
template <typename T>
pf_result init_struct(T* out, uint32_t size, const T& full, const char* fn) {
    if (!out || size < 4 || size % 4 != 0) {
        return Log{}.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": out must not be NULL and struct_size a multiple "
                                                                          "of 4, at least 4");
    }
    auto* bytes = reinterpret_cast<uint8_t*>(out);
    const size_t mine = sizeof(T);
    std::memcpy(bytes, &full, size < mine ? size : mine);
    if (size > mine) std::memset(bytes + mine, 0, size - mine);
    std::memcpy(bytes, &size, sizeof size);
    return PF_OK;
}

// Reads an input struct of the word-only kind (pf_sim_params, pf_ssf_params,
// pf_particle_params: every field a 4-byte scalar or an array of them) over `defaults`.
template <typename T>
pf_result read_input(const T* in, const T& defaults, T& out, const Log& log, const char* fn) {
    static_assert(sizeof(T) % 4 == 0, "word-only struct");
    const uint32_t size = struct_size_of(in);
    if (!valid_struct_size(size)) {
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + AbiInfo<T>::name + ".struct_size " +
                                                        std::to_string(size) + " is not 0 or a multiple of 4 (start from pf_default_*())");
    }
    out = defaults;
    const size_t caller = size ? size : AbiInfo<T>::v1;
    const size_t n = caller < sizeof(T) ? caller : sizeof(T);
    const auto* src = reinterpret_cast<const uint8_t*>(in);
    auto* dst = reinterpret_cast<uint8_t*>(&out);
    if (size != 0) {
        std::memcpy(dst, src, n);
    } else {
        for (size_t at = 4; at + 4 <= n; at += 4) {  // each zero word keeps its default
            uint32_t w = 0;
            std::memcpy(&w, src + at, 4);
            if (w != 0) std::memcpy(dst + at, &w, 4);
        }
    }
    out.struct_size = uint32_t(sizeof(T));
    return PF_OK;
}

// Writes an output struct: out->struct_size bytes of `full` (0: the v1 size), at most this
// build's; out->struct_size becomes the bytes written.
template <typename T>
pf_result write_output(T* out, const T& full, const Log& log, const char* fn) {
    const uint32_t size = struct_size_of(out);
    if (!valid_struct_size(size)) {
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + AbiInfo<T>::name + ".struct_size " +
                                                        std::to_string(size) + " is not 0 or a multiple of 4");
    }
    const uint32_t caller = size ? size : AbiInfo<T>::v1;
    const uint32_t n = caller < sizeof(T) ? caller : uint32_t(sizeof(T));
    std::memcpy(out, &full, n);
    std::memcpy(out, &n, sizeof n);
    return PF_OK;
}

// Reads a caller's pf_sim_desc (its own layout: the head, params of the caller's
// params.struct_size, then the tail from gl_get_proc_address on) over the defaults.
pf_result read_desc(const pf_sim_desc* in, pf_sim_desc& out, const Log& log);

// pf_create's check of desc.header_version against the library's version.
pf_result check_header_version(uint32_t header_version, const Log& log);

}  // namespace pf
