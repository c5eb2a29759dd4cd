// A compute pass described as data: the program, the buffer on every storage slot it uses,
// the value of every explicit-location uniform it uses, its size (invocations, or an
// indirect-argument record written on the GPU) and the entry of the per-pass statistics list it
// counts towards. PassRunner binds and sets everything a pass names on every dispatch, so no
// pass depends on bindings or uniform values an earlier one left behind.
#pragma once
#include <array>
#include <cstdint>
#include <initializer_list>

#include "common/slots.h"
#include "gl/buffer.h"
#include "gl/shader_source.h"

namespace pf {

// The workgroups of a dispatch of `invocations` (PF_WORKGROUP_SIZE each), folded into a 2D
// grid with x at most max_groups_x (flat_id() in shaders/common/dispatch.glsl unfolds it).
// Every workgroup of the grid runs, so a reduction over it writes x * y partial sums.
struct Workgroups {
    uint32_t x = 0, y = 0;
    uint32_t total() const { return x * y; }
};
inline Workgroups workgroups_for(uint64_t invocations, int32_t max_groups_x) {
    const uint64_t groups = (invocations + PF_WORKGROUP_SIZE - 1) / PF_WORKGROUP_SIZE;
    const uint64_t x = groups < uint64_t(max_groups_x) ? groups : uint64_t(max_groups_x);
    return x == 0 ? Workgroups{} : Workgroups{uint32_t(x), uint32_t((groups + x - 1) / x)};
}

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
        for (const Bind& b : binds) add(b);
    }
    // One more binding, for passes whose optional buffers depend on the program chosen.
    void add(const Bind& b) {
        if (mask() & (1u << b.slot)) twice_ |= 1u << b.slot;  // the later would replace the earlier
        if (count_ < binds_.size()) binds_[count_++] = b;
        else overflow_ = true;  // PassRunner refuses the pass
    }
    bool overflow() const { return overflow_; }
    // Slots named twice (PassRunner refuses the pass: one of the kernel's blocks would read or
    // write the other's buffer).
    uint32_t twice() const { return twice_; }
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
    uint32_t twice_ = 0;
    bool overflow_ = false;
};

// One explicit-location uniform value (`layout(location = N) uniform ...` in the kernel).
struct Uniform {
    enum class Kind : uint8_t { uint1, float1, ivec4, vec4 };
    GLint location = -1;
    Kind kind = Kind::uint1;
    union {
        uint32_t u;
        float f;
        int32_t i[4];
        float v[4];
    } value{};

    static Uniform uint1(GLint location, uint32_t v) {
        Uniform u{location, Kind::uint1, {}};
        u.value.u = v;
        return u;
    }
    static Uniform float1(GLint location, float v) {
        Uniform u{location, Kind::float1, {}};
        u.value.f = v;
        return u;
    }
    static Uniform ivec4(GLint location, int32_t x, int32_t y, int32_t z, int32_t w) {
        Uniform u{location, Kind::ivec4, {}};
        u.value.i[0] = x, u.value.i[1] = y, u.value.i[2] = z, u.value.i[3] = w;
        return u;
    }
    static Uniform vec4(GLint location, float x, float y, float z, float w) {
        Uniform u{location, Kind::vec4, {}};
        u.value.v[0] = x, u.value.v[1] = y, u.value.v[2] = z, u.value.v[3] = w;
        return u;
    }
};

// The uniform values of one pass (at most kMaxUniforms).
class Uniforms {
public:
    static constexpr size_t kMaxUniforms = 6;
    Uniforms() = default;
    Uniforms(std::initializer_list<Uniform> values) {
        for (const Uniform& u : values) {
            if (count_ < values_.size()) values_[count_++] = u;
            else overflow_ = true;  // PassRunner refuses the pass
        }
    }
    bool overflow() const { return overflow_; }
    const Uniform* begin() const { return values_.data(); }
    const Uniform* end() const { return values_.data() + count_; }
    uint32_t mask() const {
        uint32_t m = 0;
        for (const Uniform& u : *this) m |= u.location >= 0 && u.location < 32 ? 1u << u.location : 0u;
        return m;
    }

private:
    std::array<Uniform, kMaxUniforms> values_{};
    uint32_t count_ = 0;
    bool overflow_ = false;
};

// Indirect dispatch arguments: three uints (groups x, y, z) at `offset` in `buffer`, written by
// an earlier pass (solvers write zero groups once they have converged).
struct Indirect {
    const gl::Buffer* buffer = nullptr;
    uint32_t offset = 0;
};

// The 3D textures a pass samples (the engine's signed-distance textures of SDF obstacles): each
// bound with `sampler` to texture unit `unit` for the pass's dispatch only; PassRunner puts the
// unit's previous texture and sampler back right after it (the engine's state is kept).
class Textures {
public:
    static constexpr size_t kMaxTextures = 16;
    struct Bind {
        GLuint unit = 0, texture = 0, sampler = 0;
    };
    void add(GLuint unit, GLuint texture, GLuint sampler) {
        if (count_ < binds_.size()) binds_[count_++] = Bind{unit, texture, sampler};
    }
    const Bind* begin() const { return binds_.data(); }
    const Bind* end() const { return binds_.data() + count_; }
    bool empty() const { return count_ == 0; }

private:
    std::array<Bind, kMaxTextures> binds_{};
    uint32_t count_ = 0;
};

struct Pass {
    gl::ProgramId program;
    StatId stat;
    uint64_t invocations = 0;  // direct dispatch: one invocation per item (0: skipped)
    Bindings binds;
    Indirect indirect{};       // when indirect.buffer is set, invocations is ignored
    Uniforms uniforms{};
    Textures textures{};       // GL_TEXTURE_3D bindings (none for most passes)
};

}  // namespace pf
