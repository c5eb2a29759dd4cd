// pf_headless — the pflip demo without a window.
//
// Creates a headless GL 4.3 context (EGL), loads a scene, runs it with pf_step and every K
// frames draws the particles straight from pflip's GL buffers (pf_get_gl_buffers) as shaded
// sphere sprites into an offscreen framebuffer, reads it back and writes frame_NNNN.png.
// At the end it prints pflip's per-pass GPU timings and the wall time per step.
//
// Only the public API (pf/pf.h) is used for the simulation; the drawing uses the sample's own
// GL loader (glad, global functions), just as an engine would use its own.

#include <glad/gl.h>

#include <pf/pf.h>

#include "egl_context.h"
#include "image_write.h"
#include "scene.h"
#include "util.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace {

using pfs::Error;

// ---- command line ---------------------------------------------------------------------------

struct Options {
    std::string scene = "dam_break_small";
    bool frames_set = false;
    uint32_t frames = 0;
    std::string out = "out";
    uint32_t width = 960, height = 540;
    uint32_t every = 4;
    uint32_t msaa = 4;
    float speed_max = 0; // colour scale; 0: sqrt(2 g H) of the scene
    bool verbose = false;
    bool debug = false;
};

void print_usage(std::FILE* f) {
    std::fprintf(f,
                 "usage: pf_headless [options]\n"
                 "  --scene PATH|NAME   scene file, or a name in the scenes directory (default dam_break_small)\n"
                 "  --frames N          frames to simulate (default: the scene's \"frames\")\n"
                 "  --out DIR           where frame_NNNN.png go (default ./out)\n"
                 "  --size WxH          image size (default 960x540)\n"
                 "  --every K           write an image every K frames, 0 = none (default 4)\n"
                 "  --msaa N            multisample count for the images, 1 = off (default 4)\n"
                 "  --speed-max V       speed (m/s) drawn white; default from the scene height\n"
                 "  --verbose           pflip's info messages and EGL details\n"
                 "  --debug-context     request a debug GL context\n"
                 "  -h, --help          this text\n"
                 "environment: PF_EGL_PLATFORM=device|surfaceless, PF_EGL_DEVICE=N, PF_SCENES_DIR=DIR\n"
                 "scenes directory: %s\n",
                 pfs::scenes_dir().c_str());
}

Options parse_args(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw Error(a + " needs a value (see --help)");
            return argv[++i];
        };
        if (a == "-h" || a == "--help") {
            print_usage(stdout);
            std::exit(0);
        } else if (a == "--scene") {
            o.scene = value();
        } else if (a == "--frames") {
            o.frames = pfs::parse_u32(value(), "--frames", 0, 10000000);
            o.frames_set = true;
        } else if (a == "--out") {
            o.out = value();
        } else if (a == "--size") {
            pfs::parse_size(value(), "--size", o.width, o.height);
        } else if (a == "--every") {
            o.every = pfs::parse_u32(value(), "--every", 0, 1000000);
        } else if (a == "--msaa") {
            o.msaa = pfs::parse_u32(value(), "--msaa", 1, 16);
        } else if (a == "--speed-max") {
            o.speed_max = pfs::parse_float(value(), "--speed-max", 0.001f, 1e4f);
        } else if (a == "--verbose") {
            o.verbose = true;
        } else if (a == "--debug-context") {
            o.debug = true;
        } else {
            throw Error("unknown argument '" + a + "' (see --help)");
        }
    }
    return o;
}

// ---- GL helpers -----------------------------------------------------------------------------

const char* gl_error_name(GLenum e) {
    switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "GL error";
    }
}

void check_gl(const char* where) {
    GLenum e = glGetError();
    if (e == GL_NO_ERROR) return;
    std::string msg = std::string("GL error in ") + where + ":";
    for (int n = 0; e != GL_NO_ERROR && n < 8; ++n, e = glGetError()) msg += std::string(" ") + gl_error_name(e);
    throw Error(msg);
}

