// The C boundary: checks every argument, then forwards to pf::Simulation. Nothing here
// throws across the boundary; host allocation failures become PF_ERROR_OUT_OF_MEMORY. Each
// effect's entry points live in its folder (src/sim/effects/<name>/<name>_api.cpp).
#include <cmath>
#include <memory>
#include <new>
#include <string>

#include "api/abi.h"
#include "api/entry.h"
#include "api/field_checks.h"
#include "api/handle.h"
#include "api/validate.h"
#include "pf/pf.h"

namespace {
using pf::guarded;
}  // namespace

extern "C" {

uint32_t pf_version(void) { return PF_VERSION; }

const char* pf_result_string(pf_result r) {
    switch (r) {
        case PF_OK: return "ok";
        case PF_ERROR_INVALID_ARGUMENT: return "invalid argument";
        case PF_ERROR_GL_UNSUPPORTED: return "OpenGL 4.3 core not available";
        case PF_ERROR_SHADER_COMPILE: return "shader compilation failed";
        case PF_ERROR_OUT_OF_MEMORY: return "out of memory";
        case PF_ERROR_CAPACITY: return "capacity exceeded";
        case PF_ERROR_INVALID_STATE: return "invalid state";
        case PF_ERROR_GL: return "OpenGL error";
        case PF_NOT_READY: return "not ready";
        default: return "unknown result";
    }
}

const char* pf_pass_name(pf_pass pass) {
    static const char* const kNames[PF_PASS_COUNT] = {"clear",          "p2g",           "grid_forces",
                                                      "classify",       "pressure_setup", "pressure_solve",
                                                      "velocity_update", "extrapolate",   "g2p",
                                                      "advect"};
    return (pass >= 0 && pass < PF_PASS_COUNT) ? kNames[pass] : "unknown";
}

namespace {
pf_sim_params full_default_params() {
    pf_sim_params p{};
    p.struct_size = uint32_t(sizeof p);
    p.gravity[1] = -9.81f;
    p.flip_ratio = 0.95f;
    p.pressure_iterations = 40;
    p.jacobi_omega = 1.0f;
    p.cfl = 1.0f;
    p.max_substeps = 16;  // measured: 8 lost 9% of a dam break at 0.5 s frames, 16 3% (docs/notes/2026-11-25-volume-correction.md)
    p.extrapolation_layers = 2;
    // The balanced preset (issue 6: the default must keep a resting tank and a dam break's volume):
    // MGPCG converged to 1e-3 in place of the original's 40 Jacobi sweeps, separation off because
    // its active-set rounds cost 3-5x (docs/accuracy.md "Presets").
    p.separation = 0;
    p.pressure_solver = PF_PRESSURE_SOLVER_MGPCG;
    p.pressure_tolerance = 1e-3f;
    p.sor_omega = 1.6f;
    p.volume_correction = 0.5f;  // measured: docs/notes/2026-11-25-volume-correction.md
    p.free_surface = PF_FREE_SURFACE_GHOST_FLUID;  // waves keep their amplitude and period (docs/accuracy.md)
    // Fixed point's sums bit for bit, 2.6 times faster at 1.2M particles (docs/performance.md).
    p.p2g = PF_P2G_TILED;
    p.volume_loss_limit = 0.1f;  // docs/stability.md
    p.energy_gain_limit = 0.1f;  // docs/stability.md
    return p;
}

pf_sim_desc full_default_desc() {
    pf_sim_desc d{};
    d.struct_size = uint32_t(sizeof d);
    d.grid_size[0] = d.grid_size[1] = d.grid_size[2] = 32;
    d.cell_size = 0.05f;
    d.max_particles = 262144;
    d.max_speed = 100.0f;
    d.density = 1000.0f;
    d.fill_particles_per_cell = 8;
    d.fill_jitter = 0.8f;
    d.seed = 1;
    d.params = full_default_params();
    return d;
}
}  // namespace

pf_result pf_init_sim_params(pf_sim_params* out, uint32_t struct_size) {
    return pf::init_struct(out, struct_size, full_default_params(), "pf_init_sim_params");
}

pf_result pf_init_sim_desc(pf_sim_desc* out, uint32_t struct_size) {
    // Written as this build's layout, truncated: right for every caller while pf_sim_params has
    // not grown since struct_size was introduced (only fields after params can be missing). When
    // it grows, an older caller's params end earlier and its tail must be written where read_desc
    // reads it (after the caller's params).
    return pf::init_struct(out, struct_size, full_default_desc(), "pf_init_sim_desc");
}

pf_result pf_quality_params(pf_quality quality, pf_sim_params* out) {
    if (!out || pf::enum_bits(quality) >= PF_QUALITY_COUNT) {
        return pf::global_error(PF_ERROR_INVALID_ARGUMENT, "pf_quality_params: unknown quality or NULL out");
    }
    pf_sim_params p = full_default_params();
    switch (quality) {
        case PF_QUALITY_FAST:  // the original's 40 Jacobi sweeps add energy; MGPCG to 1e-2 too, with the
            p.pressure_tolerance = 3e-3f;  // ghost fluid in a thin tank (docs/accuracy.md)
            // Fewer projections: the particle's own velocity along the grid's path; CFL 3.5 breaks the
            // stability suite's large-step volume bound (docs/accuracy.md, "The fast preset").
            p.advection = PF_ADVECTION_RK2_OFFSET;
            p.cfl = 3.0f;
            break;
        case PF_QUALITY_BALANCED: break;  // the defaults
        case PF_QUALITY_ACCURATE:  // RK2/RK3 measured no better than Euler here (docs/accuracy.md)
            p.pressure_solver = PF_PRESSURE_SOLVER_MGPCG;
            p.pressure_tolerance = 1e-5f;
            p.separation = 1;
            p.transfer = PF_TRANSFER_APIC;
            break;
        default: break;
    }
    return pf::write_output(out, p, pf::Log(pf::global_logger()), "pf_quality_params");
}

pf_result pf_create(const pf_sim_desc* desc, pf_sim** out) {
    if (!desc) return pf::global_error(PF_ERROR_INVALID_ARGUMENT, "pf_create: desc and out must not be NULL");
    // The caller's layout is known only after struct_size: its logger is read with the rest.
    pf_sim_desc read{};
    if (pf_result r = pf::read_desc(desc, read, pf::Log(pf::global_logger())); r != PF_OK) return r;
    const pf::Log log(read.logger);
    if (!out) return log.error(PF_ERROR_INVALID_ARGUMENT, "pf_create: desc and out must not be NULL");
    if (pf_result r = pf::check_header_version(read.header_version, log); r != PF_OK) return r;
    return guarded(log, "pf_create", [&] {
        const pf_sim_desc resolved = pf::resolve_desc(read);
        if (pf_result r = pf::validate_desc(resolved, log); r != PF_OK) return r;
        auto entry = std::make_unique<pf::SimEntry>();
        if (pf_result r = pf::Simulation::create(resolved, entry->impl); r != PF_OK) return r;
        *out = pf::register_sim(std::move(entry));
        return PF_OK;
    });
}

pf_result pf_destroy(pf_sim* handle) {
    if (!handle) return PF_OK;
    std::unique_ptr<pf::SimEntry> entry = pf::unregister_sim(handle);
    if (!entry) return pf::invalid_handle(handle, "pf_destroy");
    entry.reset();  // deletes its GL objects: the context must be current
    return PF_OK;
}

void pf_set_global_logger(const pf_logger* logger) { pf::set_global_logger(logger); }

pf_result pf_add_particles(pf_sim* handle, const float* xyz, const float* vel, uint32_t n) {
    PF_ENTRY(sim, handle, "pf_add_particles");
    pf::Simulation& s = *sim->impl;
    return guarded(s.log(), "pf_add_particles", [&] {
        if (n == 0) return PF_OK;
        if (!xyz) return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_add_particles: xyz must not be NULL");
        const uint32_t live = s.live_count();
        if (uint64_t(live) + n > s.desc().max_particles) {
            return s.log().error(PF_ERROR_CAPACITY, "pf_add_particles: " + std::to_string(n) + " particles do not fit (" +
                                                        std::to_string(live) + " of " +
                                                        std::to_string(s.desc().max_particles) + " in use)");
        }
        if (pf_result r = pf::validate_particles(s.desc(), xyz, vel, n, s.log()); r != PF_OK) return r;
        return s.add_particles(xyz, vel, n);
    });
}

pf_result pf_fill_box(pf_sim* handle, const float lo[3], const float hi[3], const float vel[3]) {
    PF_ENTRY(sim, handle, "pf_fill_box");
    pf::Simulation& s = *sim->impl;
    return guarded(s.log(), "pf_fill_box", [&] {
        if (!lo || !hi) return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_fill_box: lo and hi must not be NULL");
        for (int a = 0; a < 3; ++a) {
            if (!std::isfinite(lo[a]) || !std::isfinite(hi[a]) || (vel && !std::isfinite(vel[a])))
                return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_fill_box: lo, hi and vel must be finite");
        }
        if (vel && std::sqrt(double(vel[0]) * vel[0] + double(vel[1]) * vel[1] + double(vel[2]) * vel[2]) > s.desc().max_speed)
            return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_fill_box: vel exceeds desc.max_speed");
        return s.fill_box(lo, hi, vel);
    });
}

pf_result pf_clear_particles(pf_sim* handle) {
    PF_ENTRY(sim, handle, "pf_clear_particles");
    return sim->impl->clear_particles();
}

pf_result pf_step(pf_sim* handle, float frame_dt) {
    PF_ENTRY(sim, handle, "pf_step");
    pf::Simulation& s = *sim->impl;
    if (!(std::isfinite(frame_dt) && frame_dt > 0.0f && frame_dt <= 1.0f)) {
        return s.log().error(PF_ERROR_INVALID_ARGUMENT,
                             "pf_step: frame_dt must be in (0, 1] seconds, got " + std::to_string(frame_dt));
    }
    return guarded(s.log(), "pf_step", [&] { return s.step(frame_dt); });
}

pf_result pf_push(pf_sim* handle, const float center[3], float radius, const float dv[3]) {
    PF_ENTRY(sim, handle, "pf_push");
    pf::Simulation& s = *sim->impl;
    if (!center || !dv) return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_push: center and dv must not be NULL");
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(center[a]) || !std::isfinite(dv[a]))
            return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_push: center and dv must be finite");
    }
    if (!(std::isfinite(radius) && radius > 0.0f))
        return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_push: radius must be finite and > 0, got " + std::to_string(radius));
    return guarded(s.log(), "pf_push", [&] { return s.push(center, radius, dv); });
}

