// The engine's side of the GL etiquette tests (pf.h "GL contract", docs/design.md §6): a
// field-by-field snapshot of every piece of GL state an engine could notice, and an Engine
// with its own program, buffers, VAO, FBO, textures and raster state, bound in a distinctive
// (and, for pflip's draws, hostile) way. Uses the app's GLAD, as an engine would.
#pragma once
#include <glad/gl.h>

// GL 4.4 (ARB_query_buffer_object); the app GLAD is generated for 4.3.
#ifndef GL_QUERY_BUFFER
#define GL_QUERY_BUFFER 0x9192
#endif
#ifndef GL_QUERY_BUFFER_BINDING
#define GL_QUERY_BUFFER_BINDING 0x9193
#endif
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pf::test {

const char* gl_error_name(GLenum e);
void drain_gl_errors();
GLint geti(GLenum pname);
bool gl_at_least(int major, int minor);

struct Snapshot {
    std::vector<std::pair<std::string, int64_t>> fields;
    void add(const std::string& name, int64_t v) { fields.emplace_back(name, v); }
};

// Buffer bindings, VAO/FBO/program bindings, viewport/scissor, texture and sampler bindings
// of units 0-7 (2D, 3D, cube), image units 0-3, every capability, per-draw-buffer blend and
// colour mask, per-viewport scissor test, depth/stencil/polygon state, clear values, the
// bound VAO's vertex buffer bindings and the bound FBO's draw/read buffers.
Snapshot snapshot();
// Every field that differs, one per line; empty when the states match.
std::string diff(const Snapshot& before, const Snapshot& after);

enum class EngineProgram { compute, graphics };

class Engine {
public:
    static constexpr int kBuffers = 40;
    static constexpr int kTextureUnits = 8;

    explicit Engine(EngineProgram kind);
    ~Engine();
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    // Binds everything and sets odd raster state; `variant` rotates which buffer sits where
    // and which raster switches are on, so each call sees a new layout.
    void bind(int variant);
    void unbind_all();
    // Every engine object still exists and every buffer still holds what the engine wrote.
    void expect_intact(const std::string& after) const;

    GLuint buffer(int i) const { return buffers_[size_t(i)]; }
    // Also keep an engine buffer on GL_QUERY_BUFFER (GL 4.4+) from the next bind() on.
    void bind_query_buffer(bool on) { query_buffer_ = on; }

private:
    GLuint program_ = 0, vao_ = 0, fbo_ = 0, sampler_ = 0, cube_ = 0;
    GLuint textures_[kTextureUnits] = {};
    std::vector<GLuint> buffers_;
    std::vector<std::vector<uint8_t>> contents_;
    GLint ssbo_align_ = 1, ubo_align_ = 1;
    size_t bytes_ = 0;
    bool query_buffer_ = false;
};

// Binds the engine's state (layout `variant`), runs `call`, and checks that the state is
// unchanged field by field, that no GL error is pending and that engine buffers are intact.
template <typename Fn>
void guarded_call(Engine& engine, int variant, const char* what, Fn&& call) {
    SCOPED_TRACE(what);
    engine.bind(variant);
    drain_gl_errors();
    const Snapshot before = snapshot();
    call();
    const GLenum err = glGetError();
    const Snapshot after = snapshot();
    EXPECT_EQ(err, GLenum(GL_NO_ERROR)) << what << " left " << gl_error_name(err) << " (0x" << std::hex << err << ")";
    const std::string d = diff(before, after);
    EXPECT_TRUE(d.empty()) << what << " changed the engine's GL state:\n" << d;
    engine.expect_intact(what);
}

}  // namespace pf::test
