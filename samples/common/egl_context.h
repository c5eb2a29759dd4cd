// Headless OpenGL 4.3 core context through EGL, for the samples and for anyone wanting to run
// pflip without a window.
//
// Platform order: the EGL device platform (EGL_EXT_platform_device: NVIDIA's driver on a
// machine without a display, or Mesa's DRM/software devices), then Mesa's surfaceless platform
// (EGL_MESA_platform_surfaceless, e.g. llvmpipe on machines without a GPU). The environment
// variable PF_EGL_PLATFORM=device|surfaceless forces one (no fallback); PF_EGL_DEVICE=N picks
// the N-th EGL device instead of the first hardware one.
//
// The context is created without a config (EGL_KHR_no_config_context) and made current with no
// surface (EGL_KHR_surfaceless_context): render into your own FBO.
#pragma once

#include <pf/pf.h>

#include <string>

namespace pfs {

/// GL entry point lookup for pf_sim_desc.gl_get_proc_address and gladLoadGL: wraps
/// eglGetProcAddress (which, with EGL 1.5 / glvnd, also returns core functions).
pf_gl_proc get_proc(const char* name);

class EglContext {
public:
    struct Options {
        int major = 4, minor = 3;
        bool debug = false;   ///< request a debug context (EGL_CONTEXT_OPENGL_DEBUG)
        bool verbose = false; ///< print what is tried to stderr
    };

    /// Creates the context and makes it current on the calling thread; throws pfs::Error with
    /// everything that was tried when no platform works.
    explicit EglContext(const Options& options);
    EglContext() : EglContext(Options{}) {}
    ~EglContext();

    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    /// "device" or "surfaceless".
    const std::string& platform() const { return platform_; }
    /// Details of the EGL device used (index, extensions, DRM node), empty for surfaceless.
    const std::string& device_info() const { return device_info_; }
    /// EGL_VENDOR / EGL_VERSION of the display.
    const std::string& egl_vendor() const { return egl_vendor_; }
    const std::string& egl_version() const { return egl_version_; }
    /// GL_VENDOR, GL_RENDERER, GL_VERSION of the context.
    const std::string& gl_vendor() const { return gl_vendor_; }
    const std::string& gl_renderer() const { return gl_renderer_; }
    const std::string& gl_version() const { return gl_version_; }

    /// One-paragraph human-readable summary of the above.
    std::string describe() const;

    /// Make the context current again on this thread (it already is after construction).
    void make_current();
    /// Leave this thread with no current context (make_current restores it).
    void release_current();

private:
    bool try_device(const Options& o, std::string& log);
    bool try_surfaceless(const Options& o, std::string& log);
    bool create_on_display(void* display, const Options& o, std::string& log);
    void release();

    void* display_ = nullptr; // EGLDisplay
    void* context_ = nullptr; // EGLContext
    void* surface_ = nullptr; // EGLSurface (only for the pbuffer fallback)
    std::string platform_, device_info_;
    std::string egl_vendor_, egl_version_;
    std::string gl_vendor_, gl_renderer_, gl_version_;
};

} // namespace pfs
