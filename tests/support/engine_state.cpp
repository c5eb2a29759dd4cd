#include "support/engine_state.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <initializer_list>

namespace pf::test {

namespace {
// ---------------------------------------------------------------------------------------------
// Snapshot of the engine-visible GL state, field by field.

constexpr int kSsboBindings = 16;
constexpr int kUboBindings = 4;
constexpr int kTextureUnits = Engine::kTextureUnits;
constexpr int kImageUnits = 4;

struct NamedEnum {
    GLenum target, binding;
    const char* name;
};
const NamedEnum kGenericBuffers[] = {
    {GL_ARRAY_BUFFER, GL_ARRAY_BUFFER_BINDING, "GL_ARRAY_BUFFER"},
    {GL_ELEMENT_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER_BINDING, "GL_ELEMENT_ARRAY_BUFFER (VAO)"},
    {GL_SHADER_STORAGE_BUFFER, GL_SHADER_STORAGE_BUFFER_BINDING, "GL_SHADER_STORAGE_BUFFER"},
    {GL_UNIFORM_BUFFER, GL_UNIFORM_BUFFER_BINDING, "GL_UNIFORM_BUFFER"},
    {GL_COPY_READ_BUFFER, GL_COPY_READ_BUFFER_BINDING, "GL_COPY_READ_BUFFER"},
    {GL_COPY_WRITE_BUFFER, GL_COPY_WRITE_BUFFER_BINDING, "GL_COPY_WRITE_BUFFER"},
    {GL_DISPATCH_INDIRECT_BUFFER, GL_DISPATCH_INDIRECT_BUFFER_BINDING, "GL_DISPATCH_INDIRECT_BUFFER"},
    {GL_DRAW_INDIRECT_BUFFER, GL_DRAW_INDIRECT_BUFFER_BINDING, "GL_DRAW_INDIRECT_BUFFER"},
    {GL_PIXEL_PACK_BUFFER, GL_PIXEL_PACK_BUFFER_BINDING, "GL_PIXEL_PACK_BUFFER"},
    {GL_PIXEL_UNPACK_BUFFER, GL_PIXEL_UNPACK_BUFFER_BINDING, "GL_PIXEL_UNPACK_BUFFER"},
    {GL_ATOMIC_COUNTER_BUFFER, GL_ATOMIC_COUNTER_BUFFER_BINDING, "GL_ATOMIC_COUNTER_BUFFER"},
    {GL_TRANSFORM_FEEDBACK_BUFFER, GL_TRANSFORM_FEEDBACK_BUFFER_BINDING, "GL_TRANSFORM_FEEDBACK_BUFFER"},
};
const NamedEnum kCapabilities[] = {
    {GL_BLEND, 0, "GL_BLEND"},
    {GL_DEPTH_TEST, 0, "GL_DEPTH_TEST"},
    {GL_CULL_FACE, 0, "GL_CULL_FACE"},
    {GL_SCISSOR_TEST, 0, "GL_SCISSOR_TEST"},
    {GL_STENCIL_TEST, 0, "GL_STENCIL_TEST"},
    {GL_RASTERIZER_DISCARD, 0, "GL_RASTERIZER_DISCARD"},
    {GL_PROGRAM_POINT_SIZE, 0, "GL_PROGRAM_POINT_SIZE"},
    {GL_MULTISAMPLE, 0, "GL_MULTISAMPLE"},
    {GL_FRAMEBUFFER_SRGB, 0, "GL_FRAMEBUFFER_SRGB"},
    {GL_DEPTH_CLAMP, 0, "GL_DEPTH_CLAMP"},
    {GL_POLYGON_OFFSET_FILL, 0, "GL_POLYGON_OFFSET_FILL"},
    {GL_POLYGON_OFFSET_LINE, 0, "GL_POLYGON_OFFSET_LINE"},
    {GL_POLYGON_OFFSET_POINT, 0, "GL_POLYGON_OFFSET_POINT"},
    {GL_SAMPLE_ALPHA_TO_COVERAGE, 0, "GL_SAMPLE_ALPHA_TO_COVERAGE"},
    {GL_SAMPLE_ALPHA_TO_ONE, 0, "GL_SAMPLE_ALPHA_TO_ONE"},
    {GL_SAMPLE_COVERAGE, 0, "GL_SAMPLE_COVERAGE"},
    {GL_SAMPLE_MASK, 0, "GL_SAMPLE_MASK"},
    {GL_SAMPLE_SHADING, 0, "GL_SAMPLE_SHADING"},
    {GL_COLOR_LOGIC_OP, 0, "GL_COLOR_LOGIC_OP"},
    {GL_DITHER, 0, "GL_DITHER"},
    {GL_TEXTURE_CUBE_MAP_SEAMLESS, 0, "GL_TEXTURE_CUBE_MAP_SEAMLESS"},
    {GL_PRIMITIVE_RESTART, 0, "GL_PRIMITIVE_RESTART"},
    {GL_LINE_SMOOTH, 0, "GL_LINE_SMOOTH"},
    {GL_POLYGON_SMOOTH, 0, "GL_POLYGON_SMOOTH"},
};

// Raw bits of a float or double, so diff() compares them exactly.
int64_t bits(double v) {
    int64_t b = 0;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

GLuint compile(GLenum stage, const char* src) {
    GLuint sh = glCreateShader(stage);
    glShaderSource(sh, 1, &src, nullptr);
    glCompileShader(sh);
    GLint ok = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    EXPECT_TRUE(ok) << "engine shader failed to compile";
    return sh;
}

GLuint link(std::initializer_list<GLuint> shaders) {
    GLuint p = glCreateProgram();
    for (GLuint s : shaders) glAttachShader(p, s);
    glLinkProgram(p);
    for (GLuint s : shaders) {
        glDetachShader(p, s);
        glDeleteShader(s);
    }
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    EXPECT_TRUE(ok) << "engine program failed to link";
    return p;
}

}  // namespace

const char* gl_error_name(GLenum e) {
    switch (e) {
        case GL_NO_ERROR: return "GL_NO_ERROR";
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        default: return "GL error";
    }
}

void drain_gl_errors() {
    while (glGetError() != GL_NO_ERROR) {
    }
}

GLint geti(GLenum pname) {
    GLint v = 0;
    glGetIntegerv(pname, &v);
    return v;
}

bool gl_at_least(int major, int minor) {
    const GLint M = geti(GL_MAJOR_VERSION), m = geti(GL_MINOR_VERSION);
    return M > major || (M == major && m >= minor);
}

Snapshot snapshot() {
    Snapshot s;
    s.add("GL_CURRENT_PROGRAM", geti(GL_CURRENT_PROGRAM));
    s.add("GL_PROGRAM_PIPELINE_BINDING", geti(GL_PROGRAM_PIPELINE_BINDING));
    for (int i = 0; i < kSsboBindings; ++i) {
        GLint buf = 0;
        GLint64 start = 0, size = 0;
        glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, GLuint(i), &buf);
        glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, GLuint(i), &start);
        glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, GLuint(i), &size);
        const std::string n = "[" + std::to_string(i) + "]";
        s.add("GL_SHADER_STORAGE_BUFFER_BINDING" + n, buf);
        s.add("GL_SHADER_STORAGE_BUFFER_START" + n, start);
        s.add("GL_SHADER_STORAGE_BUFFER_SIZE" + n, size);
    }
    for (int i = 0; i < kUboBindings; ++i) {
        GLint buf = 0;
        GLint64 start = 0, size = 0;
        glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, GLuint(i), &buf);
        glGetInteger64i_v(GL_UNIFORM_BUFFER_START, GLuint(i), &start);
        glGetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, GLuint(i), &size);
        const std::string n = "[" + std::to_string(i) + "]";
        s.add("GL_UNIFORM_BUFFER_BINDING" + n, buf);
        s.add("GL_UNIFORM_BUFFER_START" + n, start);
        s.add("GL_UNIFORM_BUFFER_SIZE" + n, size);
    }
    for (int i = 0; i < 2; ++i) {
        GLint buf = 0;
        glGetIntegeri_v(GL_ATOMIC_COUNTER_BUFFER_BINDING, GLuint(i), &buf);
        s.add("GL_ATOMIC_COUNTER_BUFFER_BINDING[" + std::to_string(i) + "]", buf);
    }
    for (const NamedEnum& g : kGenericBuffers) s.add(g.name, geti(g.binding));
    if (gl_at_least(4, 4)) s.add("GL_QUERY_BUFFER", geti(GL_QUERY_BUFFER_BINDING));
    s.add("GL_VERTEX_ARRAY_BINDING", geti(GL_VERTEX_ARRAY_BINDING));
    s.add("GL_DRAW_FRAMEBUFFER_BINDING", geti(GL_DRAW_FRAMEBUFFER_BINDING));
    s.add("GL_READ_FRAMEBUFFER_BINDING", geti(GL_READ_FRAMEBUFFER_BINDING));
    s.add("GL_RENDERBUFFER_BINDING", geti(GL_RENDERBUFFER_BINDING));
    GLint vp[4] = {}, sc[4] = {};
    glGetIntegerv(GL_VIEWPORT, vp);
    glGetIntegerv(GL_SCISSOR_BOX, sc);
    for (int i = 0; i < 4; ++i) {
        s.add("GL_VIEWPORT[" + std::to_string(i) + "]", vp[i]);
        s.add("GL_SCISSOR_BOX[" + std::to_string(i) + "]", sc[i]);
    }
    const GLint active = geti(GL_ACTIVE_TEXTURE);
    s.add("GL_ACTIVE_TEXTURE", active);
    for (int u = 0; u < kTextureUnits; ++u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        const std::string n = "[unit " + std::to_string(u) + "]";
        s.add("GL_TEXTURE_BINDING_2D" + n, geti(GL_TEXTURE_BINDING_2D));
        s.add("GL_TEXTURE_BINDING_3D" + n, geti(GL_TEXTURE_BINDING_3D));
        s.add("GL_TEXTURE_BINDING_CUBE_MAP" + n, geti(GL_TEXTURE_BINDING_CUBE_MAP));
        s.add("GL_SAMPLER_BINDING" + n, geti(GL_SAMPLER_BINDING));
    }
    glActiveTexture(GLenum(active));
    const GLenum image_fields[] = {GL_IMAGE_BINDING_NAME, GL_IMAGE_BINDING_LEVEL, GL_IMAGE_BINDING_LAYERED,
                                   GL_IMAGE_BINDING_LAYER, GL_IMAGE_BINDING_ACCESS, GL_IMAGE_BINDING_FORMAT};
    const char* image_names[] = {"NAME", "LEVEL", "LAYERED", "LAYER", "ACCESS", "FORMAT"};
    for (int i = 0; i < kImageUnits; ++i) {
        for (int f = 0; f < 6; ++f) {
            GLint v = 0;
            glGetIntegeri_v(image_fields[f], GLuint(i), &v);
            s.add(std::string("GL_IMAGE_BINDING_") + image_names[f] + "[" + std::to_string(i) + "]", v);
        }
    }
    for (const NamedEnum& c : kCapabilities) s.add(c.name, glIsEnabled(c.target));
    for (GLint i = 0; i < geti(GL_MAX_VIEWPORTS); ++i)
        s.add("GL_SCISSOR_TEST[" + std::to_string(i) + "]", glIsEnabledi(GL_SCISSOR_TEST, GLuint(i)));
    const GLenum blend_fields[] = {GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA,
                                   GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA};
    const char* blend_names[] = {"SRC_RGB", "DST_RGB", "SRC_ALPHA", "DST_ALPHA", "EQUATION_RGB", "EQUATION_ALPHA"};
    for (GLint b = 0; b < geti(GL_MAX_DRAW_BUFFERS); ++b) {
        const std::string n = "[" + std::to_string(b) + "]";
        s.add("GL_BLEND" + n, glIsEnabledi(GL_BLEND, GLuint(b)));
        for (int f = 0; f < 6; ++f) {
            GLint v = 0;
            glGetIntegeri_v(blend_fields[f], GLuint(b), &v);
            s.add(std::string("GL_BLEND_") + blend_names[f] + n, v);
        }
        GLboolean mask[4] = {};
        glGetBooleani_v(GL_COLOR_WRITEMASK, GLuint(b), mask);
        s.add("GL_COLOR_WRITEMASK" + n, mask[0] | mask[1] << 1 | mask[2] << 2 | mask[3] << 3);
    }
    GLfloat blend_color[4] = {};
    glGetFloatv(GL_BLEND_COLOR, blend_color);
    for (int i = 0; i < 4; ++i) s.add("GL_BLEND_COLOR[" + std::to_string(i) + "]", bits(blend_color[i]));
    s.add("GL_DEPTH_FUNC", geti(GL_DEPTH_FUNC));
    GLboolean depth_mask = GL_FALSE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
    s.add("GL_DEPTH_WRITEMASK", depth_mask);
    GLdouble depth_range[2] = {};
    glGetDoublev(GL_DEPTH_RANGE, depth_range);
    s.add("GL_DEPTH_RANGE[0]", bits(depth_range[0]));
    s.add("GL_DEPTH_RANGE[1]", bits(depth_range[1]));
    GLint polygon_mode[2] = {};
    glGetIntegerv(GL_POLYGON_MODE, polygon_mode);
    s.add("GL_POLYGON_MODE", polygon_mode[0]);
    GLfloat offset_factor = 0, offset_units = 0;
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &offset_factor);
    glGetFloatv(GL_POLYGON_OFFSET_UNITS, &offset_units);
    s.add("GL_POLYGON_OFFSET_FACTOR", bits(offset_factor));
    s.add("GL_POLYGON_OFFSET_UNITS", bits(offset_units));
    const GLenum ints[] = {GL_CULL_FACE_MODE, GL_FRONT_FACE, GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK,
                           GL_STENCIL_WRITEMASK, GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS,
                           GL_STENCIL_BACK_FUNC, GL_STENCIL_BACK_WRITEMASK, GL_STENCIL_CLEAR_VALUE, GL_LOGIC_OP_MODE,
                           GL_PROVOKING_VERTEX, GL_DRAW_BUFFER0, GL_READ_BUFFER};
    const char* int_names[] = {"GL_CULL_FACE_MODE", "GL_FRONT_FACE", "GL_STENCIL_FUNC", "GL_STENCIL_REF",
                               "GL_STENCIL_VALUE_MASK", "GL_STENCIL_WRITEMASK", "GL_STENCIL_FAIL",
                               "GL_STENCIL_PASS_DEPTH_FAIL", "GL_STENCIL_PASS_DEPTH_PASS", "GL_STENCIL_BACK_FUNC",
                               "GL_STENCIL_BACK_WRITEMASK", "GL_STENCIL_CLEAR_VALUE", "GL_LOGIC_OP_MODE",
                               "GL_PROVOKING_VERTEX", "GL_DRAW_BUFFER0 (bound FBO)", "GL_READ_BUFFER (bound FBO)"};
    for (size_t i = 0; i < sizeof ints / sizeof ints[0]; ++i) s.add(int_names[i], geti(ints[i]));
    GLfloat clear[4] = {};
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    for (int i = 0; i < 4; ++i) s.add("GL_COLOR_CLEAR_VALUE[" + std::to_string(i) + "]", bits(clear[i]));
    GLdouble clear_depth = 0;
    glGetDoublev(GL_DEPTH_CLEAR_VALUE, &clear_depth);
    s.add("GL_DEPTH_CLEAR_VALUE", bits(clear_depth));
    GLfloat line_width = 0, point_size = 0;
    glGetFloatv(GL_LINE_WIDTH, &line_width);
    glGetFloatv(GL_POINT_SIZE, &point_size);
    s.add("GL_LINE_WIDTH", bits(line_width));
    s.add("GL_POINT_SIZE", bits(point_size));
    s.add("GL_POINT_SPRITE_COORD_ORIGIN", geti(GL_POINT_SPRITE_COORD_ORIGIN));
    // The bound VAO's first vertex buffer bindings and attribute switches (pflip uses its own VAO).
    for (GLuint i = 0; i < 2; ++i) {
        GLint buf = 0, enabled = 0;
        glGetIntegeri_v(GL_VERTEX_BINDING_BUFFER, i, &buf);
        if (geti(GL_VERTEX_ARRAY_BINDING) != 0) glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &enabled);
        s.add("GL_VERTEX_BINDING_BUFFER[" + std::to_string(i) + "]", buf);
        s.add("GL_VERTEX_ATTRIB_ARRAY_ENABLED[" + std::to_string(i) + "]", enabled);
    }
    s.add("GL_PACK_ALIGNMENT", geti(GL_PACK_ALIGNMENT));
    s.add("GL_UNPACK_ALIGNMENT", geti(GL_UNPACK_ALIGNMENT));
    return s;
}

