// The library's GL entry points: a glad2 multi-context loader, one GladGLContext per
// simulation, so pflip has no global GL function pointers and exports no GL symbols.
#pragma once
#include <glad/gl.h>

#include <cstdio>
#include <string>

namespace pf::gl {
using Api = GladGLContext;

// "0x0505": how GL enums and error codes appear in log messages.
inline std::string hex(GLenum value) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%04X", unsigned(value));
    return buf;
}
}  // namespace pf::gl
