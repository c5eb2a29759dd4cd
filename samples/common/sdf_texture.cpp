#include "sdf_texture.h"

#include "util.h"

#include <glad/gl.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace pfs {

namespace {
std::string gl_error_text(GLenum e) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%04X", unsigned(e));
    return text;
}
} // namespace

SdfTextures::~SdfTextures() { release(); }

SdfTextures& SdfTextures::operator=(SdfTextures&& other) noexcept {
    if (this != &other) {
        release();
        names_ = std::exchange(other.names_, {});
    }
    return *this;
}

void SdfTextures::release() {
    // Names exist only if add() ran, so the loader is there.
    if (!names_.empty()) glDeleteTextures(GLsizei(names_.size()), names_.data());
    names_.clear();
}

uint32_t SdfTextures::add(const SdfGrid& grid, const std::string& label) {
    if (!glad_glTexStorage3D || !glad_glTexSubImage3D)
        throw Error(label + ": the SDF texture needs the app's GL loader (gladLoadGL) with OpenGL 4.3");
    if (GLenum pending = glGetError(); pending != GL_NO_ERROR)
        throw Error(label + ": a GL error (" + gl_error_text(pending) + ") was pending before the SDF upload");
    GLint previous_texture = 0, previous_unpack = 0, previous_alignment = 4;
    glGetIntegerv(GL_TEXTURE_BINDING_3D, &previous_texture);
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &previous_unpack);
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &previous_alignment);

    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_3D, name);
    // Texels from client memory, rows packed (a row of floats is 4-aligned anyway).
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // The file's precision is kept: a float16 grid becomes GL_R16F (half the memory); its values
    // came from halves, so the conversion back is exact.
    const GLenum internal = grid.precision == SdfGrid::Precision::float16 ? GL_R16F : GL_R32F;
    glTexStorage3D(GL_TEXTURE_3D, 1, internal, GLsizei(grid.size[0]), GLsizei(grid.size[1]), GLsizei(grid.size[2]));
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, GLsizei(grid.size[0]), GLsizei(grid.size[1]), GLsizei(grid.size[2]),
                    GL_RED, GL_FLOAT, grid.values.data());
    // The library samples through its own sampler (linear, clamped); these serve other readers.
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR && glObjectLabel) {
        // For GL debuggers; a label longer than the context allows would be an error, so its
        // end (the obstacle's pointer) is kept.
        GLint most = 0;
        glGetIntegerv(GL_MAX_LABEL_LENGTH, &most);
        const size_t keep = std::min(label.size(), size_t(std::max(most - 1, 0)));
        glObjectLabel(GL_TEXTURE, name, GLsizei(keep), label.c_str() + (label.size() - keep));
    }

    glPixelStorei(GL_UNPACK_ALIGNMENT, previous_alignment);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(previous_unpack));
    glBindTexture(GL_TEXTURE_3D, GLuint(previous_texture));
    if (error != GL_NO_ERROR) {
        glDeleteTextures(1, &name);
        throw Error(label + ": uploading the SDF texture failed with GL error " + gl_error_text(error) +
                    (error == GL_OUT_OF_MEMORY ? " (out of memory)" : ""));
    }
    names_.push_back(name);
    return name;
}

} // namespace pfs
