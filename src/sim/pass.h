// A compute pass described as data: the program, the buffer on every storage slot it uses,
// its size (invocations, or an indirect-argument record written on the GPU) and the entry of
// the per-pass statistics list it counts towards. PassRunner binds everything a pass names on
// every dispatch, so no pass depends on bindings an earlier one left behind.
#pragma once
#include <array>
#include <cstdint>
#include <initializer_list>

#include "common/slots.h"
#include "gl/buffer.h"
#include "gl/shader_source.h"

namespace pf {

// Index into the runtime list of pass statistics (PassRunner::add_stat).
using StatId = uint32_t;

// One storage-buffer binding: slot (shaders/common/slots.h) and the buffer bound there.
struct Bind {
    GLuint slot = 0;
    const gl::Buffer* buffer = nullptr;
};

// The storage bindings of one pass (at most PF_SLOT_COUNT, the GL 4.3 minimum).
class Bindings {
public:
    Bindings() = default;
    Bindings(std::initializer_list<Bind> binds) {
        for (const Bind& b : binds) binds_[count_++] = b;  // PassRunner rejects count_ > slots
    }
    const Bind* begin() const { return binds_.data(); }
    const Bind* end() const { return binds_.data() + count_; }
    uint32_t mask() const {
        uint32_t m = 0;
        for (const Bind& b : *this) m |= 1u << b.slot;
        return m;
    }

private:
    std::array<Bind, PF_SLOT_COUNT> binds_{};
    uint32_t count_ = 0;
};

// Indirect dispatch arguments: three uints (groups x, y, z) at `offset` in `buffer`, written by
// an earlier pass (solvers write zero groups once they have converged).
struct Indirect {
    const gl::Buffer* buffer = nullptr;
    uint32_t offset = 0;
};

struct Pass {
    gl::ProgramId program;
    StatId stat;
    uint64_t invocations = 0;  // direct dispatch: one invocation per item (0: skipped)
    Bindings binds;
    Indirect indirect{};       // when indirect.buffer is set, invocations is ignored
};

}  // namespace pf