// Every field that differs, one per line; empty when the states match.
std::string diff(const Snapshot& before, const Snapshot& after) {
    std::string out;
    if (before.fields.size() != after.fields.size()) return "snapshot layouts differ";
    for (size_t i = 0; i < before.fields.size(); ++i) {
        if (before.fields[i].second != after.fields[i].second) {
            char line[192];
            std::snprintf(line, sizeof line, "  %s: was %" PRId64 ", now %" PRId64 "\n", before.fields[i].first.c_str(),
                          before.fields[i].second, after.fields[i].second);
            out += line;
        }
    }
    return out;
}


Engine::Engine(EngineProgram kind) {
    if (kind == EngineProgram::compute) {
        program_ = link({compile(GL_COMPUTE_SHADER,
                                 "#version 430 core\nlayout(local_size_x = 1) in;\n"
                                 "layout(std430, binding = 0) buffer B { uint x[]; };\n"
                                 "void main() { x[0] = 7u; }\n")});
    } else {
        program_ = link({compile(GL_VERTEX_SHADER, "#version 430 core\nvoid main() { gl_Position = vec4(0.0); }\n"),
                         compile(GL_FRAGMENT_SHADER,
                                 "#version 430 core\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n")});
    }
    ssbo_align_ = std::max(geti(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT), 1);
    ubo_align_ = std::max(geti(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT), 1);
    bytes_ = size_t(4 * std::max(ssbo_align_, ubo_align_) + 1024);
    buffers_.resize(kBuffers);
    glGenBuffers(kBuffers, buffers_.data());
    contents_.resize(kBuffers);
    for (int b = 0; b < kBuffers; ++b) {
        contents_[b].resize(bytes_);
        for (size_t j = 0; j < bytes_; ++j) contents_[b][j] = uint8_t(b * 37 + j * 13 + 5);
        glBindBuffer(GL_COPY_WRITE_BUFFER, buffers_[b]);
        glBufferData(GL_COPY_WRITE_BUFFER, GLsizeiptr(bytes_), contents_[b].data(), GL_STATIC_DRAW);
    }
    glGenVertexArrays(1, &vao_);
    glGenTextures(kTextureUnits, textures_);
    for (int u = 0; u < kTextureUnits; ++u) {
        glBindTexture(GL_TEXTURE_2D, textures_[u]);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 4, 4);
    }
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, textures_[0], 0);
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    glGenSamplers(1, &sampler_);
    glGenTextures(1, &cube_);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube_);
    glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_RGBA8, 4, 4);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    const GLint max_ssbo = geti(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS);
    EXPECT_GE(max_ssbo, kSsboBindings) << "this GL has fewer indexed SSBO bindings than the test binds";
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "engine setup";
}