pf_result pf_set_features(pf_sim* handle, uint32_t features) {
    PF_ENTRY(sim, handle, "pf_set_features");
    pf::Simulation& s = *sim->impl;
    if (pf_result r = pf::validate_features(features, s.log(), "pf_set_features"); r != PF_OK) return r;
    return guarded(s.log(), "pf_set_features", [&] { return s.set_features(features, "pf_set_features"); });
}

pf_result pf_get_features(const pf_sim* handle, uint32_t* out) {
    PF_ENTRY(sim, handle, "pf_get_features");
    if (!out) return sim->impl->log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_features: out must not be NULL");
    *out = sim->impl->features();
    return PF_OK;
}

pf_result pf_get_particle_count(pf_sim* handle, uint32_t* out) {
    PF_ENTRY(sim, handle, "pf_get_particle_count");
    pf::Simulation& s = *sim->impl;
    if (!out) return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_particle_count: out must not be NULL");
    return guarded(s.log(), "pf_get_particle_count", [&] {
        *out = s.live_count();
        return PF_OK;
    });
}

pf_result pf_get_params(const pf_sim* handle, pf_sim_params* out) {
    PF_ENTRY(sim, handle, "pf_get_params");
    if (!out) return sim->impl->log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_params: out must not be NULL");
    return pf::write_output(out, sim->impl->params(), sim->impl->log(), "pf_get_params");
}

