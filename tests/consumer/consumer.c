/* A tiny engine-side program built outside pflip's tree against an installed or embedded pflip
 * (tests/consumer/consumer_test.cmake builds it three ways). It brings its own GL context (EGL
 * surfaceless, Mesa llvmpipe without a GPU), runs one step and checks what came back: the
 * point is that the package, not pflip's own build, gives a working header and library. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <pf/pf.h>

#include <math.h>
#include <stdio.h>

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif
#ifndef EGL_NO_CONFIG_KHR
#define EGL_NO_CONFIG_KHR ((EGLConfig)0)
#endif

static int fail(const char* what) {
    fprintf(stderr, "pflip consumer: FAILED: %s\n", what);
    return 1;
}

static pf_gl_proc get_proc(const char* name) { return (pf_gl_proc)eglGetProcAddress(name); }

static void log_message(void* user, pf_log_level level, pf_result code, const char* message) {
    (void)user;
    if (level <= PF_LOG_WARNING) fprintf(stderr, "pflip: %s (%s)\n", message, pf_result_string(code));
}

/* One step of a small box of liquid; 0 on success. */
static int run_one_step(void) {
    pf_sim_desc desc = pf_default_sim_desc();
    pf_sim* sim = NULL;
    pf_stats before, after;
    const float lo[3] = {0.0f, 0.0f, 0.0f}, hi[3] = {0.5f, 0.5f, 0.5f};
    float xyz[3] = {-1.0f, -1.0f, -1.0f};
    int rc = 0;
    /* Output structs say how large the caller compiled them (pf.h ABI rules). */
    before.struct_size = after.struct_size = (uint32_t)sizeof(pf_stats);

    desc.grid_size[0] = desc.grid_size[1] = desc.grid_size[2] = 16;
    desc.cell_size = 1.0f / 16.0f; /* a 1 m cube */
    desc.max_particles = 1u << 16;
    desc.gl_get_proc_address = get_proc;
    desc.logger.fn = log_message;
    if (pf_create(&desc, &sim) != PF_OK) return fail("pf_create");
    if (pf_fill_box(sim, lo, hi, NULL) != PF_OK) rc = fail("pf_fill_box");
    if (!rc && pf_get_stats(sim, &before) != PF_OK) rc = fail("pf_get_stats");
    if (!rc && pf_step(sim, 1.0f / 60.0f) != PF_OK) rc = fail("pf_step");
    if (!rc && pf_get_stats(sim, &after) != PF_OK) rc = fail("pf_get_stats after the step");
    /* 8 particles per cell in the 8^3 cells of the box. */
    if (!rc && before.particle_count != 8u * 8u * 8u * 8u) rc = fail("particle count after pf_fill_box");
    if (!rc && after.particle_count != before.particle_count) rc = fail("particle count changed by the step");
    if (!rc && after.steps != 1) rc = fail("pf_stats.steps after one step");
    if (!rc && pf_read_particles(sim, 0, 1, xyz, NULL) != PF_OK) rc = fail("pf_read_particles");
    if (!rc && !(isfinite(xyz[0]) && xyz[0] >= 0.0f && xyz[0] <= 1.0f && xyz[1] >= 0.0f && xyz[1] <= 1.0f &&
                 xyz[2] >= 0.0f && xyz[2] <= 1.0f))
        rc = fail("particle 0 is outside the domain");
    if (!rc)
        printf("pflip consumer: pflip %s, %u particles, one step: ok\n", PF_VERSION_STRING, after.particle_count);
    pf_destroy(sim);
    return rc;
}

int main(void) {
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    static const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 3,
                                             EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                             EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLDisplay dpy;
    EGLContext ctx;
    int rc;

    /* The header the consumer compiled against and the library it loaded must agree. */
    if (pf_version() != PF_VERSION) return fail("pf_version() differs from PF_VERSION");
    if (!get_display) return fail("eglGetPlatformDisplayEXT missing");
    dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, NULL, NULL)) return fail("EGL surfaceless display");
    if (!eglBindAPI(EGL_OPENGL_API)) return fail("eglBindAPI(EGL_OPENGL_API)");
    ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, context_attribs);
    if (ctx == EGL_NO_CONTEXT) return fail("eglCreateContext (GL 4.3 core, no config)");
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) return fail("eglMakeCurrent");

    rc = run_one_step();

    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, ctx);
    eglTerminate(dpy);
    return rc;
}