Engine::~Engine() {
    unbind_all();
    glDeleteBuffers(kBuffers, buffers_.data());
    glDeleteVertexArrays(1, &vao_);
    glDeleteFramebuffers(1, &fbo_);
    glDeleteTextures(kTextureUnits, textures_);
    glDeleteSamplers(1, &sampler_);
    glDeleteTextures(1, &cube_);
    glDeleteProgram(program_);
}


void Engine::bind(int variant) {
    auto buf = [&](int slot) { return buffers_[size_t((slot + variant * 7) % kBuffers)]; };
    glUseProgram(program_);
    for (int i = 0; i < kSsboBindings; ++i) {
        if ((i + variant) % 3 == 1) {
            const GLintptr off = GLintptr(ssbo_align_) * (1 + (i % 3));
            glBindBufferRange(GL_SHADER_STORAGE_BUFFER, GLuint(i), buf(i), off, 256);
        } else {
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(i), buf(i));
        }
    }
    for (int i = 0; i < kUboBindings; ++i) {
        if ((i + variant) % 2 == 1) {
            glBindBufferRange(GL_UNIFORM_BUFFER, GLuint(i), buf(16 + i), GLintptr(ubo_align_) * 2, 128);
        } else {
            glBindBufferBase(GL_UNIFORM_BUFFER, GLuint(i), buf(16 + i));
        }
    }
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, 0, buf(20));
    glBindBufferRange(GL_ATOMIC_COUNTER_BUFFER, 1, buf(21), 4 * 16, 16);
    glBindVertexArray(vao_);
    int slot = 22;
    for (const NamedEnum& g : kGenericBuffers) glBindBuffer(g.target, buf(slot++));  // after the indexed ones
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(3 + variant, 5, 17, 19);
    glScissor(1, 2 + variant, 3, 4);
    for (int u = 0; u < kTextureUnits; ++u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        glBindTexture(GL_TEXTURE_2D, textures_[(u + variant) % kTextureUnits]);
    }
    glBindSampler(3, sampler_);
    glActiveTexture(GLenum(GL_TEXTURE0 + 5));
    glBindImageTexture(2, textures_[1], 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
    glEnable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glEnable(GL_SCISSOR_TEST);
    // Raster state an engine may well leave behind, none of it what pflip's draws want.
    glActiveTexture(GLenum(GL_TEXTURE0 + 4));
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube_);
    glActiveTexture(GLenum(GL_TEXTURE0 + 5));
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_DST_ALPHA);
    glBlendEquationSeparate(GL_FUNC_REVERSE_SUBTRACT, GL_MAX);
    glBlendFunci(1, GL_DST_COLOR, GL_ZERO);
    glDisablei(GL_BLEND, 2);
    glColorMaski(0, GL_TRUE, GL_FALSE, GL_TRUE, variant % 2 ? GL_FALSE : GL_TRUE);
    glColorMaski(3, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glBlendColor(0.1f, 0.2f, 0.3f, 0.4f);
    glDepthFunc(variant % 2 ? GL_GREATER : GL_EQUAL);
    glDepthMask(GL_FALSE);
    glDepthRange(0.25, 0.75);
    glPolygonMode(GL_FRONT_AND_BACK, variant % 2 ? GL_LINE : GL_POINT);
    glPolygonOffset(2.0f, 3.0f);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NEVER, 3, 0x0f);
    glStencilOp(GL_KEEP, GL_INCR, GL_DECR);
    glCullFace(GL_FRONT_AND_BACK);
    glFrontFace(GL_CW);
    glEnable(GL_SAMPLE_MASK);
    glSampleMaski(0, 0x2);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_XOR);
    glEnable(GL_DEPTH_CLAMP);
    glEnable(GL_PROGRAM_POINT_SIZE);
    if (variant % 2) glEnable(GL_FRAMEBUFFER_SRGB);
    if (variant % 3 == 2) glEnable(GL_RASTERIZER_DISCARD);
    glDisable(GL_DITHER);
    glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glEnablei(GL_SCISSOR_TEST, 0);
    glClearColor(0.5f, 0.25f, 0.125f, 1.0f);
    glClearDepth(0.5);
    glLineWidth(1.0f);
    glPointSize(3.0f);
    glEnableVertexAttribArray(1);
    glBindVertexBuffer(0, buffer(5), 16, 32);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    if (query_buffer_) glBindBuffer(GL_QUERY_BUFFER, buf(39));
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "engine bind";
}


