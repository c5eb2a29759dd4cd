// The pf_sim handles: generation-checked ids kept in a process-wide registry (the one global
// state of the library besides the global logger, both guarded by one mutex). A handle is not a
// pointer: it encodes a registry slot and that slot's generation, so a destroyed handle, a
// handle from another slot's earlier life or any stray value is recognised without reading
// freed memory. Internal; tests include it to reach pf::Simulation behind a handle made by
// pf_create (pf::entry).
#pragma once
#include <cstdint>
#include <exception>
#include <memory>
#include <new>
#include <string>

#include "render/renderer.h"
#include "sim/simulation.h"

namespace pf {

// What a live handle names: the simulation and its renderer (made by the first render call).
struct SimEntry {
    std::unique_ptr<Simulation> impl;
    // Declared after impl so it is destroyed first: it uses the simulation's GL loader.
    std::unique_ptr<Renderer> renderer;
};

// Registers `entry` and returns its new handle (never NULL).
pf_sim* register_sim(std::unique_ptr<SimEntry> entry);
// The entry a live handle names, nullptr for NULL, destroyed or unknown handles. The entry
// stays valid until the handle is unregistered (pf_destroy, on the simulation's own thread).
SimEntry* entry(const pf_sim* handle);
template <typename Deleter>
SimEntry* entry(const std::unique_ptr<pf_sim, Deleter>& handle) {
    return entry(handle.get());
}
// Removes a live handle and hands back its entry (nullptr if the handle was not live).
std::unique_ptr<SimEntry> unregister_sim(const pf_sim* handle);
// Live handles (tests).
uint32_t live_sim_count();

// The logger of pf_set_global_logger (copied under the registry's lock).
pf_logger global_logger();
void set_global_logger(const pf_logger* logger);
// Logs through the global logger and returns `code`.
pf_result global_error(pf_result code, const std::string& message);
// PF_ERROR_INVALID_ARGUMENT for a call `fn` on a handle that is NULL or not live (logged globally).
inline pf_result invalid_handle(const pf_sim* handle, const char* fn) {
    return global_error(PF_ERROR_INVALID_ARGUMENT,
                        std::string(fn) + (handle ? ": invalid pf_sim (destroyed, or not made by pf_create)"
                                                  : ": sim must not be NULL"));
}

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
