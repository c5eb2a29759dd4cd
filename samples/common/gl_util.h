// Small OpenGL helpers for the samples' own drawing (the application-side GLAD, pf_glad_app):
// shader compilation with readable errors, GL error checks, framebuffer checks, and the
// GL 4.5 glClipControl entry point (outside the 4.3 core profile that GLAD loads).
#pragma once

#include <glad/gl.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pfs {

/// Throws pfs::Error("GL error in <where>: GL_INVALID_...") if glGetError reports anything.
void check_gl(const char* where);

/// Compiles and links a vertex + fragment program; throws pfs::Error with the info log.
GLuint link_program(const char* vs, const char* fs, const char* name);
/// Compiles and links a compute program; throws pfs::Error with the info log.
GLuint link_compute_program(const char* cs, const char* name);

/// Throws pfs::Error naming the status unless the bound GL_FRAMEBUFFER is complete.
void check_framebuffer(const char* what);

/// "major.minor" of the current context as 100*major + 10*minor (e.g. 450).
int gl_version_number();

/// glClipControl (GL 4.5 or ARB_clip_control), looked up through get_proc; nullptr when the
/// context does not have it.
using ClipControlFn = void (*)(GLenum origin, GLenum depth);
ClipControlFn load_clip_control(GLADloadfunc get_proc);

constexpr GLenum kGL_LOWER_LEFT = 0x8CA1;
constexpr GLenum kGL_NEGATIVE_ONE_TO_ONE = 0x935E;
constexpr GLenum kGL_ZERO_TO_ONE = 0x935F;

/// Reads the colour of the bound read framebuffer's read buffer as RGBA8, bottom row first.
void read_rgba(int width, int height, std::vector<uint8_t>& out);

} // namespace pfs