void Engine::unbind_all() {
    glUseProgram(0);
    for (int i = 0; i < kSsboBindings; ++i) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(i), 0);
    for (int i = 0; i < kUboBindings; ++i) glBindBufferBase(GL_UNIFORM_BUFFER, GLuint(i), 0);
    for (int i = 0; i < 2; ++i) glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, GLuint(i), 0);
    glBindVertexArray(0);
    for (const NamedEnum& g : kGenericBuffers) {
        if (g.target != GL_ELEMENT_ARRAY_BUFFER) glBindBuffer(g.target, 0);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    for (int u = 0; u < kTextureUnits; ++u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glActiveTexture(GL_TEXTURE0);
    glBindSampler(3, 0);
    glBindImageTexture(2, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA8);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glActiveTexture(GLenum(GL_TEXTURE0 + 4));
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    glActiveTexture(GL_TEXTURE0);
    glBlendFunc(GL_ONE, GL_ZERO);
    glBlendEquation(GL_FUNC_ADD);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBlendColor(0.0f, 0.0f, 0.0f, 0.0f);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDepthRange(0.0, 1.0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glPolygonOffset(0.0f, 0.0f);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xffffffffu);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glDisable(GL_SAMPLE_MASK);
    glSampleMaski(0, ~0u);
    glDisable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_COPY);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_PROGRAM_POINT_SIZE);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_RASTERIZER_DISCARD);
    glEnable(GL_DITHER);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepth(1.0);
    glPointSize(1.0f);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (gl_at_least(4, 4)) glBindBuffer(GL_QUERY_BUFFER, 0);
}