GLuint compile(GLenum type, const char* src, const char* name) {
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(std::max(len, 1)), '\0');
        glGetShaderInfoLog(s, len, nullptr, log.data());
        glDeleteShader(s);
        throw Error(std::string("compiling ") + name + " failed:\n" + log);
    }
    return s;
}

GLuint link(const char* vs, const char* fs, const char* name) {
    const GLuint v = compile(GL_VERTEX_SHADER, vs, name);
    GLuint f = 0;
    try {
        f = compile(GL_FRAGMENT_SHADER, fs, name);
    } catch (...) {
        glDeleteShader(v);
        throw;
    }
    GLuint p = glCreateProgram();
    glAttachShader(p, v);
    glAttachShader(p, f);
    glLinkProgram(p);
    glDeleteShader(v);
    glDeleteShader(f);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(p, GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(std::max(len, 1)), '\0');
        glGetProgramInfoLog(p, len, nullptr, log.data());
        glDeleteProgram(p);
        throw Error(std::string("linking ") + name + " failed:\n" + log);
    }
    return p;
}

// ---- shaders --------------------------------------------------------------------------------

// Particles: positions and velocities come straight from pflip's buffers as vertex attributes
// (vec4 per particle, stride 16). Each is drawn as a point sprite sized to the sphere's
// projected diameter; the fragment shader turns it into a lit sphere with correct depth.
const char* kParticleVS = R"(#version 430 core
layout(location = 0) in vec4 a_position;
layout(location = 1) in vec4 a_velocity;
uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_radius;
uniform float u_viewport_height;
uniform float u_inv_speed_max;
out vec3 v_center;   // view space
out vec3 v_color;
void main() {
    vec4 c = u_view * vec4(a_position.xyz, 1.0);
    v_center = c.xyz;
    gl_Position = u_proj * c;
    gl_PointSize = clamp(u_viewport_height * u_proj[1][1] * u_radius / max(gl_Position.w, 1e-4), 1.0, 64.0);
    float t = clamp(length(a_velocity.xyz) * u_inv_speed_max, 0.0, 1.0);
    vec3 deep  = vec3(0.03, 0.20, 0.55);
    vec3 water = vec3(0.10, 0.50, 0.90);
    vec3 foam  = vec3(0.88, 0.96, 1.00);
    v_color = mix(mix(deep, water, smoothstep(0.0, 0.45, t)), foam, smoothstep(0.45, 1.0, t));
}
)";

const char* kParticleFS = R"(#version 430 core
in vec3 v_center;
in vec3 v_color;
uniform mat4 u_proj;
uniform float u_radius;
uniform vec3 u_light_dir;   // view space, towards the light
layout(location = 0) out vec4 o_color;
void main() {
    vec2 p = gl_PointCoord * 2.0 - 1.0;
    p.y = -p.y;
    float r2 = dot(p, p);
    if (r2 > 1.0) discard;
    vec3 n = vec3(p, sqrt(1.0 - r2));
    vec4 clip = u_proj * vec4(v_center + n * u_radius, 1.0);
    gl_FragDepth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
    vec3 l = normalize(u_light_dir);
    float diffuse = max(dot(n, l), 0.0);
    vec3 h = normalize(l + vec3(0.0, 0.0, 1.0));
    float spec = pow(max(dot(n, h), 0.0), 40.0);
    float rim = pow(1.0 - n.z, 3.0);
    vec3 c = v_color * (0.28 + 0.72 * diffuse) + vec3(0.45) * spec + vec3(0.10, 0.15, 0.20) * rim;
    o_color = vec4(c, 1.0);
}
)";

// Floor (checker) and tank outline: world-space triangles / lines with a flat colour.
const char* kSceneVS = R"(#version 430 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_proj;
out vec3 v_world;
void main() {
    v_world = a_position;
    gl_Position = u_view_proj * vec4(a_position, 1.0);
}
)";

