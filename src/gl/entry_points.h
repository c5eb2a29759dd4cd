// Checks that the engine's loader supplied every GL function pflip calls: glad leaves a
// missing one NULL, and calling it would crash instead of failing cleanly.
#pragma once
#include "gl/gl.h"

namespace pf::gl {

// Name of the first required entry point that is NULL ("glDispatchCompute"), or nullptr.
const char* first_missing_entry_point(const Api& gl);

}  // namespace pf::gl
