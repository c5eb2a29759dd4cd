#include "support/test_context.h"

#include <glad/gl.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#include <link.h>
#endif

#include "egl_context.h"

namespace pf::test {

namespace {
std::string g_last_log;

void record_log(void*, pf_log_level, pf_result, const char* message) { g_last_log = message; }

#if defined(__SANITIZE_ADDRESS__)
// Under AddressSanitizer: pins the GL driver (Mesa's *_dri.so, loaded by EGL) in memory until the
// process ends. EGL unloads it when the context is torn down at exit, before LeakSanitizer
// looks; the driver's lifetime allocations (made once, freed never, by design) then have an
// unloaded module in their stack and no live pointer to them, so they read as leaks that no
// suppression can name. Pinned, they stay reachable from the driver's globals.
void pin_gl_driver() {
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void*) {
            const char* name = info->dlpi_name;
            if (name && std::strstr(name, "_dri.so")) dlopen(name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
            return 0;
        },
        nullptr);
}
#else
void pin_gl_driver() {}
#endif

// The test binary's one context (the samples' headless EGL context: NVIDIA device
// platform when present, Mesa surfaceless otherwise), torn down at exit.
std::unique_ptr<pfs::EglContext> make_context() {
    try {
        auto ctx = std::make_unique<pfs::EglContext>();
        if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(pfs::get_proc))) return nullptr;
        pin_gl_driver();
        std::fprintf(stderr, "[test context] %s | %s | %s\n", ctx->platform().c_str(), ctx->gl_renderer().c_str(),
                     ctx->gl_version().c_str());
        return ctx;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "[test context] no GL 4.3 context: %s\n", e.what());
        return nullptr;
    }
}
}  // namespace

pfs::EglContext* the_context() {
    static const std::unique_ptr<pfs::EglContext> ctx = make_context();
    return ctx.get();
}

bool ensure_context() {
    pfs::EglContext* ctx = the_context();
    if (ctx) ctx->make_current();
    return ctx != nullptr;
}

void release_context() {
    if (pfs::EglContext* ctx = the_context()) ctx->release_current();
}

pf_gl_proc get_proc(const char* name) { return pfs::get_proc(name); }

pf_sim_desc test_desc(uint32_t nx, uint32_t ny, uint32_t nz, float cell_size) {
    pf_sim_desc d = pf_default_sim_desc();
    d.grid_size[0] = nx;
    d.grid_size[1] = ny;
    d.grid_size[2] = nz;
    d.cell_size = cell_size;
    d.max_particles = nx * ny * nz * 8;
    d.gl_get_proc_address = get_proc;
    d.logger.fn = record_log;
    return d;
}

const char* last_log() { return g_last_log.c_str(); }
void clear_log() { g_last_log.clear(); }

}  // namespace pf::test
