#include "egl_context.h"

#include "util.h"

#define EGL_NO_X11
#define MESA_EGL_NO_X11_HEADERS
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#ifndef EGL_PLATFORM_DEVICE_EXT
#define EGL_PLATFORM_DEVICE_EXT 0x313F
#endif
#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif
#ifndef EGL_DRM_DEVICE_FILE_EXT
#define EGL_DRM_DEVICE_FILE_EXT 0x3233
#endif
#ifndef EGL_NO_CONFIG_KHR
#define EGL_NO_CONFIG_KHR ((EGLConfig)0)
#endif
#ifndef EGL_CONTEXT_MAJOR_VERSION
#define EGL_CONTEXT_MAJOR_VERSION 0x3098
#endif
#ifndef EGL_CONTEXT_MINOR_VERSION
#define EGL_CONTEXT_MINOR_VERSION 0x30FB
#endif
#ifndef EGL_CONTEXT_OPENGL_PROFILE_MASK
#define EGL_CONTEXT_OPENGL_PROFILE_MASK 0x30FD
#endif
#ifndef EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT
#define EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT 0x00000001
#endif
#ifndef EGL_CONTEXT_OPENGL_DEBUG
#define EGL_CONTEXT_OPENGL_DEBUG 0x31B0
#endif

namespace pfs {

pf_gl_proc get_proc(const char* name) {
    return reinterpret_cast<pf_gl_proc>(eglGetProcAddress(name));
}

namespace {

// Whole-word search in a space-separated extension string.
bool has_ext(const char* list, const char* name) {
    if (!list || !name || !*name) return false;
    const size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
        const bool start_ok = p == list || p[-1] == ' ';
        const bool end_ok = p[n] == ' ' || p[n] == '\0';
        if (start_ok && end_ok) return true;
    }
    return false;
}

const char* egl_error_name(EGLint e) {
    switch (e) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return "EGL error";
    }
}

std::string egl_err() {
    const EGLint e = eglGetError();
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s (0x%04X)", egl_error_name(e), unsigned(e));
    return buf;
}

const char* client_extensions() {
    // NULL (with EGL_BAD_DISPLAY) when EGL_EXT_client_extensions is unsupported.
    const char* s = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!s) eglGetError();
    return s;
}

PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display_fn() {
    return reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
}

typedef const unsigned char* (*GetStringFn)(unsigned int);
constexpr unsigned int kGL_VENDOR = 0x1F00, kGL_RENDERER = 0x1F01, kGL_VERSION = 0x1F02;

} // namespace

EglContext::EglContext(const Options& o) {
    std::string log;
    const char* forced = std::getenv("PF_EGL_PLATFORM");
    std::string want = forced ? forced : "";
    if (!want.empty() && want != "device" && want != "surfaceless")
        throw Error("PF_EGL_PLATFORM='" + want + "': expected 'device' or 'surfaceless'");

    bool ok = false;
    if (want.empty() || want == "device") ok = try_device(o, log);
    if (!ok && (want.empty() || want == "surfaceless")) ok = try_surfaceless(o, log);
    if (!ok) {
        throw Error("could not create a headless OpenGL " + std::to_string(o.major) + "." +
                    std::to_string(o.minor) + " core context with EGL" +
                    (want.empty() ? std::string() : " (PF_EGL_PLATFORM=" + want + ")") + ":\n" + log);
    }
    if (o.verbose) std::fprintf(stderr, "%s", log.c_str());
}

EglContext::~EglContext() { release(); }

void EglContext::release() {
    if (display_) {
        EGLDisplay dpy = static_cast<EGLDisplay>(display_);
        eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surface_) eglDestroySurface(dpy, static_cast<EGLSurface>(surface_));
        if (context_) eglDestroyContext(dpy, static_cast<EGLContext>(context_));
        eglTerminate(dpy);
        eglReleaseThread();
    }
    display_ = context_ = surface_ = nullptr;
}

void EglContext::make_current() {
    EGLSurface s = surface_ ? static_cast<EGLSurface>(surface_) : EGL_NO_SURFACE;
    if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), s, s, static_cast<EGLContext>(context_)))
        throw Error("eglMakeCurrent failed: " + egl_err());
}

void EglContext::release_current() {
    if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT))
        throw Error("eglMakeCurrent (release) failed: " + egl_err());
}

