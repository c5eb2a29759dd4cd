#include "gl_util.h"

#include "util.h"

#include <algorithm>
#include <initializer_list>
#include <cstdio>
#include <cstring>

namespace pfs {

namespace {
const char* gl_error_name(GLenum e) {
    switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "GL error";
    }
}

GLuint compile(GLenum type, const char* src, const char* name) {
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(std::max(len, 1)), '\0');
        glGetShaderInfoLog(s, len, nullptr, log.data());
        glDeleteShader(s);
        throw Error(std::string("compiling ") + name + (type == GL_VERTEX_SHADER ? " (vertex)" : " (fragment)") +
                    " failed:\n" + log);
    }
    return s;
}
} // namespace

void check_gl(const char* where) {
    GLenum e = glGetError();
    if (e == GL_NO_ERROR) return;
    std::string msg = std::string("GL error in ") + where + ":";
    for (int n = 0; e != GL_NO_ERROR && n < 8; ++n, e = glGetError()) msg += std::string(" ") + gl_error_name(e);
    throw Error(msg);
}

namespace {
// Links the compiled shaders (deleting them) into a program; throws pfs::Error with the info log.
GLuint link(std::initializer_list<GLuint> shaders, const char* name) {
    GLuint p = glCreateProgram();
    for (GLuint s : shaders) glAttachShader(p, s);
    glLinkProgram(p);
    for (GLuint s : shaders) glDeleteShader(s);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(p, GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(std::max(len, 1)), '\0');
        glGetProgramInfoLog(p, len, nullptr, log.data());
        glDeleteProgram(p);
        throw Error(std::string("linking ") + name + " failed:\n" + log);
    }
    return p;
}
}  // namespace

GLuint link_program(const char* vs, const char* fs, const char* name) {
    const GLuint v = compile(GL_VERTEX_SHADER, vs, name);
    GLuint f = 0;
    try {
        f = compile(GL_FRAGMENT_SHADER, fs, name);
    } catch (...) {
        glDeleteShader(v);
        throw;
    }
    return link({v, f}, name);
}

GLuint link_compute_program(const char* cs, const char* name) { return link({compile(GL_COMPUTE_SHADER, cs, name)}, name); }

void check_framebuffer(const char* what) {
    const GLenum st = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (st != GL_FRAMEBUFFER_COMPLETE) {
        char buf[128];
        std::snprintf(buf, sizeof buf, "%s incomplete (status 0x%04X)", what, unsigned(st));
        throw Error(buf);
    }
}

int gl_version_number() {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    return major * 100 + minor * 10;
}

ClipControlFn load_clip_control(GLADloadfunc get_proc) {
    if (gl_version_number() < 450) {
        // ARB_clip_control on an older context.
        GLint n = 0;
        glGetIntegerv(GL_NUM_EXTENSIONS, &n);
        bool found = false;
        for (GLint i = 0; i < n && !found; ++i) {
            const char* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
            found = e && std::strcmp(e, "GL_ARB_clip_control") == 0;
        }
        if (!found) return nullptr;
    }
    return reinterpret_cast<ClipControlFn>(get_proc("glClipControl"));
}

void read_rgba(int width, int height, std::vector<uint8_t>& out) {
    out.resize(size_t(width) * size_t(height) * 4);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
}

} // namespace pfs
