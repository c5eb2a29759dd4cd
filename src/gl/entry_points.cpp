#include "gl/entry_points.h"

namespace pf::gl {

const char* first_missing_entry_point(const Api& gl) {
#define PF_GL(name) \
    if (!gl.name) return "gl" #name;
#include "gl/entry_points.inc"
#undef PF_GL
    return nullptr;
}

}  // namespace pf::gl
