// pf::SimUniforms: the C++ side of the per-substep uniform block. Its members come from the
// same list as the GLSL block (shaders/common/sim_uniforms.h), so the two cannot drift; the
// std140 rules that make the offsets agree are checked here at compile time and against the
// GL's reported offsets in tests/internal/test_uniform_layout.cpp.
#pragma once
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace pf {
namespace glsl_types {
// GLSL type names as C++ types, so each PF_UNIFORM line reads the same in both languages.
using uint = uint32_t;
using vec4 = glm::vec4;
using ivec4 = glm::ivec4;
using uvec4 = glm::uvec4;

struct SimUniforms {
#define PF_UNIFORM(type, name) type name;
#include "common/sim_uniforms.h"
#undef PF_UNIFORM
};

// std140 base alignment of each allowed member type.
template <typename T> constexpr size_t std140_alignment() { return sizeof(T) == 16 ? 16 : 4; }
template <typename T> constexpr bool std140_allowed() { return sizeof(T) == 4 || sizeof(T) == 16; }

#define PF_UNIFORM(type, name)                                                                    \
    static_assert(std140_allowed<type>(), "sim_uniforms.h: " #name " must be a scalar or a 4-vector"); \
    static_assert(offsetof(SimUniforms, name) % std140_alignment<type>() == 0,                     \
                  "sim_uniforms.h: " #name " breaks std140 alignment (start vectors at 16 bytes)");
#include "common/sim_uniforms.h"
#undef PF_UNIFORM
static_assert(sizeof(SimUniforms) % 16 == 0, "sim_uniforms.h: pad the block to a multiple of 16 bytes");
}  // namespace glsl_types

using glsl_types::SimUniforms;

// Member names and offsets, for the layout test.
struct UniformMember {
    const char* name;
    size_t offset;
};
inline constexpr UniformMember kSimUniformMembers[] = {
#define PF_UNIFORM(type, name) {#name, offsetof(SimUniforms, name)},
#include "common/sim_uniforms.h"
#undef PF_UNIFORM
};

}  // namespace pf