const char* kSceneFS = R"(#version 430 core
in vec3 v_world;
uniform vec3 u_color;
uniform float u_checker;    // checker cell size in metres; 0: flat colour
uniform vec3 u_tank_min;
uniform vec3 u_tank_max;
layout(location = 0) out vec4 o_color;
void main() {
    vec3 c = u_color;
    if (u_checker > 0.0) {
        vec2 q = floor(v_world.xz / u_checker);
        float k = mod(q.x + q.y, 2.0);
        c *= mix(0.82, 1.0, k);
        // darken outside the tank, fade with distance
        vec2 d = max(max(u_tank_min.xz - v_world.xz, v_world.xz - u_tank_max.xz), 0.0);
        c *= mix(1.0, 0.55, clamp(length(d) * 1.5, 0.0, 1.0));
    }
    o_color = vec4(c, 1.0);
}
)";

// ---- renderer -------------------------------------------------------------------------------

class Renderer {
public:
    Renderer(uint32_t w, uint32_t h, uint32_t msaa, const pfs::Scene& scene) : w_(w), h_(h) {
        GLint max_samples = 1;
        glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
        samples_ = std::min<GLint>(GLint(msaa), max_samples);
        if (samples_ < 2) samples_ = 0;

        // Multisampled target (if any) and the single-sampled one glReadPixels reads.
        glGenFramebuffers(2, fbo_);
        glGenRenderbuffers(3, rb_);
        if (samples_) {
            glBindRenderbuffer(GL_RENDERBUFFER, rb_[0]);
            glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, GLsizei(w), GLsizei(h));
            glBindRenderbuffer(GL_RENDERBUFFER, rb_[1]);
            glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, GLsizei(w), GLsizei(h));
        } else {
            glBindRenderbuffer(GL_RENDERBUFFER, rb_[0]);
            glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, GLsizei(w), GLsizei(h));
            glBindRenderbuffer(GL_RENDERBUFFER, rb_[1]);
            glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, GLsizei(w), GLsizei(h));
        }
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_[0]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb_[0]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb_[1]);
        check_complete("draw framebuffer");
        if (samples_) {
            glBindRenderbuffer(GL_RENDERBUFFER, rb_[2]);
            glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, GLsizei(w), GLsizei(h));
            glBindFramebuffer(GL_FRAMEBUFFER, fbo_[1]);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb_[2]);
            check_complete("resolve framebuffer");
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);

        particle_prog_ = link(kParticleVS, kParticleFS, "particle shader");
        scene_prog_ = link(kSceneVS, kSceneFS, "scene shader");

        // Particle VAO: two attribute bindings whose buffers are pflip's, bound at draw time.
        glGenVertexArrays(1, &particle_vao_);
        glBindVertexArray(particle_vao_);
        glVertexAttribFormat(0, 4, GL_FLOAT, GL_FALSE, 0);
        glVertexAttribBinding(0, 0);
        glEnableVertexAttribArray(0);
        glVertexAttribFormat(1, 4, GL_FLOAT, GL_FALSE, 0);
        glVertexAttribBinding(1, 1);
        glEnableVertexAttribArray(1);
        glBindVertexArray(0);

        build_static_geometry(scene);
        check_gl("renderer setup");
    }

    ~Renderer() {
        glDeleteVertexArrays(1, &particle_vao_);
        glDeleteVertexArrays(1, &scene_vao_);
        glDeleteBuffers(1, &scene_vbo_);
        glDeleteProgram(particle_prog_);
        glDeleteProgram(scene_prog_);
        glDeleteFramebuffers(2, fbo_);
        glDeleteRenderbuffers(3, rb_);
    }

    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    void set_camera(const pfs::SceneCamera& cam, float near_plane, float far_plane) {
        view_ = glm::lookAt(glm::vec3(cam.eye[0], cam.eye[1], cam.eye[2]),
                            glm::vec3(cam.target[0], cam.target[1], cam.target[2]), glm::vec3(0, 1, 0));
        proj_ = glm::perspective(glm::radians(cam.fov_deg), float(w_) / float(h_), near_plane, far_plane);
    }

    int samples() const { return samples_; }

    /// Draws the tank and the particles in bufs; leaves the image in pixels (bottom row first).
    void render(const pf_gl_buffers& bufs, float radius, float speed_max, std::vector<uint8_t>& pixels) {
        // pflip wrote the particle buffers from compute shaders (as shader storage); make those
        // writes visible to vertex fetching. Cheap if pflip already issued it.
        glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);

        glBindFramebuffer(GL_FRAMEBUFFER, fbo_[0]);
        glViewport(0, 0, GLsizei(w_), GLsizei(h_));
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        if (samples_) glEnable(GL_MULTISAMPLE);
        glClearColor(0.11f, 0.12f, 0.15f, 1.0f);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

        const glm::mat4 vp = proj_ * view_;
        glUseProgram(scene_prog_);
        glUniformMatrix4fv(glGetUniformLocation(scene_prog_, "u_view_proj"), 1, GL_FALSE, glm::value_ptr(vp));
        glUniform3fv(glGetUniformLocation(scene_prog_, "u_tank_min"), 1, tank_min_);
        glUniform3fv(glGetUniformLocation(scene_prog_, "u_tank_max"), 1, tank_max_);
        glBindVertexArray(scene_vao_);
        // floor
        glUniform3f(glGetUniformLocation(scene_prog_, "u_color"), 0.62f, 0.60f, 0.56f);
        glUniform1f(glGetUniformLocation(scene_prog_, "u_checker"), checker_);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 1.0f);
        glDrawArrays(GL_TRIANGLES, 0, 6);
        glDisable(GL_POLYGON_OFFSET_FILL);

        // particles
        if (bufs.count > 0) {
            glUseProgram(particle_prog_);
            glUniformMatrix4fv(glGetUniformLocation(particle_prog_, "u_view"), 1, GL_FALSE, glm::value_ptr(view_));
            glUniformMatrix4fv(glGetUniformLocation(particle_prog_, "u_proj"), 1, GL_FALSE, glm::value_ptr(proj_));
            glUniform1f(glGetUniformLocation(particle_prog_, "u_radius"), radius);
            glUniform1f(glGetUniformLocation(particle_prog_, "u_viewport_height"), float(h_));
            glUniform1f(glGetUniformLocation(particle_prog_, "u_inv_speed_max"), 1.0f / speed_max);
            const glm::vec3 light = glm::normalize(glm::mat3(view_) * glm::vec3(0.4f, 1.0f, 0.55f));
            glUniform3fv(glGetUniformLocation(particle_prog_, "u_light_dir"), 1, glm::value_ptr(light));
            glEnable(GL_PROGRAM_POINT_SIZE);
            glBindVertexArray(particle_vao_);
            glBindVertexBuffer(0, bufs.positions, 0, GLsizei(bufs.stride));
            glBindVertexBuffer(1, bufs.velocities, 0, GLsizei(bufs.stride));
            glDrawArrays(GL_POINTS, 0, GLsizei(bufs.count));
            // Do not keep pflip's buffers referenced by our VAO.
            glBindVertexBuffer(0, 0, 0, 16);
            glBindVertexBuffer(1, 0, 0, 16);
            glDisable(GL_PROGRAM_POINT_SIZE);
        }

        // tank outline on top of the floor, depth tested against the particles
        glUseProgram(scene_prog_);
        glBindVertexArray(scene_vao_);
        glUniform3f(glGetUniformLocation(scene_prog_, "u_color"), 0.85f, 0.85f, 0.80f);
        glUniform1f(glGetUniformLocation(scene_prog_, "u_checker"), 0.0f);
        glDrawArrays(GL_LINES, 6, 24);

        glBindVertexArray(0);
        glUseProgram(0);

        // resolve and read back
        GLuint read_fbo = fbo_[0];
        if (samples_) {
            glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_[0]);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_[1]);
            glBlitFramebuffer(0, 0, GLint(w_), GLint(h_), 0, 0, GLint(w_), GLint(h_), GL_COLOR_BUFFER_BIT, GL_NEAREST);
            read_fbo = fbo_[1];
        }
        glBindFramebuffer(GL_READ_FRAMEBUFFER, read_fbo);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glPixelStorei(GL_PACK_ROW_LENGTH, 0);
        pixels.resize(size_t(w_) * h_ * 4);
        glReadPixels(0, 0, GLsizei(w_), GLsizei(h_), GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        check_gl("render");
    }

