// Saves the GL state pflip's calls touch and restores it on scope exit, so an engine's
// bindings survive every pf_* call: current program, indexed storage/uniform bindings the
// kernels use, the generic buffer bindings used for uploads and readbacks, and (GL 4.4+)
// the query buffer, which is unbound meanwhile so query results land in host memory.
#pragma once
#include <array>

#include "common/slots.h"
#include "gl/gl.h"

namespace pf::gl {

class StateGuard {
public:
    struct Options {
        bool query_buffer = false;  // GL >= 4.4: save GL_QUERY_BUFFER and unbind it meanwhile
    };
    StateGuard(const Api& gl, const Options& options);
    ~StateGuard();
    StateGuard(const StateGuard&) = delete;
    StateGuard& operator=(const StateGuard&) = delete;

private:
    struct Indexed {
        GLint buffer = 0;
        GLint64 start = 0;
        GLint64 size = 0;
    };
    static constexpr GLenum kGeneric[] = {GL_SHADER_STORAGE_BUFFER, GL_UNIFORM_BUFFER,
                                          GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER,
                                          GL_DISPATCH_INDIRECT_BUFFER, GL_DRAW_INDIRECT_BUFFER};
    static constexpr GLenum kGenericBinding[] = {
        GL_SHADER_STORAGE_BUFFER_BINDING, GL_UNIFORM_BUFFER_BINDING, GL_COPY_READ_BUFFER_BINDING,
        GL_COPY_WRITE_BUFFER_BINDING, GL_DISPATCH_INDIRECT_BUFFER_BINDING, GL_DRAW_INDIRECT_BUFFER_BINDING};
    static constexpr int kGenericCount = 6;

    void save_indexed(GLenum binding, GLenum start, GLenum size, GLuint index, Indexed& out);
    void restore_indexed(GLenum target, GLuint index, const Indexed& s);

    const Api& gl_;
    Options options_;
    GLint program_ = 0;
    GLint query_buffer_ = 0;
    std::array<Indexed, PF_SLOT_COUNT> storage_{};
    Indexed uniform_{};
    std::array<GLint, kGenericCount> generic_{};
};

}  // namespace pf::gl
