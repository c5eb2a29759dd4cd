// The opaque pf_sim handle: a liveness tag, the simulation and its renderer (made by the first
// render call). Internal; tests include it to reach pf::Simulation behind a handle made by
// pf_create.
#pragma once
#include <cstdint>
#include <memory>

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