bool EglContext::try_device(const Options& o, std::string& log) {
    const char* cext = client_extensions();
    const bool enumerate = has_ext(cext, "EGL_EXT_device_base") || has_ext(cext, "EGL_EXT_device_enumeration");
    const bool query = has_ext(cext, "EGL_EXT_device_base") || has_ext(cext, "EGL_EXT_device_query");
    if (!enumerate || !has_ext(cext, "EGL_EXT_platform_device") || !has_ext(cext, "EGL_EXT_platform_base")) {
        log += "  device: EGL_EXT_device_enumeration / EGL_EXT_platform_device not supported\n";
        return false;
    }
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto query_device_string =
        query ? reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"))
              : nullptr;
    auto get_platform_display = get_platform_display_fn();
    if (!query_devices || !get_platform_display) {
        log += "  device: eglQueryDevicesEXT / eglGetPlatformDisplayEXT missing\n";
        return false;
    }
    EGLint n = 0;
    if (!query_devices(0, nullptr, &n) || n <= 0) {
        log += "  device: no EGL devices (" + egl_err() + ")\n";
        return false;
    }
    std::vector<EGLDeviceEXT> devices(static_cast<size_t>(n));
    if (!query_devices(n, devices.data(), &n) || n <= 0) {
        log += "  device: eglQueryDevicesEXT failed: " + egl_err() + "\n";
        return false;
    }
    devices.resize(static_cast<size_t>(n));

    auto dev_exts = [&](EGLDeviceEXT d) -> std::string {
        if (!query_device_string) return {};
        const char* s = query_device_string(d, EGL_EXTENSIONS);
        return s ? s : "";
    };
    auto dev_drm = [&](EGLDeviceEXT d) -> std::string {
        if (!query_device_string || !has_ext(dev_exts(d).c_str(), "EGL_EXT_device_drm")) return {};
        const char* s = query_device_string(d, EGL_DRM_DEVICE_FILE_EXT);
        if (!s) eglGetError();
        return s ? s : "";
    };

    // Try order: PF_EGL_DEVICE if set; else hardware devices in enumeration order, then
    // software ones (Mesa lists an llvmpipe "device" too, and glvnd's vendor order is not a
    // promise that the GPU comes first).
    std::vector<int> order;
    if (const char* env = std::getenv("PF_EGL_DEVICE"); env && *env) {
        const uint32_t idx = parse_u32(env, "PF_EGL_DEVICE", 0, uint32_t(n - 1));
        order.push_back(int(idx));
    } else {
        for (int i = 0; i < n; ++i)
            if (!has_ext(dev_exts(devices[size_t(i)]).c_str(), "EGL_MESA_device_software")) order.push_back(i);
        for (int i = 0; i < n; ++i)
            if (has_ext(dev_exts(devices[size_t(i)]).c_str(), "EGL_MESA_device_software")) order.push_back(i);
    }

    for (int i : order) {
        EGLDeviceEXT d = devices[size_t(i)];
        const std::string exts = dev_exts(d);
        const std::string drm = dev_drm(d);
        std::string what = "device " + std::to_string(i) + "/" + std::to_string(n);
        if (!drm.empty()) what += " " + drm;
        if (has_ext(exts.c_str(), "EGL_MESA_device_software")) what += " (software)";
        if (has_ext(exts.c_str(), "EGL_NV_device_cuda")) what += " (NVIDIA CUDA device)";
        EGLDisplay dpy = get_platform_display(EGL_PLATFORM_DEVICE_EXT, d, nullptr);
        if (dpy == EGL_NO_DISPLAY) {
            log += "  " + what + ": eglGetPlatformDisplayEXT failed: " + egl_err() + "\n";
            continue;
        }
        std::string sub;
        if (create_on_display(dpy, o, sub)) {
            platform_ = "device";
            device_info_ = what;
            log += "  " + what + ": ok\n";
            return true;
        }
        log += "  " + what + ": " + sub;
    }
    return false;
}

bool EglContext::try_surfaceless(const Options& o, std::string& log) {
    const char* cext = client_extensions();
    if (!has_ext(cext, "EGL_MESA_platform_surfaceless") || !has_ext(cext, "EGL_EXT_platform_base")) {
        log += "  surfaceless: EGL_MESA_platform_surfaceless not supported\n";
        return false;
    }
    auto get_platform_display = get_platform_display_fn();
    if (!get_platform_display) {
        log += "  surfaceless: eglGetPlatformDisplayEXT missing\n";
        return false;
    }
    EGLDisplay dpy = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (dpy == EGL_NO_DISPLAY) {
        log += "  surfaceless: eglGetPlatformDisplayEXT failed: " + egl_err() + "\n";
        return false;
    }
    std::string sub;
    if (create_on_display(dpy, o, sub)) {
        platform_ = "surfaceless";
        log += "  surfaceless: ok\n";
        return true;
    }
    log += "  surfaceless: " + sub;
    return false;
}

