#include "sim/particle_readback.h"

#include <atomic>
#include <cstring>
#include <string>
#include <vector>

namespace pf {

namespace {
// Tickets are unique across the process (not per simulation), so one simulation's ticket is
// never in flight in another: polling the wrong simulation is refused, not answered wrongly.
std::atomic<uint32_t> g_next_ticket{1};
uint32_t new_ticket() {
    for (;;) {
        const uint32_t t = g_next_ticket.fetch_add(1);
        if (t != 0) return t;  // 0 is never a ticket (after 2^32 requests the counter wraps)
    }
}
}  // namespace

ParticleReadback::ParticleReadback(const gl::Api& gl)
    : gl_(gl), persistent_(gl.ARB_buffer_storage && gl.BufferStorage && gl.MapBufferRange) {}

ParticleReadback::~ParticleReadback() {
    for (Slot& s : slots_)
        if (s.fence) gl_.DeleteSync(s.fence);
    // The buffers (and with them their persistent mappings) go with the slots.
}

uint32_t ParticleReadback::in_flight() const {
    uint32_t n = 0;
    for (const Slot& s : slots_) n += s.ticket != 0 ? 1u : 0u;
    return n;
}

pf_result ParticleReadback::request(const gl::Buffer& pos, const gl::Buffer& vel, uint32_t first, uint32_t count,
                                    uint32_t* ticket, const Log& log) {
    Slot* slot = nullptr;
    for (Slot& s : slots_)
        if (!s.ticket) {
            slot = &s;
            break;
        }
    if (!slot) {
        return log.error(PF_ERROR_CAPACITY, "pf_request_particles: already " + std::to_string(kSlots) +
                                                " requests in flight (PF_MAX_PARTICLE_REQUESTS); poll one to completion first");
    }
    const size_t bytes = size_t(count) * 32;
    if (slot->buffer.bytes() < bytes) {
        // Grown to the largest request this slot has held; kept for the next ones.
        slot->mapped = nullptr;
        if (persistent_) {
            GLuint id = 0;
            gl_.GenBuffers(1, &id);
            gl_.BindBuffer(GL_COPY_WRITE_BUFFER, id);
            const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
            gl_.BufferStorage(GL_COPY_WRITE_BUFFER, GLsizeiptr(bytes), nullptr, flags);
            slot->buffer = gl::Buffer::adopt(gl_, id, bytes, "particle_request");
            slot->mapped = gl_.MapBufferRange(GL_COPY_WRITE_BUFFER, 0, GLsizeiptr(bytes), flags);
        } else {
            slot->buffer = gl::Buffer(gl_, bytes, GL_STREAM_READ, "particle_request");
        }
        if (GLenum err = gl_.GetError(); err != GL_NO_ERROR || (persistent_ && !slot->mapped)) {
            slot->buffer = gl::Buffer();
            slot->mapped = nullptr;
            return log.error(err == GL_OUT_OF_MEMORY ? PF_ERROR_OUT_OF_MEMORY : PF_ERROR_GL,
                             "pf_request_particles: allocating a readback buffer of " + std::to_string(bytes) +
                                 " bytes failed (GL error " + gl::hex(err) + ")");
        }
    }
    if (count) {
        // Copies read what the step's shaders wrote (pf_step ends with this barrier too).
        gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        gl_.BindBuffer(GL_COPY_WRITE_BUFFER, slot->buffer.id());
        gl_.BindBuffer(GL_COPY_READ_BUFFER, pos.id());
        gl_.CopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, GLintptr(first) * 16, 0, GLsizeiptr(count) * 16);
        gl_.BindBuffer(GL_COPY_READ_BUFFER, vel.id());
        gl_.CopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, GLintptr(first) * 16, GLintptr(count) * 16,
                              GLsizeiptr(count) * 16);
    }
    slot->fence = gl_.FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    gl_.Flush();  // the fence must reach the GPU, or a poll without flushing would never see it pass
    slot->count = count;
    slot->ticket = new_ticket();
    *ticket = slot->ticket;
    return PF_OK;
}

pf_result ParticleReadback::poll(uint32_t ticket, float* xyz, float* vel, const Log& log) {
    Slot* slot = nullptr;
    for (Slot& s : slots_)
        if (ticket != 0 && s.ticket == ticket) slot = &s;
    if (!slot) {
        return log.error(PF_ERROR_INVALID_ARGUMENT, "pf_poll_particles: ticket " + std::to_string(ticket) +
                                                        " is not in flight (never issued, or already collected)");
    }
    // A test of the fence, never a wait (timeout 0, no flush: request() flushed).
    const GLenum r = gl_.ClientWaitSync(slot->fence, 0, 0);
    if (r == GL_WAIT_FAILED) {
        return log.error(PF_ERROR_GL, "pf_poll_particles: glClientWaitSync failed on ticket " + std::to_string(ticket));
    }
    if (r != GL_ALREADY_SIGNALED && r != GL_CONDITION_SATISFIED) return PF_NOT_READY;
    const uint32_t n = slot->count;
    if (n && (xyz || vel)) {
        std::vector<float> tmp;
        const float* data = static_cast<const float*>(slot->mapped);
        if (!data) {
            tmp.resize(size_t(n) * 8);
            slot->buffer.download(0, tmp.size() * 4, tmp.data());
            data = tmp.data();
        }
        for (uint32_t i = 0; i < n; ++i) {
            for (int a = 0; a < 3; ++a) {
                if (xyz) xyz[size_t(i) * 3 + a] = data[size_t(i) * 4 + a];
                if (vel) vel[size_t(i) * 3 + a] = data[(size_t(n) + i) * 4 + a];
            }
        }
    }
    gl_.DeleteSync(slot->fence);
    slot->fence = nullptr;
    slot->ticket = 0;
    slot->count = 0;
    return PF_OK;
}

}  // namespace pf