void Engine::expect_intact(const std::string& after) const {
    const GLint saved = geti(GL_COPY_READ_BUFFER_BINDING);
    std::vector<uint8_t> got(bytes_);
    for (int b = 0; b < kBuffers; ++b) {
        ASSERT_TRUE(glIsBuffer(buffers_[b])) << "engine buffer " << buffers_[b] << " deleted by " << after;
        glBindBuffer(GL_COPY_READ_BUFFER, buffers_[b]);
        glGetBufferSubData(GL_COPY_READ_BUFFER, 0, GLsizeiptr(bytes_), got.data());
        size_t first_diff = bytes_;
        for (size_t j = 0; j < bytes_ && first_diff == bytes_; ++j) {
            if (got[j] != contents_[b][j]) first_diff = j;
        }
        EXPECT_EQ(first_diff, bytes_) << "engine buffer " << buffers_[b] << " modified at byte " << first_diff
                                      << " by " << after;
    }
    glBindBuffer(GL_COPY_READ_BUFFER, GLuint(saved));
    EXPECT_TRUE(glIsProgram(program_)) << after;
    EXPECT_TRUE(glIsVertexArray(vao_)) << after;
    EXPECT_TRUE(glIsFramebuffer(fbo_)) << after;
    EXPECT_TRUE(glIsSampler(sampler_)) << after;
    for (GLuint t : textures_) EXPECT_TRUE(glIsTexture(t)) << after;
    EXPECT_TRUE(glIsTexture(cube_)) << after;
}


}  // namespace pf::test