bool EglContext::create_on_display(void* display, const Options& o, std::string& log) {
    EGLDisplay dpy = static_cast<EGLDisplay>(display);
    EGLint emaj = 0, emin = 0;
    if (!eglInitialize(dpy, &emaj, &emin)) {
        log += "eglInitialize failed: " + egl_err() + "\n";
        return false;
    }
    auto fail = [&](const std::string& why, EGLContext ctx, EGLSurface surf) {
        log += why + "\n";
        eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surf != EGL_NO_SURFACE) eglDestroySurface(dpy, surf);
        if (ctx != EGL_NO_CONTEXT) eglDestroyContext(dpy, ctx);
        eglTerminate(dpy);
        return false;
    };
    if (!eglBindAPI(EGL_OPENGL_API)) return fail("eglBindAPI(EGL_OPENGL_API) failed: " + egl_err(), EGL_NO_CONTEXT, EGL_NO_SURFACE);

    const char* dext = eglQueryString(dpy, EGL_EXTENSIONS);
    const bool no_config = has_ext(dext, "EGL_KHR_no_config_context") || has_ext(dext, "EGL_MESA_configless_context");
    const bool surfaceless = has_ext(dext, "EGL_KHR_surfaceless_context");
    const bool versioned = (emaj > 1 || (emaj == 1 && emin >= 5)) || has_ext(dext, "EGL_KHR_create_context");
    if (!versioned)
        return fail("EGL " + std::to_string(emaj) + "." + std::to_string(emin) +
                        " without EGL_KHR_create_context cannot request a GL version",
                    EGL_NO_CONTEXT, EGL_NO_SURFACE);

    // A config is only needed when we cannot go config-less or must fall back to a pbuffer.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!no_config || !surfaceless) {
        const EGLint cfg_attribs[] = {EGL_SURFACE_TYPE, surfaceless ? 0 : EGL_PBUFFER_BIT,
                                      EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                      EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                                      EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(dpy, cfg_attribs, &config, 1, &count) || count < 1)
            return fail("no EGL config with EGL_OPENGL_BIT: " + egl_err(), EGL_NO_CONTEXT, EGL_NO_SURFACE);
    }

    std::vector<EGLint> attribs = {EGL_CONTEXT_MAJOR_VERSION, o.major, EGL_CONTEXT_MINOR_VERSION, o.minor,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT};
    if (o.debug) {
        attribs.push_back(EGL_CONTEXT_OPENGL_DEBUG);
        attribs.push_back(EGL_TRUE);
    }
    attribs.push_back(EGL_NONE);
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, attribs.data());
    if (ctx == EGL_NO_CONTEXT)
        return fail("eglCreateContext(GL " + std::to_string(o.major) + "." + std::to_string(o.minor) +
                        " core) failed: " + egl_err(),
                    EGL_NO_CONTEXT, EGL_NO_SURFACE);

    EGLSurface surf = EGL_NO_SURFACE;
    if (!surfaceless) {
        const EGLint pb_attribs[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
        surf = eglCreatePbufferSurface(dpy, config, pb_attribs);
        if (surf == EGL_NO_SURFACE) return fail("eglCreatePbufferSurface failed: " + egl_err(), ctx, EGL_NO_SURFACE);
    }
    if (!eglMakeCurrent(dpy, surf, surf, ctx)) return fail("eglMakeCurrent failed: " + egl_err(), ctx, surf);

    auto get_string = reinterpret_cast<GetStringFn>(eglGetProcAddress("glGetString"));
    const unsigned char* ver = get_string ? get_string(kGL_VERSION) : nullptr;
    if (!ver) return fail("glGetString(GL_VERSION) returned NULL", ctx, surf);
    int gmaj = 0, gmin = 0;
    if (std::sscanf(reinterpret_cast<const char*>(ver), "%d.%d", &gmaj, &gmin) != 2 ||
        gmaj * 100 + gmin < o.major * 100 + o.minor)
        return fail(std::string("context reports GL_VERSION '") + reinterpret_cast<const char*>(ver) + "'", ctx, surf);

    auto str = [&](unsigned int name) {
        const unsigned char* s = get_string(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    gl_vendor_ = str(kGL_VENDOR);
    gl_renderer_ = str(kGL_RENDERER);
    gl_version_ = str(kGL_VERSION);
    const char* ev = eglQueryString(dpy, EGL_VENDOR);
    const char* evs = eglQueryString(dpy, EGL_VERSION);
    egl_vendor_ = ev ? ev : "?";
    egl_version_ = evs ? evs : "?";
    display_ = dpy;
    context_ = ctx;
    surface_ = surf == EGL_NO_SURFACE ? nullptr : surf;
    return true;
}

std::string EglContext::describe() const {
    std::string s = "EGL platform: " + platform_;
    if (!device_info_.empty()) s += " [" + device_info_ + "]";
    s += "\nEGL: " + egl_vendor_ + " " + egl_version_;
    s += "\nGL_VENDOR:   " + gl_vendor_;
    s += "\nGL_RENDERER: " + gl_renderer_;
    s += "\nGL_VERSION:  " + gl_version_;
    return s;
}

} // namespace pfs
