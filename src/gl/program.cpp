#include "gl/program.h"

#include <vector>

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
}  // namespace

GLuint build_compute_program(const Api& gl, const ExpandedSource& src, const std::string& name,
                             std::string& error) {
    if (!src.error.empty()) {
        error = name + ": " + src.error;
        return 0;
    }
    GLuint shader = gl.CreateShader(GL_COMPUTE_SHADER);
    const char* text = src.text.c_str();
    gl.ShaderSource(shader, 1, &text, nullptr);
    gl.CompileShader(shader);
    GLint ok = GL_FALSE;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        error = name + ": compile failed:\n" + annotate_log(shader_log(gl, shader), src.files);
        gl.DeleteShader(shader);
        return 0;
    }
    GLuint program = gl.CreateProgram();
    gl.AttachShader(program, shader);
    gl.LinkProgram(program);
    gl.DetachShader(program, shader);
    gl.DeleteShader(shader);
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        error = name + ": link failed:\n" + annotate_log(program_log(gl, program), src.files);
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
    slot = build_compute_program(gl_, expand_shader(info.file, info.defines), info.id, error);
    return slot;
}

}  // namespace pf::gl
