// What the current GL implementation says of itself.
#pragma once
#include <string>

#include "gl/gl.h"

namespace pf::gl {

// glGetString(name), or "" where the GL returns none.
std::string implementation_string(const Api& gl, GLenum name);

// True when GL_RENDERER names a rasteriser that runs on the CPU (Mesa's llvmpipe and softpipe,
// SwiftShader): it has a few cores and no launch cost, so a kernel shaped to fill a GPU's many
// multiprocessors only adds work there.
bool runs_on_the_cpu(const Api& gl);

}  // namespace pf::gl