pf_result pf_set_params(pf_sim* handle, const pf_sim_params* params) {
    PF_ENTRY(sim, handle, "pf_set_params");
    pf::Simulation& s = *sim->impl;
    if (!params) return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_set_params: params must not be NULL");
    return guarded(s.log(), "pf_set_params", [&] {
        pf_sim_params read{};
        if (pf_result r = pf::read_input(params, pf_default_sim_params(), read, s.log(), "pf_set_params"); r != PF_OK)
            return r;
        const pf_sim_params resolved = pf::resolve_params(read);
        if (pf_result r = pf::validate_params(resolved, s.log(), "pf_set_params"); r != PF_OK) return r;
        return s.set_params(resolved);
    });
}

pf_result pf_read_particles(pf_sim* handle, uint32_t first, uint32_t count, float* xyz, float* vel) {
    PF_ENTRY(sim, handle, "pf_read_particles");
    pf::Simulation& s = *sim->impl;
    const uint32_t live = s.live_count();
    if (uint64_t(first) + count > live) {
        return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_read_particles: range [" + std::to_string(first) + ", " +
                                                            std::to_string(uint64_t(first) + count) + ") exceeds the " +
                                                            std::to_string(live) + " live particles");
    }
    if (count == 0 || (!xyz && !vel)) return PF_OK;
    return guarded(s.log(), "pf_read_particles", [&] { return s.read_particles(first, count, xyz, vel); });
}

