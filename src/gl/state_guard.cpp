#include "gl/state_guard.h"

namespace pf::gl {

namespace {
// GL 4.4 enums; the library's loader is generated for 4.3.
constexpr GLenum kQueryBuffer = 0x9192;
constexpr GLenum kQueryBufferBinding = 0x9193;
}  // namespace

StateGuard::StateGuard(const Api& gl, const Options& options) : gl_(gl), options_(options) {
    if (options_.query_buffer) {
        gl_.GetIntegerv(kQueryBufferBinding, &query_buffer_);
        if (query_buffer_) gl_.BindBuffer(kQueryBuffer, 0);
    }
    gl_.GetIntegerv(GL_CURRENT_PROGRAM, &program_);
    for (GLuint i = 0; i < PF_SLOT_COUNT; ++i) {
        save_indexed(GL_SHADER_STORAGE_BUFFER_BINDING, GL_SHADER_STORAGE_BUFFER_START,
                     GL_SHADER_STORAGE_BUFFER_SIZE, i, storage_[i]);
    }
    save_indexed(GL_UNIFORM_BUFFER_BINDING, GL_UNIFORM_BUFFER_START, GL_UNIFORM_BUFFER_SIZE,
                 PF_UBO_SIM, uniform_);
    for (int i = 0; i < kGenericCount; ++i) gl_.GetIntegerv(kGenericBinding[i], &generic_[i]);
}

StateGuard::~StateGuard() {
    gl_.UseProgram(static_cast<GLuint>(program_));
    for (GLuint i = 0; i < PF_SLOT_COUNT; ++i) restore_indexed(GL_SHADER_STORAGE_BUFFER, i, storage_[i]);
    restore_indexed(GL_UNIFORM_BUFFER, PF_UBO_SIM, uniform_);
    // Indexed binds also set the generic binding point, so generic bindings go last.
    for (int i = 0; i < kGenericCount; ++i) gl_.BindBuffer(kGeneric[i], static_cast<GLuint>(generic_[i]));
    if (query_buffer_) gl_.BindBuffer(kQueryBuffer, static_cast<GLuint>(query_buffer_));
}

void StateGuard::save_indexed(GLenum binding, GLenum start, GLenum size, GLuint index, Indexed& out) {
    gl_.GetIntegeri_v(binding, index, &out.buffer);
    gl_.GetInteger64i_v(start, index, &out.start);
    gl_.GetInteger64i_v(size, index, &out.size);
}

void StateGuard::restore_indexed(GLenum target, GLuint index, const Indexed& s) {
    const GLuint buffer = static_cast<GLuint>(s.buffer);
    if (buffer != 0 && s.size > 0) {
        gl_.BindBufferRange(target, index, buffer, static_cast<GLintptr>(s.start),
                            static_cast<GLsizeiptr>(s.size));
    } else {
        gl_.BindBufferBase(target, index, buffer);
    }
}

}  // namespace pf::gl
