// Asynchronous particle readback (pf_request_particles / pf_poll_particles): each request copies
// a range of the particle buffers on the GPU into a buffer of its own and sets a fence; a poll
// tests the fence without waiting and, once it has passed, reads the copy, which no GPU work
// touches any more, so nothing stalls. With ARB_buffer_storage (GL 4.4) the buffers are mapped
// persistently (read with memcpy), else read with glGetBufferSubData after the fence.
#pragma once
#include <array>
#include <cstdint>

#include "api/log.h"
#include "gl/buffer.h"
#include "gl/gl.h"
#include "pf/pf.h"

namespace pf {

class ParticleReadback {
public:
    static constexpr uint32_t kSlots = PF_MAX_PARTICLE_REQUESTS;

    explicit ParticleReadback(const gl::Api& gl);
    ~ParticleReadback();
    ParticleReadback(const ParticleReadback&) = delete;
    ParticleReadback& operator=(const ParticleReadback&) = delete;

    // Copies particles [first, first + count) of pos and vel (vec4 each) into a free slot (GL
    // state guarded by the caller); PF_ERROR_CAPACITY when every slot is taken.
    pf_result request(const gl::Buffer& pos, const gl::Buffer& vel, uint32_t first, uint32_t count, uint32_t* ticket,
                      const Log& log);
    // PF_NOT_READY while the copy is in flight; PF_OK once it was written to xyz / vel (3 floats a
    // particle, either may be NULL) and the ticket released; PF_ERROR_INVALID_ARGUMENT for a
    // ticket that is not in flight (nothing changes).
    pf_result poll(uint32_t ticket, float* xyz, float* vel, const Log& log);
    // Requests in flight (tests).
    uint32_t in_flight() const;
    bool persistent() const { return persistent_; }

private:
    struct Slot {
        uint32_t ticket = 0;  // 0: free
        uint32_t count = 0;
        gl::Buffer buffer;    // count vec4 positions, then count vec4 velocities
        void* mapped = nullptr;
        GLsync fence = nullptr;
    };
    const gl::Api& gl_;
    bool persistent_ = false;
    std::array<Slot, kSlots> slots_{};
};

}  // namespace pf