private:
    void check_complete(const char* what) {
        const GLenum st = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        if (st != GL_FRAMEBUFFER_COMPLETE) {
            char buf[96];
            std::snprintf(buf, sizeof buf, "%s incomplete (status 0x%04X)", what, unsigned(st));
            throw Error(buf);
        }
    }

    void build_static_geometry(const pfs::Scene& s) {
        const pfs::vec3f lo = s.domain_min(), hi = s.domain_max();
        for (int a = 0; a < 3; ++a) {
            tank_min_[a] = lo[a];
            tank_max_[a] = hi[a];
        }
        const float ex = hi[0] - lo[0], ez = hi[2] - lo[2];
        const float m = 0.6f * std::max(ex, ez);
        checker_ = 4.0f * s.cell_size;
        std::vector<float> v;
        auto p = [&](float x, float y, float z) { v.insert(v.end(), {x, y, z}); };
        // floor quad, slightly below the tank bottom
        const float y0 = lo[1] - 0.001f * (hi[1] - lo[1]);
        const float x0 = lo[0] - m, x1 = hi[0] + m, z0 = lo[2] - m, z1 = hi[2] + m;
        p(x0, y0, z0); p(x1, y0, z0); p(x1, y0, z1);
        p(x0, y0, z0); p(x1, y0, z1); p(x0, y0, z1);
        // 12 edges of the tank
        const float c[2][3] = {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
        for (int axis = 0; axis < 3; ++axis) {
            const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j) {
                    float e0[3], e1[3];
                    e0[axis] = c[0][axis];
                    e1[axis] = c[1][axis];
                    e0[a1] = e1[a1] = c[i][a1];
                    e0[a2] = e1[a2] = c[j][a2];
                    p(e0[0], e0[1], e0[2]);
                    p(e1[0], e1[1], e1[2]);
                }
        }
        glGenVertexArrays(1, &scene_vao_);
        glGenBuffers(1, &scene_vbo_);
        glBindVertexArray(scene_vao_);
        glBindBuffer(GL_ARRAY_BUFFER, scene_vbo_);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(float)), v.data(), GL_STATIC_DRAW);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
        glEnableVertexAttribArray(0);
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }

    uint32_t w_, h_;
    GLint samples_ = 0;
    GLuint fbo_[2] = {0, 0};
    GLuint rb_[3] = {0, 0, 0};
    GLuint particle_prog_ = 0, scene_prog_ = 0;
    GLuint particle_vao_ = 0, scene_vao_ = 0, scene_vbo_ = 0;
    glm::mat4 view_{1.0f}, proj_{1.0f};
    float tank_min_[3] = {}, tank_max_[3] = {};
    float checker_ = 0.1f;
};

