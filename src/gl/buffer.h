// Owning handle of one GL buffer object (deleted with its owner; never an engine's buffer).
#pragma once
#include <cstddef>
#include <utility>

#include "gl/debug.h"
#include "gl/gl.h"

namespace pf::gl {

class Buffer {
public:
    Buffer() = default;
    // `label` names it for debuggers ("pflip/<label>", src/gl/debug.h).
    Buffer(const Api& gl, size_t bytes, GLenum usage, const char* label) : gl_(&gl), bytes_(bytes) {
        gl.GenBuffers(1, &id_);
        // COPY_WRITE is a binding the state guard restores; allocation needs some target.
        gl.BindBuffer(GL_COPY_WRITE_BUFFER, id_);
        gl.BufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, usage);
        label_object(gl, GL_BUFFER, id_, label);
    }
    ~Buffer() { reset(); }
    // Takes ownership of buffer `id` (made and allocated by the caller, e.g. with glBufferStorage).
    static Buffer adopt(const Api& gl, GLuint id, size_t bytes, const char* label) {
        Buffer b;
        b.gl_ = &gl;
        b.id_ = id;
        b.bytes_ = bytes;
        label_object(gl, GL_BUFFER, id, label);
        return b;
    }
    Buffer(Buffer&& o) noexcept { *this = std::move(o); }
    Buffer& operator=(Buffer&& o) noexcept {
        if (this != &o) {
            reset();
            std::swap(gl_, o.gl_);
            std::swap(id_, o.id_);
            std::swap(bytes_, o.bytes_);
        }
        return *this;
    }
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    GLuint id() const { return id_; }
    size_t bytes() const { return bytes_; }

    // Both wait for shader writes first: storage writes are incoherent, and without
    // GL_BUFFER_UPDATE_BARRIER_BIT a shader's earlier store may land after (or be missed by) the
    // update. Mesa's llvmpipe happens to serialise them; NVIDIA does not (a compute clear then
    // an upload of the same buffer lost the upload there).
    void upload(size_t offset, size_t bytes, const void* data) const {
        gl_->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        gl_->BindBuffer(GL_COPY_WRITE_BUFFER, id_);
        gl_->BufferSubData(GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
    }
    void download(size_t offset, size_t bytes, void* data) const {
        gl_->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        gl_->BindBuffer(GL_COPY_READ_BUFFER, id_);
        gl_->GetBufferSubData(GL_COPY_READ_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
    }

private:
    void reset() {
        if (gl_ && id_) gl_->DeleteBuffers(1, &id_);
        id_ = 0;
        bytes_ = 0;
    }
    const Api* gl_ = nullptr;
    GLuint id_ = 0;
    size_t bytes_ = 0;
};

}  // namespace pf::gl
