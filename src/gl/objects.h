// Owning handles of the GL objects the renderer makes (textures, framebuffers, samplers,
// vertex arrays): deleted with their owner, never an engine's object.
#pragma once
#include <utility>

#include "gl/gl.h"

namespace pf::gl {

enum class ObjectKind { texture, framebuffer, sampler, vertex_array };

class Object {
public:
    Object() = default;
    Object(const Api& gl, ObjectKind kind) : gl_(&gl), kind_(kind) {
        switch (kind) {
            case ObjectKind::texture: gl.GenTextures(1, &id_); break;
            case ObjectKind::framebuffer: gl.GenFramebuffers(1, &id_); break;
            case ObjectKind::sampler: gl.GenSamplers(1, &id_); break;
            case ObjectKind::vertex_array: gl.GenVertexArrays(1, &id_); break;
        }
    }
    ~Object() { reset(); }
    Object(Object&& o) noexcept { *this = std::move(o); }
    Object& operator=(Object&& o) noexcept {
        if (this != &o) {
            reset();
            std::swap(gl_, o.gl_);
            std::swap(kind_, o.kind_);
            std::swap(id_, o.id_);
        }
        return *this;
    }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;

    GLuint id() const { return id_; }

    void reset() {
        if (gl_ && id_) {
            switch (kind_) {
                case ObjectKind::texture: gl_->DeleteTextures(1, &id_); break;
                case ObjectKind::framebuffer: gl_->DeleteFramebuffers(1, &id_); break;
                case ObjectKind::sampler: gl_->DeleteSamplers(1, &id_); break;
                case ObjectKind::vertex_array: gl_->DeleteVertexArrays(1, &id_); break;
            }
        }
        id_ = 0;
    }

private:
    const Api* gl_ = nullptr;
    ObjectKind kind_ = ObjectKind::texture;
    GLuint id_ = 0;
};

}  // namespace pf::gl
