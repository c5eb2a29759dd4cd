#include "gl/program.h"

#include "gl/debug.h"
#include "gl/program_binary_cache.h"

namespace pf::gl {

namespace {
std::string shader_log(const Api& gl, GLuint shader) {
    GLint len = 0;
    gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> buf(static_cast<size_t>(len > 1 ? len : 1), '\0');
    if (len > 1) gl.GetShaderInfoLog(shader, len, nullptr, buf.data());
    return buf.data();
}

std::string program_log(const Api& gl, GLuint program) {
    GLint len = 0;
    gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> buf(static_cast<size_t>(len > 1 ? len : 1), '\0');
    if (len > 1) gl.GetProgramInfoLog(program, len, nullptr, buf.data());
    return buf.data();
}

const char* stage_name(GLenum type) {
    switch (type) {
        case GL_COMPUTE_SHADER: return "compute";
        case GL_VERTEX_SHADER: return "vertex";
        case GL_FRAGMENT_SHADER: return "fragment";
        default: return "shader";
    }
}
}  // namespace

std::vector<ShaderStage> program_stages(const ProgramInfo& info) {
    std::vector<ShaderStage> stages;
    if (!info.fragment) {
        stages.push_back({GL_COMPUTE_SHADER, expand_shader(info.file, info.defines)});
    } else {
        stages.push_back({GL_VERTEX_SHADER, expand_shader(info.file, info.defines)});
        stages.push_back({GL_FRAGMENT_SHADER, expand_shader(info.fragment, info.defines)});
    }
    return stages;
}

GLuint build_program(const Api& gl, const std::vector<ShaderStage>& stages, const std::string& name,
                     std::string& error, bool retrievable) {
    for (const ShaderStage& s : stages) {
        if (!s.source.error.empty()) {
            error = name + ": " + s.source.error;
            return 0;
        }
    }
    std::vector<GLuint> shaders;
    auto release = [&] {
        for (GLuint sh : shaders) gl.DeleteShader(sh);
    };
    for (const ShaderStage& s : stages) {
        GLuint shader = gl.CreateShader(s.type);
        shaders.push_back(shader);
        const char* text = s.source.text.c_str();
        gl.ShaderSource(shader, 1, &text, nullptr);
        gl.CompileShader(shader);
        GLint ok = GL_FALSE;
        gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            error = name + ": " + stage_name(s.type) + " compile failed:\n" +
                    annotate_log(shader_log(gl, shader), s.source.files);
            release();
            return 0;
        }
    }
    GLuint program = gl.CreateProgram();
    for (GLuint sh : shaders) gl.AttachShader(program, sh);
    if (retrievable) gl.ProgramParameteri(program, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
    gl.LinkProgram(program);
    for (GLuint sh : shaders) gl.DetachShader(program, sh);
    release();
    GLint ok = GL_FALSE;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        // Link logs may point into either stage; the first stage's file table is the usual culprit.
        error = name + ": link failed:\n" + annotate_log(program_log(gl, program), stages.front().source.files);
        gl.DeleteProgram(program);
        return 0;
    }
    return program;
}

ProgramCache::~ProgramCache() {
    for (GLuint p : programs_) {
        if (p) gl_.DeleteProgram(p);
    }
}

GLuint ProgramCache::get(ProgramId id, std::string& error) {
    GLuint& slot = programs_[static_cast<size_t>(id)];
    if (slot) return slot;
    const ProgramInfo& info = program_info(id);
    if (binaries_ && binaries_->active()) {
        slot = binaries_->get_or_build(program_stages(info), info.id, error);
    } else {
        slot = build_program(gl_, program_stages(info), info.id, error);
    }
    label_object(gl_, GL_PROGRAM, slot, info.id);
    return slot;
}

}  // namespace pf::gl
