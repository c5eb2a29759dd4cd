// What every C entry point that takes a pf_sim starts with, and the one shape of the entry points
// that add or replace an effect's object (pf_add_obstacle, pf_set_emitter, ...): each effect's
// folder (src/sim/effects/<name>/<name>_api.cpp) holds its own entry points, defaults and
// validation, built from these.
#pragma once
#include <cstdint>
#include <string>

#include "api/abi.h"
#include "api/handle.h"
#include "pf/pf.h"

// The entry a live handle names, as `var`; otherwise the call returns PF_ERROR_INVALID_ARGUMENT
// after logging through the global logger (a dead handle has no simulation, hence no logger).
#define PF_ENTRY(var, handle, fn)                \
    pf::SimEntry* const var = pf::entry(handle); \
    if (!var) return pf::invalid_handle(handle, fn)

namespace pf {

// An add or set entry point of an effect's object of type T: `object` (the caller's struct_size
// bytes over `defaults`, the ABI rules) is checked by validate(in, log, fn) and then handed to
// apply(simulation, in). `what` names the argument in the NULL message.
template <typename T, typename Validate, typename Apply>
pf_result effect_object_call(pf_sim* handle, const T* object, const char* fn, const char* what, const T& defaults,
                             Validate&& validate, Apply&& apply) {
    PF_ENTRY(sim, handle, fn);
    Simulation& s = *sim->impl;
    if (!object) return s.log().error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what + " must not be NULL");
    T in{};
    if (pf_result r = read_input(object, defaults, in, s.log(), fn); r != PF_OK) return r;
    if (pf_result r = validate(in, s, fn); r != PF_OK) return r;
    return guarded(s.log(), fn, [&] { return apply(s, in); });
}

// A remove entry point: apply(simulation) under the handle check and the exception guard.
template <typename Apply>
pf_result effect_call(pf_sim* handle, const char* fn, Apply&& apply) {
    PF_ENTRY(sim, handle, fn);
    Simulation& s = *sim->impl;
    return guarded(s.log(), fn, [&] { return apply(s); });
}

}  // namespace pf
