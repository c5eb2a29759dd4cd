// Runs Pass descriptions: builds their programs, binds the uniform block and every storage
// slot a pass names, dispatches (directly or indirectly), inserts the barrier, counts the
// dispatch and times it. Timing follows the statistics list: consecutive passes of one entry
// share a pair of GPU timestamps, a new entry starts a new pair.
//
// The runner checks each pass against its program: the storage slots and the explicit-location
// uniforms the linked program actually uses (queried from the GL) must all be bound and set by
// the pass. A missing one is a bug in pflip; it is logged once per program and counted
// (binding_errors(), asserted to be 0 by the tests). Uniform values a pass names that the
// linker removed are skipped (setting them would be a GL error on drivers that remove them).
// Sampler uniforms are not checked: they are bound to units by layout(binding), and a pass that
// samples (the SDF obstacles) names its textures, bound for its dispatch only and the units'
// previous texture and sampler put back right after (the engine's state is kept).
#pragma once
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "api/log.h"
#include "gl/gl.h"
#include "gl/program.h"
#include "gl/timer_ring.h"
#include "pf/pf.h"
#include "sim/pass.h"

namespace pf {

class PassRunner {
public:
    // One entry of the runtime statistics list.
    struct Stat {
        std::string name;   // stable short name shown by pf_get_pass_stats ("p2g", "jacobi", ...)
        pf_pass group;      // the pf_stats.gpu_ms / dispatches slot it adds to
        uint32_t dispatches = 0;  // in the current (or last) step
        std::string debug_group;  // "pflip/<name>": the KHR_debug group of its dispatches
    };

    // `binaries`: the engine's program-binary cache its programs go through (may be null).
    PassRunner(const gl::Api& gl, const Log& log, const gl::Buffer& uniforms, GLuint uniform_slot,
               gl::ProgramBinaryCache* binaries = nullptr);

    // Adds an entry to the statistics list (or returns the existing one of that name).
    StatId add_stat(const std::string& name, pf_pass group);
    // A deque: entries never move, so the names pf_get_pass_stats hands out stay valid as it grows.
    const std::deque<Stat>& stats() const { return stats_; }
    // GPU milliseconds of entry `id` in the newest measured step (0 until one is measured).
    float gpu_ms(StatId id) const { return timers_.latest().at(id); }
    const gl::TimerRing::Result& latest_timing() const { return timers_.latest(); }
    void poll_timers() { timers_.poll(); }
    // What the next steps time (pf_set_gpu_timing).
    void set_timing(gl::TimerRing::Mode mode) { timers_.set_mode(mode); }
    gl::TimerRing::Mode timing() const { return timers_.mode(); }
    // Per kernel (PF_GPU_TIMING_KERNELS, with Mode::passes): inside a step, each pass is counted
    // and timed under "<entry>:<program>" (added on first use) instead of its entry.
    void set_kernel_timing(bool on) {
        if (on != kernel_timing_) timers_.forget();
        kernel_timing_ = on;
    }
    bool kernel_timing() const { return kernel_timing_; }

    // Builds `id` (once) and learns which storage slots it uses. Empty string on success.
    std::string prepare(gl::ProgramId id);
    // GL name of a prepared program, 0 if not prepared.
    GLuint program(gl::ProgramId id) const { return programs_.built(id); }
    // Programs linked so far (tests: effects that are off build none).
    uint32_t programs_built() const { return programs_.built_count(); }

    // Starts a step: clears the dispatch counts and opens a timing slot.
    void begin_step(uint64_t step, uint32_t substeps);
    // Closes the open timing pair (end of a step).
    void end_step();
    // Copies `bytes` from src to dst on the GPU, after everything earlier passes wrote.
    void copy(const gl::Buffer& src, const gl::Buffer& dst, size_t bytes) { copy(src, 0, dst, 0, bytes); }
    void copy(const gl::Buffer& src, size_t src_offset, const gl::Buffer& dst, size_t dst_offset, size_t bytes);
    // Runs one pass (the program must have been prepared) inside the debug group
    // "pflip/<statistics entry name>" when the GL has KHR_debug (src/gl/debug.h). Timed and counted inside a step
    // (begin_step .. end_step), neither outside one (creation, pf_push, pf_clear_particles).
    void run(const Pass& pass);
    // Sets the first `words` words of `buffer` to `value` (a pass of the fill program, which the
    // owner of this runner prepares), counted and timed as entry `stat`.
    void fill(const gl::Buffer& buffer, uint32_t words, uint32_t value, StatId stat);

