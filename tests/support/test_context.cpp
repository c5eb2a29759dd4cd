#include "support/test_context.h"

#include <glad/gl.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace pf::test {

namespace {
std::string g_last_log;

void record_log(void*, pf_log_level, pf_result, const char* message) { g_last_log = message; }

struct Context {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    bool ok = false;

    Context() {
        auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        auto platform_display =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!platform_display) return;
        const char* force = std::getenv("PF_EGL_PLATFORM");
        const bool want_device = !force || std::strcmp(force, "surfaceless") != 0;
        if (want_device && query_devices) {
            EGLDeviceEXT devices[8];
            EGLint count = 0;
            if (query_devices(8, devices, &count) && count > 0) {
                for (EGLint i = 0; i < count && display == EGL_NO_DISPLAY; ++i) {
                    EGLDisplay d = platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr) && try_context(d)) display = d;
                }
            }
        }
        if (display == EGL_NO_DISPLAY) {
            EGLDisplay d = platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
            if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr) && try_context(d)) display = d;
        }
        if (display == EGL_NO_DISPLAY) return;
        ok = gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)) != 0;
        if (ok) std::fprintf(stderr, "[test context] %s | %s\n", glGetString(GL_RENDERER), glGetString(GL_VERSION));
    }

    bool try_context(EGLDisplay d) {
        if (!eglBindAPI(EGL_OPENGL_API)) return false;
        const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 3,
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        EGLContext c = eglCreateContext(d, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
        if (c == EGL_NO_CONTEXT) return false;
        if (!eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, c)) {
            eglDestroyContext(d, c);
            return false;
        }
        context = c;
        return true;
    }
};
}  // namespace

bool ensure_context() {
    static Context ctx;  // the test binary's one context, torn down at exit
    if (ctx.ok) eglMakeCurrent(ctx.display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx.context);
    return ctx.ok;
}

pf_gl_proc get_proc(const char* name) { return reinterpret_cast<pf_gl_proc>(eglGetProcAddress(name)); }

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
