// Snapshots of a simulation (pf_snapshot_size / pf_save_snapshot / pf_restore_snapshot): every
// state that determines the following steps, so that a restore continues bit for bit as the
// original did (docs/integration.md §2). Layout, in host byte order:
//   header (magic, format, sizes, FNV-1a checksum of everything after it)
//   the descriptor fields a snapshot must match; params; features; the fill counter
//   CPU state of the step logic (CFL speed estimate, P2G range, solver history, hydrostatic start)
//   each effect's host state (Effect::save_state), in feature-bit order
//   particle count; the GPU status words; positions, velocities, APIC affine vectors (while APIC
//   is on); the pressure (the next solve's warm start)
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "api/validate.h"
#include "common/slots.h"
#include "sim/simulation.h"

namespace pf {

namespace {

constexpr char kMagic[8] = {'p', 'f', 'l', 'i', 'p', 's', 'n', 'p'};
// 2: the status words gained PF_STATUS_INTERIOR_DENSITY (14 words, 2026-11-24).
// 3: and PF_STATUS_WHITEWATER_COUNT (16 words, 2026-11-26).
// 4: the host state holds the newest status words read back, which effects learn from (2026-11-27).
// 5: the status words gained the viscosity's four (20 words); the effects' state its settings
// and what its recent solves needed (2026-11-27).
// 6: the effects' state holds the surface tension's settings (2026-11-27).
// 7: the viscosity settings gained coupling_rounds (2026-11-28).
// 8: the readbacks and the CFL state gained the strain (PF_STATUS_STRAIN, 2026-12-05).
// 9: the status words gained the volume correction's residual, iterations and whether it ran
// (23 words, 2026-12-06).
constexpr uint32_t kFormat = 9;

struct Header {
    char magic[8];
    uint32_t format;
    uint32_t header_bytes;
    uint64_t total_bytes;
    uint64_t checksum;  // FNV-1a 64 of bytes [header_bytes, total_bytes)
    uint32_t library_version;
    uint32_t reserved;
};

// The descriptor fields the saving and the restoring simulation must share.
struct Compat {
    uint32_t grid[3];
    float cell_size;
    float origin[3];
    float max_speed;
    float density;
    uint32_t fill_particles_per_cell;
};

uint64_t fnv1a(const uint8_t* p, size_t n) {
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

Compat compat_of(const pf_sim_desc& d) {
    Compat c{};
    std::memcpy(c.grid, d.grid_size, sizeof c.grid);
    c.cell_size = d.cell_size;
    std::memcpy(c.origin, d.origin, sizeof c.origin);
    c.max_speed = d.max_speed;
    c.density = d.density;
    c.fill_particles_per_cell = d.fill_particles_per_cell;
    return c;
}

}  // namespace

// The step logic's CPU state (what the snapshot restores besides params, effects and buffers).
struct Simulation::SnapshotState {
    uint64_t steps;  // pf_step calls at the save: the step-valued fields are relative to it
    uint64_t status_step, flags_cleared_at_step;
    int64_t p2g_range_changed_at_step, added_at_step;
    float gpu_max_speed, added_speed, solver_residual;
    uint32_t solver_iterations, recent_iterations, recent_later_iterations, recent_solver;
    uint32_t p2g_range_shift, flags, hydrostatic_start_pending, fill_calls;
    // The readbacks the next steps take in (Simulation::take_lagged_status), by slot, and the
    // CFL input in use: the continuation chooses the same substeps as the original.
    int64_t cfl_step;
    float cfl_speed, cfl_strain;
    StepStatus received[kReadbackSlots];
    // The newest status words read back, which effects learn from (FrameInfo::status).
    uint32_t status_words[PF_STATUS_WORDS];
};

std::vector<uint8_t> Simulation::snapshot_host_state() const {
    std::vector<uint8_t> bytes;
    ByteWriter w(bytes);
    w.put(compat_of(desc_));
    w.put(uint32_t(sizeof(pf_sim_params)));
    w.put(desc_.params);
    w.put(desc_.features);
    SnapshotState s{};
    s.steps = steps_;
    s.status_step = status_step_;
    s.p2g_range_changed_at_step = p2g_.range().changed_at_step();
    s.added_at_step = added_at_step_;
    s.flags_cleared_at_step = flags_cleared_at_step_;
    s.gpu_max_speed = gpu_max_speed_;
    s.added_speed = added_speed_;
    s.solver_residual = solver_residual_;
    s.solver_iterations = solver_iterations_;
    s.recent_iterations = recent_iterations_;
    s.recent_later_iterations = recent_later_iterations_;
    s.recent_solver = uint32_t(recent_solver_);
    s.p2g_range_shift = p2g_.range().shift();
    s.flags = flags_;
    s.hydrostatic_start_pending = hydrostatic_start_pending_ ? 1u : 0u;
    s.fill_calls = fill_calls_;
    s.cfl_step = cfl_step_;
    s.cfl_speed = cfl_speed_;
    s.cfl_strain = cfl_strain_;
    for (int k = 0; k < kReadbackSlots; ++k) s.received[k] = received_[k];
    std::copy(status_words_.begin(), status_words_.end(), std::begin(s.status_words));
    w.put(s);
    w.put(kEffectCount);
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        std::vector<uint8_t> effect;
        ByteWriter ew(effect);
        effects_[i]->save_state(ew);
        w.put(effects_[i]->feature());
        w.put(uint64_t(effect.size()));
        w.put_bytes(effect.data(), effect.size());
    }
    w.put(particle_count_);
    w.put(uint32_t(snapshot_has_affine() ? 1u : 0u));
    return bytes;
}

bool Simulation::snapshot_has_affine() const {
    return desc_.params.transfer == PF_TRANSFER_APIC && affine_.bytes() != 0;
}

size_t Simulation::snapshot_gpu_bytes(uint32_t particles, bool affine) const {
    return size_t(PF_STATUS_WORDS) * 4 + size_t(particles) * (32 + (affine ? 48 : 0)) + size_t(layout_.cells()) * 4;
}

size_t Simulation::snapshot_size() const {
    live_count();  // while the GPU keeps the count: the exact one, so the size is exact
    return sizeof(Header) + snapshot_host_state().size() + snapshot_gpu_bytes(particle_count_, snapshot_has_affine());
}

void Simulation::drain_status() {
    // Every status readback in flight is waited for and taken in, so the snapshot's CPU state
    // holds all the GPU has reported up to now, and the original continues from exactly that.
    for (int k = 0; k < kReadbackSlots; ++k) {
        if (readback_.pending(k)) read_status_slot(k);  // waits for the copy
    }
}

pf_result Simulation::save_snapshot(void* buffer, size_t size) {
    static constexpr const char* fn = "pf_save_snapshot";
    gl::StateGuard guard(gl_, gl_state_);
    drain_status();
    live_count();  // while the GPU keeps the count: the exact one (the GPU is idle after the drain)
    const std::vector<uint8_t> host = snapshot_host_state();
    const bool affine = snapshot_has_affine();
    const size_t total = sizeof(Header) + host.size() + snapshot_gpu_bytes(particle_count_, affine);
    if (size < total) {
        return log_.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": the buffer holds " + std::to_string(size) +
                                                         " bytes, the snapshot needs " + std::to_string(total) +
                                                         " (pf_snapshot_size)");
    }
    auto* out = static_cast<uint8_t*>(buffer);
    size_t at = sizeof(Header);
    std::memcpy(out + at, host.data(), host.size());
    at += host.size();
    status_.download(0, size_t(PF_STATUS_WORDS) * 4, out + at);
    at += size_t(PF_STATUS_WORDS) * 4;
    const size_t n = particle_count_;
    const auto vec4s = [&](const gl::Buffer& b, size_t bytes) {
        if (bytes) b.download(0, bytes, out + at);
        at += bytes;
    };
    vec4s(pos_, n * 16);
    vec4s(vel_, n * 16);
    if (affine) vec4s(affine_, n * 48);
    vec4s(pressure_, size_t(layout_.cells()) * 4);
    Header h{};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.format = kFormat;
    h.header_bytes = sizeof(Header);
    h.total_bytes = total;
    h.checksum = fnv1a(out + sizeof(Header), total - sizeof(Header));
    h.library_version = PF_VERSION;
    std::memcpy(out, &h, sizeof h);
    return PF_OK;
}

