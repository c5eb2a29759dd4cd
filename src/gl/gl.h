// The library's GL entry points: a glad2 multi-context loader, one GladGLContext per
// simulation, so pflip has no global GL function pointers and exports no GL symbols.
#pragma once
#include <glad/gl.h>

namespace pf::gl {
using Api = GladGLContext;
}
