// A small ring of GPU-to-host readback buffers behind fences, for results a step produces and
// the host reads a few steps later without stalling (the status words, the obstacle forces).
// The owner copies into a slot's buffer at the end of a step and fences it; it takes the slot
// in once the fence has passed (arrived() never waits), or, when the slot comes round again or
// the data is needed now, reads it anyway (take() then waits for the copy): a slot is never
// dropped unread, or on a GPU running far behind no result would ever arrive. What each slot
// holds (which step, which records) stays with the owner, indexed by slot.
#pragma once
#include <array>
#include <cstddef>

#include "gl/buffer.h"
#include "gl/gl.h"

namespace pf::gl {

template <int N>
class ReadbackRing {
public:
    static constexpr int kSlots = N;

    ReadbackRing() = default;
    ReadbackRing(const ReadbackRing&) = delete;
    ReadbackRing& operator=(const ReadbackRing&) = delete;
    ~ReadbackRing() { drop_all(); }

    // Allocates the N buffers of `bytes` each (`label` names them for debuggers).
    void init(const Api& gl, size_t bytes, const char* label) {
        gl_ = &gl;
        for (Buffer& b : buffers_) b = Buffer(gl, bytes, GL_STREAM_READ, label);
    }
    // The buffer the owner copies a slot's data into.
    const Buffer& buffer(int slot) const { return buffers_[slot]; }
    // Fences `slot` behind the copy just recorded, and flushes: a poll that does not flush
    // would otherwise never see the fence pass.
    void fence(int slot) {
        fences_[slot] = gl_->FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        gl_->Flush();
    }
    // A copy was fenced into `slot` and not taken in yet.
    bool pending(int slot) const { return fences_[slot] != nullptr; }
    // A pending slot whose copy has finished (never waits).
    bool arrived(int slot) const {
        if (!fences_[slot]) return false;
        const GLenum r = gl_->ClientWaitSync(fences_[slot], GL_SYNC_FLUSH_COMMANDS_BIT, 0);
        return r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED;
    }
    // Reads the first `bytes` of a pending slot into `out` (glGetBufferSubData waits for the copy
    // if it has not run yet) and frees its fence. Buffer bindings change: call it under a
    // state guard.
    void take(int slot, void* out, size_t bytes) const {
        gl_->DeleteSync(fences_[slot]);
        fences_[slot] = nullptr;
        if (bytes) buffers_[slot].download(0, bytes, out);
    }
    // Forgets every pending slot unread (their results belong to a discarded timeline).
    void drop_all() {
        if (!gl_) return;
        for (GLsync& f : fences_) {
            if (f) gl_->DeleteSync(f);
            f = nullptr;
        }
    }

private:
    const Api* gl_ = nullptr;
    std::array<Buffer, N> buffers_{};
    mutable std::array<GLsync, N> fences_{};
};

}  // namespace pf::gl
