// Per-pass GPU timing without stalls: each step records GL_TIMESTAMP queries around every
// pass into one slot of a small ring; results are read only once the GPU reports them
// available, a few steps later. glQueryCounter is used (not GL_TIME_ELAPSED) so an engine's
// own elapsed-time query may stay active across pf_step. Pass ids are small integers chosen
// by the owner (a runtime list: the simulation's pass list grows when a solver is added).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "gl/gl.h"

namespace pf::gl {

class TimerRing {
public:
    static constexpr int kSlots = 4;

    struct Result {
        uint64_t step = 0;  // 0: nothing measured yet
        uint32_t substeps = 0;
        std::vector<float> ms;  // indexed by pass id; shorter when high ids did not run
        float step_ms = 0.0f;   // the whole step (Mode::step only)
        float at(size_t pass) const { return pass < ms.size() ? ms[pass] : 0.0f; }
    };
    // What is timed: every pass (begin_pass / end_pass pairs), the step as a whole (one pair
    // from begin_step to end_step), or nothing.
    enum class Mode { passes, step, off };

    explicit TimerRing(const Api& gl) : gl_(gl) {
        GLint bits = 0;
        gl_.GetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
        supported_ = bits > 0;
    }
    ~TimerRing() {
        for (Slot& s : slots_) {
            if (!s.queries.empty()) gl_.DeleteQueries(static_cast<GLsizei>(s.queries.size()), s.queries.data());
        }
    }
    TimerRing(const TimerRing&) = delete;
    TimerRing& operator=(const TimerRing&) = delete;

    // From the next step on; what was measured before is forgotten (latest() reads nothing
    // until a step of the new mode is read), and steps still in flight are dropped.
    void set_mode(Mode mode) {
        if (mode == mode_) return;
        mode_ = mode;
        forget();
    }
    // Drops what was measured and what is in flight (the passes being timed changed).
    void forget() {
        latest_ = Result{};
        for (Slot& s : slots_) s.pending = false;
    }
    Mode mode() const { return mode_; }
    // Starts recording step `step`. If the slot's previous step is still in flight, that
    // step's timing is dropped rather than waited for.
    void begin_step(uint64_t step, uint32_t substeps) {
        poll();
        current_ = nullptr;
        if (!supported_ || mode_ == Mode::off) return;
        Slot& s = slots_[step % kSlots];
        s.step = step;
        s.substeps = substeps;
        s.used = 0;
        s.passes.clear();
        s.pending = true;
        s.whole_step = mode_ == Mode::step;
        current_ = &s;
        if (s.whole_step) stamp();
    }
    // The step's last pass was recorded.
    void end_step() {
        if (current_ && current_->whole_step) stamp();
        current_ = nullptr;
    }
    // Brackets one pass; begin/end pairs may repeat (substeps): they are summed.
    void begin_pass(int pass) {
        if (!current_ || current_->whole_step) return;
        current_->passes.push_back(pass);
        stamp();
    }
    void end_pass() {
        if (current_ && !current_->whole_step) stamp();
    }
    // Reads every finished slot without blocking; the newest finished step wins.
    void poll() {
        for (Slot& s : slots_) {
            if (!s.pending || s.used == 0) continue;
            GLuint available = 0;
            gl_.GetQueryObjectuiv(s.queries[s.used - 1], GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available) continue;
            s.pending = false;
            if (s.step < latest_.step) continue;
            Result r;
            r.step = s.step;
            r.substeps = s.substeps;
            if (s.whole_step && s.used == 2) {
                GLuint64 t0 = 0, t1 = 0;
                gl_.GetQueryObjectui64v(s.queries[0], GL_QUERY_RESULT, &t0);
                gl_.GetQueryObjectui64v(s.queries[1], GL_QUERY_RESULT, &t1);
                r.step_ms = static_cast<float>(static_cast<double>(t1 - t0) * 1e-6);
            }
            for (size_t p = 0; p < s.passes.size(); ++p) {
                GLuint64 t0 = 0, t1 = 0;
                gl_.GetQueryObjectui64v(s.queries[2 * p], GL_QUERY_RESULT, &t0);
                gl_.GetQueryObjectui64v(s.queries[2 * p + 1], GL_QUERY_RESULT, &t1);
                const size_t id = static_cast<size_t>(s.passes[p]);
                if (r.ms.size() <= id) r.ms.resize(id + 1, 0.0f);
                r.ms[id] += static_cast<float>(static_cast<double>(t1 - t0) * 1e-6);
            }
            latest_ = r;
        }
    }
    const Result& latest() const { return latest_; }
    bool supported() const { return supported_; }

private:
    struct Slot {
        uint64_t step = 0;
        uint32_t substeps = 0;
        bool pending = false;
        bool whole_step = false;  // Mode::step: queries 0 and 1 bracket the step
        size_t used = 0;
        std::vector<GLuint> queries;
        std::vector<int> passes;
    };
    void stamp() {
        Slot& s = *current_;
        if (s.used == s.queries.size()) {
            const size_t grow = s.queries.empty() ? 64 : s.queries.size();
            s.queries.resize(s.queries.size() + grow);
            gl_.GenQueries(static_cast<GLsizei>(grow), s.queries.data() + s.used);
        }
        gl_.QueryCounter(s.queries[s.used++], GL_TIMESTAMP);
    }

    const Api& gl_;
    bool supported_ = false;
    Mode mode_ = Mode::passes;
    std::array<Slot, kSlots> slots_{};
    Slot* current_ = nullptr;
    Result latest_{};
};

}  // namespace pf::gl
