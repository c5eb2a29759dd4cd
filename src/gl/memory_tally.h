// GPU memory a simulation holds, kept by every gl::Buffer it allocates: the simulation points its
// GL context's userptr (a field glad leaves to its user) at its tally, so no owner of a buffer
// reports its allocations and none is forgotten. Buffers say what their size follows.
#pragma once
#include <cstdint>

#include "gl/gl.h"

namespace pf::gl {

// What a buffer's size follows: the particle capacity (max_particles), or anything else (the
// grid, a fixed size).
enum class Sizing { other, particles };

struct MemoryTally {
    uint64_t bytes = 0;           // every buffer
    uint64_t particle_bytes = 0;  // those of Sizing::particles

    void add(Sizing sizing, uint64_t n) {
        bytes += n;
        if (sizing == Sizing::particles) particle_bytes += n;
    }
    void remove(Sizing sizing, uint64_t n) {
        bytes -= n;
        if (sizing == Sizing::particles) particle_bytes -= n;
    }
};

// The tally of the simulation whose context `gl` is (nullptr for a context without one).
inline MemoryTally* memory_tally(const Api& gl) { return static_cast<MemoryTally*>(gl.userptr); }

}  // namespace pf::gl