pf_result Simulation::restore_snapshot(const void* buffer, size_t size) {
    static constexpr const char* fn = "pf_restore_snapshot";
    const auto bad = [&](const std::string& why) {
        return log_.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + why + "; nothing was changed");
    };
    const auto* in = static_cast<const uint8_t*>(buffer);
    Header h{};
    if (size < sizeof h) return bad("the buffer (" + std::to_string(size) + " bytes) is shorter than a snapshot header");
    std::memcpy(&h, in, sizeof h);
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) return bad("not a pflip snapshot (wrong magic)");
    if (h.format != kFormat || h.header_bytes != sizeof(Header))
        return bad("snapshot format " + std::to_string(h.format) + ", this library reads format " + std::to_string(kFormat));
    if (h.total_bytes > size || h.total_bytes < sizeof(Header))
        return bad("the snapshot is " + std::to_string(h.total_bytes) + " bytes but the buffer holds " + std::to_string(size) +
                   " (truncated)");
    if (fnv1a(in + sizeof h, size_t(h.total_bytes) - sizeof h) != h.checksum) return bad("checksum mismatch (corrupted)");

    ByteReader r(in + sizeof h, size_t(h.total_bytes) - sizeof h);
    Compat c{};
    uint32_t params_bytes = 0, features = 0, effect_count = 0;
    pf_sim_params params{};
    SnapshotState s{};
    if (!r.get(c) || !r.get(params_bytes)) return bad("truncated");
    const Compat mine = compat_of(desc_);
    if (std::memcmp(&c, &mine, sizeof c) != 0)
        return bad("it was saved by a simulation with another grid, cell size, origin, max_speed, density or "
                   "fill_particles_per_cell");
    if (params_bytes != sizeof params || !r.get(params) || !r.get(features) || !r.get(s) || !r.get(effect_count))
        return bad("truncated or from another build (parameter block)");
    const Log silent;
    if (validate_params(params, log_, fn) != PF_OK) return bad("its parameters are invalid");
    if (validate_features(features, log_, fn) != PF_OK) return bad("its features are invalid");
    if (s.recent_solver > uint32_t(PF_PRESSURE_SOLVER_COUNT) || s.p2g_range_shift > FixedPointRange::kMaxShift ||
        s.hydrostatic_start_pending > 1 || s.steps < s.status_step)
        return bad("its step state is invalid");
    const auto speed_ok = [](float v) { return std::isfinite(v) && v >= 0.0f; };
    bool readbacks_ok = speed_ok(s.cfl_speed) && std::isfinite(s.cfl_strain);
    for (const StepStatus& r : s.received)
        readbacks_ok = readbacks_ok && r.valid <= 1 && (r.valid == 0 || (speed_ok(r.max_speed) && std::isfinite(r.strain)));
    if (!readbacks_ok) return bad("its CFL state (readback slots, speeds, strains) is invalid");
    if (effect_count != kEffectCount) return bad("it holds " + std::to_string(effect_count) + " effects, this build has " +
                                                 std::to_string(kEffectCount));
    std::vector<std::pair<const uint8_t*, size_t>> effect_bytes;
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        uint32_t bit = 0;
        uint64_t bytes = 0;
        if (!r.get(bit) || !r.get(bytes) || bit != effects_[i]->feature()) return bad("its effect list is invalid");
        const uint8_t* at = r.take(size_t(bytes));
        if (!at) return bad("truncated (effects)");
        effect_bytes.emplace_back(at, size_t(bytes));
    }
    uint32_t count = 0, has_affine = 0;
    if (!r.get(count) || !r.get(has_affine) || has_affine > 1) return bad("truncated (particles)");
    if (count > desc_.max_particles)
        return bad("it holds " + std::to_string(count) + " particles, more than max_particles " +
                   std::to_string(desc_.max_particles));
    if (has_affine != (params.transfer == PF_TRANSFER_APIC ? 1u : 0u)) return bad("its APIC state is inconsistent");
    const size_t gpu = snapshot_gpu_bytes(count, has_affine != 0);
    if (r.left() != gpu) return bad("its particle data is " + std::to_string(r.left()) + " bytes, " + std::to_string(gpu) +
                                    " expected");
    const uint8_t* status = r.take(size_t(PF_STATUS_WORDS) * 4);
    const uint8_t* pos = r.take(size_t(count) * 16);
    const uint8_t* vel = r.take(size_t(count) * 16);
    const uint8_t* affine = has_affine ? r.take(size_t(count) * 48) : nullptr;
    const uint8_t* pressure = r.take(size_t(layout_.cells()) * 4);
    // Particles finite and inside the domain, speeds at most max_speed (what every step keeps;
    // the GPU's clamp rounds in float, hence the small margin). The checksum already caught
    // accidental damage: this refuses a well-formed snapshot of impossible particles.
    {
        const double limit = double(desc_.max_speed) * (1.0 + 1e-4), limit2 = limit * limit;
        for (uint32_t i = 0; i < count; ++i) {
            float p[4], v[4];
            std::memcpy(p, pos + size_t(i) * 16, 16);
            std::memcpy(v, vel + size_t(i) * 16, 16);
            for (int a = 0; a < 3; ++a) {
                const double lo = desc_.origin[a], hi = lo + double(desc_.cell_size) * desc_.grid_size[a];
                if (!(std::isfinite(p[a]) && p[a] >= lo && p[a] <= hi) || !std::isfinite(v[a]))
                    return bad("particle " + std::to_string(i) + " is outside the domain or not finite");
            }
            if (double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2] > limit2)
                return bad("particle " + std::to_string(i) + " is faster than max_speed");
        }
    }

    // Everything the restored state needs is built first (programs, solver, effects), so a
    // failure here changes nothing either.
    gl::StateGuard guard(gl_, gl_state_);
    if (pf_result res = prepare_particle_passes(params, features, fn); res != PF_OK) return res;
    SolversInUse solvers;
    if (pf_result res = solvers_for(params, fn, &solvers); res != PF_OK) return res;
    const uint32_t features_before = desc_.features;
    if (pf_result res = set_features(features | features_before, fn); res != PF_OK) return res;
    desc_.features = features_before;
    // Effects: each replaces its host state only if all of it is valid; an effect failing after
    // others succeeded puts theirs back.
    std::vector<std::vector<uint8_t>> backups(kEffectCount);
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        ByteWriter w(backups[i]);
        effects_[i]->save_state(w);
    }
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        ByteReader er(effect_bytes[i].first, effect_bytes[i].second);
        pf_result res = effects_[i]->restore_state(er, log_, fn);
        if (res == PF_OK && er.left() != 0) res = log_.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": an effect's state has trailing bytes");
        if (res != PF_OK) {
            for (uint32_t j = 0; j < i; ++j) {
                ByteReader back(backups[j].data(), backups[j].size());
                effects_[j]->restore_state(back, silent, fn);
            }
            return log_.error(res, std::string(fn) + ": nothing was changed");
        }
    }

    // Apply. Status readbacks in flight belong to the discarded timeline: dropped.
    readback_.drop_all();
    desc_.params = params;
    desc_.features = features;
    gpu_count_ = (features & kGpuCountFeatures) != 0;
    solvers_in_use_ = solvers;
    // Step-valued fields are kept relative to the step count (which keeps counting pf_step calls).
    const int64_t shift = int64_t(steps_) - int64_t(s.steps);
    const auto rebase = [&](uint64_t step) { return uint64_t(std::max<int64_t>(0, int64_t(step) + shift)); };
    status_step_ = rebase(s.status_step);
    // The fields the step logic compares keep their distance from the step count even below 0.
    const auto rebase_signed = [&](int64_t step) { return step + shift; };
    added_at_step_ = rebase_signed(s.added_at_step);
    cfl_step_ = rebase_signed(s.cfl_step);
    cfl_speed_ = s.cfl_speed;
    cfl_strain_ = s.cfl_strain;
    std::copy(std::begin(s.status_words), std::end(s.status_words), status_words_.begin());
    for (StepStatus& r : received_) r = StepStatus{};
    std::fill(std::begin(fence_capped_), std::end(fence_capped_), false);
    for (const StepStatus& saved : s.received) {
        if (saved.valid == 0) continue;
        StepStatus moved = saved;
        moved.step = rebase_signed(saved.step);
        received_[((moved.step % kReadbackSlots) + kReadbackSlots) % kReadbackSlots] = moved;
    }
    flags_cleared_at_step_ = rebase(s.flags_cleared_at_step);
    gpu_max_speed_ = s.gpu_max_speed;
    added_speed_ = s.added_speed;
    solver_residual_ = s.solver_residual;
    solver_iterations_ = s.solver_iterations;
    recent_iterations_ = s.recent_iterations;
    recent_later_iterations_ = s.recent_later_iterations;
    recent_solver_ = pf_pressure_solver(s.recent_solver);
    p2g_.range().restore(s.p2g_range_shift, rebase_signed(s.p2g_range_changed_at_step));  // checked above
    flags_ = s.flags;
    hydrostatic_start_pending_ = s.hydrostatic_start_pending != 0;
    fill_calls_ = s.fill_calls;
    particle_count_ = count;
    write_count_record(count);  // exact again, in both modes
    status_.upload(0, size_t(PF_STATUS_WORDS) * 4, status);
    if (count) {
        pos_.upload(0, size_t(count) * 16, pos);
        vel_.upload(0, size_t(count) * 16, vel);
        if (affine) affine_.upload(0, size_t(count) * 48, affine);
    }
    pressure_.upload(0, size_t(layout_.cells()) * 4, pressure);
    restart_volume_reference();  // the drifts and the energy reference start again
    gl_.MemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    if (GLenum err = gl_.GetError(); err != GL_NO_ERROR)
        return log_.error(PF_ERROR_GL, std::string(fn) + ": uploading the snapshot failed (GL error " + gl::hex(err) + ")");
    return PF_OK;
}

}  // namespace pf