pf_result pf_request_particles(pf_sim* handle, uint32_t first, uint32_t count, uint32_t* out_ticket) {
    PF_ENTRY(sim, handle, "pf_request_particles");
    pf::Simulation& s = *sim->impl;
    if (!out_ticket)
        return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_request_particles: out_ticket must not be NULL");
    if (uint64_t(first) + count > s.particle_count()) {
        return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_request_particles: range [" + std::to_string(first) + ", " +
                                                            std::to_string(uint64_t(first) + count) + ") exceeds the " +
                                                            std::to_string(s.particle_count()) + " live particles");
    }
    return guarded(s.log(), "pf_request_particles", [&] { return s.request_particles(first, count, out_ticket); });
}

pf_result pf_poll_particles(pf_sim* handle, uint32_t ticket, float* xyz, float* vel) {
    PF_ENTRY(sim, handle, "pf_poll_particles");
    pf::Simulation& s = *sim->impl;
    return guarded(s.log(), "pf_poll_particles", [&] { return s.poll_particles(ticket, xyz, vel); });
}

pf_result pf_snapshot_size(const pf_sim* handle, size_t* out) {
    PF_ENTRY(sim, handle, "pf_snapshot_size");
    pf::Simulation& s = *sim->impl;
    if (!out) return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_snapshot_size: out must not be NULL");
    return guarded(s.log(), "pf_snapshot_size", [&] {
        *out = s.snapshot_size();
        return PF_OK;
    });
}

pf_result pf_save_snapshot(pf_sim* handle, void* buffer, size_t size) {
    PF_ENTRY(sim, handle, "pf_save_snapshot");
    pf::Simulation& s = *sim->impl;
    if (!buffer) return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_save_snapshot: buffer must not be NULL");
    return guarded(s.log(), "pf_save_snapshot", [&] { return s.save_snapshot(buffer, size); });
}

pf_result pf_restore_snapshot(pf_sim* handle, const void* buffer, size_t size) {
    PF_ENTRY(sim, handle, "pf_restore_snapshot");
    pf::Simulation& s = *sim->impl;
    if (!buffer) return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_restore_snapshot: buffer must not be NULL");
    return guarded(s.log(), "pf_restore_snapshot", [&] { return s.restore_snapshot(buffer, size); });
}

pf_result pf_get_gl_buffers(const pf_sim* handle, pf_gl_buffers* out) {
    PF_ENTRY(sim, handle, "pf_get_gl_buffers");
    if (!out) return sim->impl->log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_gl_buffers: out must not be NULL");
    sim->impl->gl_buffers(*out);
    return PF_OK;
}