    // While alive, every pass run is counted, timed and labelled as entry `stat` instead of its
    // own: a solver serving a second problem (the volume correction's) is accounted apart from
    // the pressure solve.
    class StatScope {
    public:
        StatScope(PassRunner& runner, StatId stat) : runner_(runner), saved_(runner.override_) { runner.override_ = stat; }
        ~StatScope() { runner_.override_ = saved_; }
        StatScope(const StatScope&) = delete;
        StatScope& operator=(const StatScope&) = delete;

    private:
        PassRunner& runner_;
        StatId saved_;
    };

    // A pass (its statistics entry resolved when it was recorded) or a copy, kept by a
    // Recording instead of being issued.
    struct RecordedOp {
        enum class Kind : uint8_t { pass, copy };
        Kind kind = Kind::pass;
        Pass pass;
        const gl::Buffer* copy_src = nullptr;
        const gl::Buffer* copy_dst = nullptr;
        size_t copy_src_offset = 0, copy_dst_offset = 0, copy_bytes = 0;
    };
    using Recorded = std::vector<RecordedOp>;
    // While alive, run(), fill() and copy() append to `into` instead of issuing; nothing is
    // counted or timed until run_interleaved issues it. The passes' buffers must outlive that.
    class Recording {
    public:
        Recording(PassRunner& runner, Recorded& into) : runner_(runner), saved_(runner.recording_) { runner.recording_ = &into; }
        ~Recording() { runner_.recording_ = saved_; }
        Recording(const Recording&) = delete;
        Recording& operator=(const Recording&) = delete;

    private:
        PassRunner& runner_;
        Recorded* saved_;
    };
    // Issues two recordings of independent work (neither reads what the other writes) in
    // lockstep: one barrier before each pair of their passes and none between the two, so the
    // GPU may overlap them (docs/notes/2026-12-01-overlapping-solves-leapfrog.md). Each pass is
    // counted under its own entry; the whole is timed as one pair under the entry of the first
    // pass of `a` (else of `b`; a timestamp between the two would wait for the first).
    void run_interleaved(const Recorded& a, const Recorded& b);

    uint32_t binding_errors() const { return binding_errors_; }
    // The workgroups run() dispatches for `invocations` on this GL.
    Workgroups workgroups(uint64_t invocations) const { return workgroups_for(invocations, max_groups_x_); }

    // Programs that write indirect-dispatch records (a solver's start, convergence checks and
    // Krylov scalars). Only after one of them does the next indirect dispatch need
    // GL_COMMAND_BARRIER_BIT; tests/internal/test_pass_pipeline.cpp keeps the list complete by
    // scanning every program's source.
    static bool writes_indirect_records(gl::ProgramId id);

private:

    const gl::Api& gl_;
    const Log& log_;
    const gl::Buffer& uniforms_;
    GLuint uniform_slot_;
    gl::ProgramCache programs_;
    gl::TimerRing timers_;
    std::deque<Stat> stats_;
    // The "<entry>:<program>" entry of a pass (kernel timing), keyed by entry << 16 | program.
    StatId kernel_stat(StatId stat, gl::ProgramId program);
    std::unordered_map<uint32_t, StatId> kernel_stats_;
    bool kernel_timing_ = false;
    void set_uniforms(GLuint program, size_t pid, const Uniforms& uniforms);
    // Starts a timing pair for `stat` unless one is open for it (inside a step).
    void open_timing(StatId stat);
    // Checks, binds and dispatches `pass` (inside the debug group of `stat`): after a storage
    // barrier when `barrier`, or when it is indirect and `records_written` (a command barrier
    // too), which it then clears and sets again if the pass writes records.
    void issue(const Pass& pass, StatId stat, bool barrier, bool& records_written);
    Recorded* recording_ = nullptr;  // Recording

    std::vector<uint32_t> used_slots_;   // per ProgramId: bit mask of storage slots in use
    std::vector<uint32_t> used_uniforms_;  // per ProgramId: bit mask of explicit uniform locations in use
    std::vector<bool> reported_;         // per ProgramId: a binding error was logged
    GLint max_groups_x_ = 65535;
    bool step_open_ = false;
    bool pair_open_ = false;
    bool records_written_ = true;  // an indirect record may have changed since the last command barrier
    StatId open_stat_ = 0;
    static constexpr StatId kNoOverride = ~StatId(0);
    StatId override_ = kNoOverride;  // StatScope
    uint32_t binding_errors_ = 0;
};

}  // namespace pf
