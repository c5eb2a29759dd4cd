// The effects of pflip, one per PF_FEATURE_* bit (docs/design.md §9).
#pragma once
#include <cstdint>
#include <memory>

#include "sim/effects/effect.h"

namespace pf {

// Feature bits in the order their effects run within a stage (lowest bit first).
constexpr uint32_t kEffectCount = 9;
static_assert(PF_FEATURE_ALL == (1u << kEffectCount) - 1u, "one effect per feature bit");

// The slot of a feature bit's effect (the bit's position); kEffectCount for anything else.
constexpr uint32_t effect_slot(uint32_t feature) {
    uint32_t slot = 0;
    while (slot < kEffectCount && feature != (1u << slot)) ++slot;
    return slot;
}

// A new, uninitialised effect for one feature bit of a simulation made from `desc` (resolved
// and validated), or nullptr for an unknown bit.
std::unique_ptr<Effect> make_effect(uint32_t feature, const pf_sim_desc& desc);

// The features whose effects add or remove particles: while one is on, the live particle count
// is decided on the GPU (docs/design.md §9.3).
constexpr uint32_t kGpuCountFeatures = PF_FEATURE_EMITTERS | PF_FEATURE_SINKS;

}  // namespace pf
