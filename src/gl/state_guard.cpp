#include "gl/state_guard.h"

namespace pf::gl {

StateGuard::StateGuard(const Api& gl) : gl_(gl) {
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
