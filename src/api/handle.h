// The opaque pf_sim handle: a liveness tag, the simulation and its renderer (made by the first
// render call). Internal; tests include it to reach pf::Simulation behind a handle made by
// pf_create.
#pragma once
#include <cstdint>
#include <exception>
#include <memory>
#include <new>
#include <string>

#include "render/renderer.h"
#include "sim/simulation.h"

namespace pf {
constexpr uint32_t kLiveMagic = 0x70666c69u;  // "pfli": catches NULL-ish and destroyed handles
}

struct pf_sim {
    uint32_t magic = pf::kLiveMagic;
    std::unique_ptr<pf::Simulation> impl;
    // Declared after impl so it is destroyed first: it uses the simulation's GL loader.
    std::unique_ptr<pf::Renderer> renderer;
};

namespace pf {

// A handle made by pf_create and not yet destroyed (as far as can be told).
inline bool live(const pf_sim* sim) { return sim && sim->magic == kLiveMagic && sim->impl; }

// Runs an entry point's body so that no exception crosses the C boundary.
template <typename Fn>
pf_result guarded(const Log& log, const char* fn, Fn&& body) {
    try {
        return body();
    } catch (const std::bad_alloc&) {
        return log.error(PF_ERROR_OUT_OF_MEMORY, std::string(fn) + ": out of host memory");
    } catch (const std::exception& e) {
        return log.error(PF_ERROR_INVALID_STATE, std::string(fn) + ": " + e.what());
    }
}

}  // namespace pf
