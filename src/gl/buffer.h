// Owning handle of one GL buffer object (deleted with its owner; never an engine's buffer).
#pragma once
#include <cstddef>
#include <utility>

#include "gl/debug.h"
#include "gl/gl.h"
#include "gl/memory_tally.h"

namespace pf::gl {

class Buffer {
public:
    Buffer() = default;
    // `label` names it for debuggers ("pflip/<label>", src/gl/debug.h); `sizing` says what its
    // size follows, for the simulation's memory tally (gl/memory_tally.h).
    Buffer(const Api& gl, size_t bytes, GLenum usage, const char* label, Sizing sizing = Sizing::other)
        : gl_(&gl), bytes_(bytes), sizing_(sizing) {
        gl.GenBuffers(1, &id_);
        // COPY_WRITE is a binding the state guard restores; allocation needs some target.
        gl.BindBuffer(GL_COPY_WRITE_BUFFER, id_);
        gl.BufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, usage);
        label_object(gl, GL_BUFFER, id_, label);
        if (MemoryTally* tally = memory_tally(gl)) tally->add(sizing_, bytes_);
    }
    ~Buffer() { reset(); }
    // Takes ownership of buffer `id` (made and allocated by the caller, e.g. with glBufferStorage).
    static Buffer adopt(const Api& gl, GLuint id, size_t bytes, const char* label) {
        Buffer b;
        b.gl_ = &gl;
        b.id_ = id;
        b.bytes_ = bytes;
        label_object(gl, GL_BUFFER, id, label);
        if (MemoryTally* tally = memory_tally(gl)) tally->add(b.sizing_, bytes);
        return b;
    }
    Buffer(Buffer&& o) noexcept { *this = std::move(o); }
    Buffer& operator=(Buffer&& o) noexcept {
        if (this != &o) {
            reset();
            std::swap(gl_, o.gl_);
            std::swap(id_, o.id_);
            std::swap(bytes_, o.bytes_);
            std::swap(sizing_, o.sizing_);
        }
        return *this;
    }
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    GLuint id() const { return id_; }
    size_t bytes() const { return bytes_; }

    // Writes `bytes` at `offset` on the GPU's timeline: the data goes into a fresh staging
    // buffer and glCopyBufferSubData moves it, after a barrier, behind every dispatch issued
    // before. A plain glBufferSubData over storage a compute pass wrote is not ordered on NVIDIA
    // (580 driver, H100): a compute clear followed by an upload of the same words lost the
    // upload even with every barrier bit set (tests/internal/test_upload_order.cpp; Mesa's
    // llvmpipe happens to serialise them).
    void upload(size_t offset, size_t bytes, const void* data) const {
        if (bytes == 0) return;
        GLuint staging = 0;
        gl_->GenBuffers(1, &staging);
        gl_->BindBuffer(GL_COPY_READ_BUFFER, staging);
        gl_->BufferData(GL_COPY_READ_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STREAM_COPY);
        label_object(*gl_, GL_BUFFER, staging, "upload_staging");
        gl_->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        gl_->BindBuffer(GL_COPY_WRITE_BUFFER, id_);
        gl_->CopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, static_cast<GLintptr>(offset),
                               static_cast<GLsizeiptr>(bytes));
        gl_->DeleteBuffers(1, &staging);  // the GL keeps it alive until the copy has run
    }
    // Waits for shader writes first (storage writes are incoherent without the barrier).
    void download(size_t offset, size_t bytes, void* data) const {
        gl_->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        gl_->BindBuffer(GL_COPY_READ_BUFFER, id_);
        gl_->GetBufferSubData(GL_COPY_READ_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
    }

private:
    void reset() {
        if (gl_ && id_) {
            gl_->DeleteBuffers(1, &id_);
            if (MemoryTally* tally = memory_tally(*gl_)) tally->remove(sizing_, bytes_);
        }
        id_ = 0;
        bytes_ = 0;
    }
    const Api* gl_ = nullptr;
    GLuint id_ = 0;
    size_t bytes_ = 0;
    Sizing sizing_ = Sizing::other;
};

}  // namespace pf::gl
