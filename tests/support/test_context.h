// A headless GL 4.3 core context for the tests (EGL: NVIDIA device platform when present,
// Mesa surfaceless otherwise), created once per test binary. Engine-side tests load GL
// with the app GLAD (pf_glad_app) after ensure_context(); this header stays GL-free so
// internal tests can include the library's own multi-context loader instead.
#pragma once

#include "pf/pf.h"

namespace pf::test {

// Makes the shared test context current (creating it on first use); false if impossible.
bool ensure_context();
// Leaves the thread with no current context (ensure_context makes it current again).
void release_context();
// eglGetProcAddress, as an engine would hand it to pf_create.
pf_gl_proc get_proc(const char* name);
// pf_default_sim_desc() with the test loader and a logger that records the last message.
pf_sim_desc test_desc(uint32_t nx, uint32_t ny, uint32_t nz, float cell_size = 0.1f);
// Last message any test_desc() logger received (cleared by take).
const char* last_log();
void clear_log();

}  // namespace pf::test