pf_result pf_get_stats(const pf_sim* handle, pf_stats* out) {
    PF_ENTRY(sim, handle, "pf_get_stats");
    if (!out) return sim->impl->log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_stats: out must not be NULL");
    if (!pf::valid_struct_size(pf::struct_size_of(out)))
        return pf::write_output(out, pf_stats{}, sim->impl->log(), "pf_get_stats");  // logs the bad size
    pf_stats full{};
    sim->impl->stats(full);
    if (sim->renderer) sim->renderer->stats(full);
    full.struct_size = uint32_t(sizeof full);
    return pf::write_output(out, full, sim->impl->log(), "pf_get_stats");
}

pf_result pf_clear_flags(pf_sim* handle) {
    PF_ENTRY(sim, handle, "pf_clear_flags");
    sim->impl->clear_flags();
    return PF_OK;
}

pf_result pf_get_pass_count(const pf_sim* handle, uint32_t* out) {
    PF_ENTRY(sim, handle, "pf_get_pass_count");
    if (!out) return sim->impl->log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_pass_count: out must not be NULL");
    *out = sim->impl->pass_count();
    return PF_OK;
}

pf_result pf_set_gpu_timing(pf_sim* handle, pf_gpu_timing timing) {
    PF_ENTRY(sim, handle, "pf_set_gpu_timing");
    pf::Simulation& s = *sim->impl;
    if (pf::enum_bits(timing) >= uint32_t(PF_GPU_TIMING_COUNT))
        return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_set_gpu_timing: timing " + std::to_string(pf::enum_bits(timing)) +
                                                            " is not a pf_gpu_timing (0..3)");
    if (timing == PF_GPU_TIMING_OFF && s.gpu_budget_ms() > 0.0f)
        return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_set_gpu_timing: PF_GPU_TIMING_OFF while a GPU budget is set "
                                                        "(pf_set_gpu_budget needs the step's times; set the budget to 0 first)");
    s.set_gpu_timing(timing);
    return PF_OK;
}

pf_result pf_set_gpu_budget(pf_sim* handle, float milliseconds) {
    PF_ENTRY(sim, handle, "pf_set_gpu_budget");
    pf::Simulation& s = *sim->impl;
    if (!(milliseconds >= 0.0f && milliseconds <= 1e4f))
        return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_set_gpu_budget: milliseconds must be in [0, 1e4], got " +
                                                            pf::number_string(milliseconds));
    if (milliseconds > 0.0f && s.gpu_timing() == PF_GPU_TIMING_OFF)
        return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_set_gpu_budget: GPU timing is off (pf_set_gpu_timing), so "
                                                        "there is nothing to fit the budget by");
    s.set_gpu_budget_ms(milliseconds);
    return PF_OK;
}

pf_result pf_get_gpu_budget(const pf_sim* handle, float* out) {
    PF_ENTRY(sim, handle, "pf_get_gpu_budget");
    if (!out) return sim->impl->log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_gpu_budget: out must not be NULL");
    *out = sim->impl->gpu_budget_ms();
    return PF_OK;
}

pf_result pf_get_gpu_timing(const pf_sim* handle, pf_gpu_timing* out) {
    PF_ENTRY(sim, handle, "pf_get_gpu_timing");
    if (!out) return sim->impl->log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_gpu_timing: out must not be NULL");
    *out = sim->impl->gpu_timing();
    return PF_OK;
}

pf_result pf_get_pass_stats(const pf_sim* handle, uint32_t index, pf_pass_stats* out) {
    PF_ENTRY(sim, handle, "pf_get_pass_stats");
    const pf::Simulation& s = *sim->impl;
    if (!out) return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_pass_stats: out must not be NULL");
    if (index >= s.pass_count()) {
        return s.log().error(PF_ERROR_INVALID_ARGUMENT, "pf_get_pass_stats: index " + std::to_string(index) +
                                                            " is not below the pass count " +
                                                            std::to_string(s.pass_count()));
    }
    s.pass_stats(index, *out);
    return PF_OK;
}

}  // extern "C"