// ---- the simulation handle ------------------------------------------------------------------

struct SimDeleter {
    void operator()(pf_sim* s) const { pf_destroy(s); }
};
using SimPtr = std::unique_ptr<pf_sim, SimDeleter>;

std::string flag_names(uint32_t flags) {
    std::string s;
    auto add = [&](uint32_t bit, const char* name) {
        if (flags & bit) s += std::string(s.empty() ? "" : " ") + name;
    };
    add(PF_FLAG_P2G_OVERFLOW, "P2G_OVERFLOW");
    add(PF_FLAG_NONFINITE, "NONFINITE");
    add(PF_FLAG_SPEED_CLAMPED, "SPEED_CLAMPED");
    add(PF_FLAG_SUBSTEPS_CLAMPED, "SUBSTEPS_CLAMPED");
    return s.empty() ? "none" : s;
}

int run(int argc, char** argv) {
    const double t_start = pfs::now_ms();
    const Options opt = parse_args(argc, argv);

    // Scene first: a typo in the file should not cost a context creation.
    const std::string scene_path = pfs::resolve_scene_path(opt.scene);
    const pfs::Scene scene = pfs::load_scene(scene_path);
    const uint32_t frames = opt.frames_set ? opt.frames : scene.frames;

    pfs::EglContext::Options copt;
    copt.debug = opt.debug;
    copt.verbose = opt.verbose;
    pfs::EglContext ctx(copt);
    std::printf("pflip %s headless demo\n%s\n", pfs::pf_version_string().c_str(), ctx.describe().c_str());

    // The sample's own GL loader, as an engine would have.
    const int glv = gladLoadGL(pfs::get_proc);
    if (!glv || GLAD_VERSION_MAJOR(glv) * 100 + GLAD_VERSION_MINOR(glv) < 403)
        throw Error("gladLoadGL: OpenGL 4.3 core functions not available");

    const pf_sim_desc desc = pfs::make_sim_desc(scene, pfs::get_proc, pfs::stderr_logger(opt.verbose));
    std::printf("scene: %s (%s)\n  grid %ux%ux%u, cell %.4g m, domain %.3g x %.3g x %.3g m, capacity %u\n",
                scene.name.c_str(), scene_path.c_str(), desc.grid_size[0], desc.grid_size[1], desc.grid_size[2],
                double(desc.cell_size), double(desc.grid_size[0] * desc.cell_size),
                double(desc.grid_size[1] * desc.cell_size), double(desc.grid_size[2] * desc.cell_size),
                desc.max_particles);
    std::printf("  frame_dt %.5g s, frames %u, pressure_iterations %u, flip_ratio %.3g, cfl %.3g, max_substeps %u\n",
                double(scene.frame_dt), frames, desc.params.pressure_iterations, double(desc.params.flip_ratio),
                double(desc.params.cfl), desc.params.max_substeps);

    double t0 = pfs::now_ms();
    SimPtr sim;
    {
        pf_sim* raw = nullptr;
        pfs::check(pf_create(&desc, &raw), "pf_create");
        sim.reset(raw);
    }
    const double create_ms = pfs::now_ms() - t0;
    t0 = pfs::now_ms();
    pfs::fill_scene(sim.get(), scene);
    glFinish();
    const double fill_ms = pfs::now_ms() - t0;

    pf_stats st{};
    pfs::check(pf_get_stats(sim.get(), &st), "pf_get_stats");
    std::printf("  %u particles (estimate %.0f); pf_create %.1f ms, fill %.1f ms\n", st.particle_count,
                scene.estimated_particles(), create_ms, fill_ms);

    // Rendering setup.
    std::unique_ptr<Renderer> renderer;
    float radius = 0, speed_max = opt.speed_max;
    if (opt.every > 0) {
        std::error_code ec;
        std::filesystem::create_directories(opt.out, ec);
        if (ec) throw Error("cannot create output directory '" + opt.out + "': " + ec.message());
        renderer = std::make_unique<Renderer>(opt.width, opt.height, opt.msaa, scene);
        const pfs::SceneCamera cam = scene.has_camera ? scene.camera : scene.default_camera();
        const pfs::vec3f lo = scene.domain_min(), hi = scene.domain_max();
        float diag = 0;
        for (int a = 0; a < 3; ++a) diag += (hi[a] - lo[a]) * (hi[a] - lo[a]);
        diag = std::sqrt(diag);
        float dist = 0;
        for (int a = 0; a < 3; ++a) dist += (cam.eye[a] - cam.target[a]) * (cam.eye[a] - cam.target[a]);
        dist = std::sqrt(dist);
        renderer->set_camera(cam, std::max(0.01f * diag, 1e-3f), dist + 4.0f * diag);
        const uint32_t ppc = desc.fill_particles_per_cell ? desc.fill_particles_per_cell : 8;
        radius = 0.62f * desc.cell_size / std::cbrt(float(ppc));
        if (speed_max <= 0) {
            // A bit below the shallow-water wave speed of a tank-deep layer, sqrt(g H): the
            // fastest sheets of a dam break come out white, the bulk stays blue.
            const float g = std::sqrt(desc.params.gravity[0] * desc.params.gravity[0] +
                                      desc.params.gravity[1] * desc.params.gravity[1] +
                                      desc.params.gravity[2] * desc.params.gravity[2]);
            speed_max = std::max(0.5f, 0.8f * std::sqrt(std::max(g, 1.0f) * (hi[1] - lo[1])));
        }
        std::printf("  images: %ux%u every %u frames (msaa %d) -> %s/frame_NNNN.png, speed %.2f m/s drawn white\n",
                    opt.width, opt.height, opt.every, renderer->samples(), opt.out.c_str(), double(speed_max));
    }

    // ---- main loop ----
    struct GpuSample {
        uint64_t step;
        float ms[PF_PASS_COUNT];
        float total;
    };
    std::vector<GpuSample> gpu_samples;
    std::vector<uint32_t> substeps_of_step(1, 0); // index: step number (1-based)
    std::vector<double> wall_ms, cpu_ms;
    uint32_t dispatches[PF_PASS_COUNT] = {};
    uint64_t last_gpu_step = 0;
    uint32_t image_index = 0;
    double sim_total_ms = 0, render_total_ms = 0, png_total_ms = 0;
    std::vector<uint8_t> pixels;
    const uint32_t report_every = std::max(1u, frames / 10);

    auto write_image = [&](uint32_t frame) {
        pf_gl_buffers bufs{};
        pfs::check(pf_get_gl_buffers(sim.get(), &bufs), "pf_get_gl_buffers");
        const double r0 = pfs::now_ms();
        renderer->render(bufs, radius, speed_max, pixels);
        const double r1 = pfs::now_ms();
        char name[64];
        std::snprintf(name, sizeof name, "frame_%04u.png", image_index++);
        const std::string path = (std::filesystem::path(opt.out) / name).string();
        if (!pfs::write_png_rgba(path, opt.width, opt.height, pixels.data(), true))
            throw Error("writing " + path + " failed: " + std::strerror(errno));
        render_total_ms += r1 - r0;
        png_total_ms += pfs::now_ms() - r1;
        (void)frame;
    };

    if (renderer) write_image(0);
    for (uint32_t f = 1; f <= frames; ++f) {
        glFinish();
        const double s0 = pfs::now_ms();
        pfs::check(pf_step(sim.get(), scene.frame_dt), "pf_step");
        glFinish();
        const double s1 = pfs::now_ms();
        wall_ms.push_back(s1 - s0);
        sim_total_ms += s1 - s0;

        pfs::check(pf_get_stats(sim.get(), &st), "pf_get_stats");
        cpu_ms.push_back(st.cpu_ms);
        if (substeps_of_step.size() <= st.steps) substeps_of_step.resize(st.steps + 1, 0);
        substeps_of_step[st.steps] = st.substeps;
        std::copy(st.dispatches, st.dispatches + PF_PASS_COUNT, dispatches);
        if (st.gpu_step != 0 && st.gpu_step != last_gpu_step) {
            GpuSample g{};
            g.step = st.gpu_step;
            std::copy(st.gpu_ms, st.gpu_ms + PF_PASS_COUNT, g.ms);
            g.total = st.gpu_total_ms;
            gpu_samples.push_back(g);
            last_gpu_step = st.gpu_step;
        }

        if (f % report_every == 0 || f == frames)
            std::printf("frame %4u/%u  t=%.3f s  substeps %u  max|v| %.2f m/s  step %.1f ms (wall)  gpu %.2f ms%s%s\n",
                        f, frames, double(f) * double(scene.frame_dt), st.substeps, double(st.max_speed),
                        s1 - s0, double(st.gpu_total_ms), st.flags ? "  flags: " : "",
                        st.flags ? flag_names(st.flags).c_str() : "");
        std::fflush(stdout);

        if (renderer && (f % opt.every == 0 || f == frames)) write_image(f);
    }

    // ---- report ----
    pfs::check(pf_get_stats(sim.get(), &st), "pf_get_stats");
    std::printf("\n=== %s: %u frames, %u particles (capacity %u), GL_RENDERER %s ===\n", scene.name.c_str(), frames,
                st.particle_count, st.max_particles, ctx.gl_renderer().c_str());

    double gpu_sum_total = 0;
    for (const auto& g : gpu_samples) gpu_sum_total += g.total;
    const bool gpu_valid = !gpu_samples.empty() && gpu_sum_total > 0;
    std::printf("GPU time per step (pf_get_stats, %zu distinct measured steps%s):\n", gpu_samples.size(),
                gpu_valid ? "" : "; timer queries read 0 on this driver");
    std::printf("  %-18s %12s %12s %7s %12s\n", "pass", "mean ms", "median ms", "share", "dispatches*");
    double total_mean = 0;
    std::vector<pfs::Summary> per_pass(PF_PASS_COUNT);
    for (int p = 0; p < PF_PASS_COUNT; ++p) {
        std::vector<double> v;
        for (const auto& g : gpu_samples) v.push_back(g.ms[p]);
        per_pass[size_t(p)] = pfs::summarize(v);
        total_mean += per_pass[size_t(p)].mean;
    }
    for (int p = 0; p < PF_PASS_COUNT; ++p) {
        const auto& s = per_pass[size_t(p)];
        std::printf("  %-18s %12.4f %12.4f %6.1f%% %12u\n", pf_pass_name(pf_pass(p)), s.mean, s.median,
                    total_mean > 0 ? 100.0 * s.mean / total_mean : 0.0, dispatches[p]);
    }
    {
        std::vector<double> tot, per_sub;
        for (const auto& g : gpu_samples) {
            tot.push_back(g.total);
            const uint32_t k = g.step < substeps_of_step.size() ? substeps_of_step[g.step] : 0;
            if (k) per_sub.push_back(g.total / k);
        }
        const auto t = pfs::summarize(tot), ps = pfs::summarize(per_sub);
        std::printf("  %-18s %12.4f %12.4f\n", "total", t.mean, t.median);
        std::printf("  %-18s %12.4f %12.4f\n", "total / substep", ps.mean, ps.median);
        std::printf("  (* dispatches in the last pf_step, all its substeps)\n");
    }
    {
        std::vector<double> subs;
        for (size_t i = 1; i < substeps_of_step.size(); ++i)
            if (substeps_of_step[i]) subs.push_back(substeps_of_step[i]);
        const auto s = pfs::summarize(subs);
        const auto w = pfs::summarize(wall_ms), c = pfs::summarize(cpu_ms);
        std::printf("wall ms per step (glFinish before and after pf_step): mean %.2f  median %.2f  min %.2f  max %.2f\n",
                    w.mean, w.median, w.min, w.max);
        std::printf("  per substep: %.2f ms\n", s.mean > 0 ? w.mean / s.mean : 0.0);
        std::printf("host ms inside pf_step (pf_stats.cpu_ms): mean %.3f  median %.3f\n", c.mean, c.median);
        std::printf("substeps per step: mean %.2f  min %.0f  max %.0f  (total %.0f over %zu steps)\n", s.mean, s.min,
                    s.max, s.mean * double(s.n), s.n);
    }
    std::printf("flags: %s; largest speed %.3f m/s\n", flag_names(st.flags).c_str(), double(st.max_speed));
    const double total_s = (pfs::now_ms() - t_start) / 1000.0;
    std::printf("total wall time %.2f s: simulation %.2f s, rendering %.2f s, PNG encoding %.2f s, %u images in %s\n",
                total_s, sim_total_ms / 1000.0, render_total_ms / 1000.0, png_total_ms / 1000.0, image_index,
                renderer ? opt.out.c_str() : "(none)");

    // Tear down in order: our GL objects and the sim while the context is current; the context
    // goes last (it is declared first).
    renderer.reset();
    sim.reset();
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "pf_headless: error: %s\n", e.what());
        return 1;
    }
}
