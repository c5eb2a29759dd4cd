#include "gl/implementation.h"

namespace pf::gl {

std::string implementation_string(const Api& gl, GLenum name) {
    const GLubyte* s = gl.GetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

bool runs_on_the_cpu(const Api& gl) {
    const std::string renderer = implementation_string(gl, GL_RENDERER);
    for (const char* cpu : {"llvmpipe", "softpipe", "SwiftShader"}) {
        if (renderer.find(cpu) != std::string::npos) return true;
    }
    return false;
}

}  // namespace pf::gl
