#include "world.h"
#include "sun_light_glsl.h"

#include "util.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <vector>

namespace pfs {

namespace {

// ---- shaders --------------------------------------------------------------------------------

// Lit world geometry. Patterns: 0 plain, 1 floor checker, 2 tiles, 3 crate planks, 4 metal.
const char* kLitVS = R"(#version 430 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
layout(location = 3) in float a_pattern;
uniform mat4 u_view_proj;
out vec3 v_world;
out vec3 v_normal;
out vec3 v_color;
flat out int v_pattern;
void main() {
    v_world = a_position;
    v_normal = a_normal;
    v_color = a_color;
    v_pattern = int(a_pattern + 0.5);
    gl_Position = u_view_proj * vec4(a_position, 1.0);
}
)";

const char* kLitFS = R"(#version 430 core
in vec3 v_world;
in vec3 v_normal;
in vec3 v_color;
flat in int v_pattern;
uniform vec3 u_sun;          // towards the sun, normalised
uniform vec3 u_eye;
uniform vec3 u_tank_min;
uniform vec3 u_tank_max;
uniform float u_tile;        // tile edge, metres
uniform float u_checker;     // floor checker edge, metres
uniform vec2 u_fog;          // horizontal distance from the tank centre: fog start, end
uniform vec3 u_fog_color;
layout(location = 0) out vec4 o_color;

float hash(vec2 p) { return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453); }

#pragma sun_light

void main() {
    vec3 n = normalize(v_normal);
    vec3 albedo = v_color;
    vec3 an = abs(n);
    vec2 uv = an.x > 0.5 ? v_world.zy : (an.y > 0.5 ? v_world.xz : v_world.xy);
    float spec_strength = 0.04, shininess = 16.0;
    if (v_pattern == 1) {
        vec2 q = floor(v_world.xz / u_checker);
        albedo *= mix(0.80, 1.0, mod(q.x + q.y, 2.0));
        // soft contact darkening around the tank
        vec2 d = max(max(u_tank_min.xz - v_world.xz, v_world.xz - u_tank_max.xz), 0.0);
        albedo *= mix(0.55, 1.0, smoothstep(0.0, 2.5 * u_tile, length(d)));
    } else if (v_pattern == 2) {
        vec2 t = uv / u_tile;
        vec2 f = fract(t);
        float g = min(min(f.x, 1.0 - f.x), min(f.y, 1.0 - f.y));
        albedo *= mix(0.62, 1.0, smoothstep(0.03, 0.07, g)) * mix(0.93, 1.04, hash(floor(t)));
        // darker towards the tank bottom (ambient occlusion of a deep pool)
        float h = (v_world.y - u_tank_min.y) / max(u_tank_max.y - u_tank_min.y, 1e-3);
        albedo *= mix(0.72, 1.0, smoothstep(0.0, 0.6, h));
        spec_strength = 0.25; shininess = 60.0;
    } else if (v_pattern == 3) {
        float plank = 0.25 * u_tile * 2.0;
        float f = fract(uv.y / plank);
        float seam = min(f, 1.0 - f);
        albedo *= mix(0.55, 1.0, smoothstep(0.02, 0.08, seam)) * mix(0.88, 1.06, hash(vec2(floor(uv.y / plank), n.x + 2.0 * n.z)));
        albedo *= 0.92 + 0.08 * sin(uv.x * 90.0 + sin(uv.y * 23.0) * 3.0);
    } else if (v_pattern == 4) {
        spec_strength = 0.6; shininess = 40.0;
    }
    vec3 c = sun_lit(albedo, n, v_world, spec_strength, shininess);
    vec2 centre = 0.5 * (u_tank_min.xz + u_tank_max.xz);
    float fog = smoothstep(u_fog.x, u_fog.y, length(v_world.xz - centre));
    o_color = vec4(mix(c, u_fog_color, fog), 1.0);
}
)";

// Sky: a full-screen triangle; the view ray comes from the inverse view rotation and the
// tangents of the half field of view, so it works with any projection depth convention.
const char* kSkyVS = R"(#version 430 core
out vec2 v_ndc;
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
    v_ndc = p;
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

const char* kSkyFS = R"(#version 430 core
in vec2 v_ndc;
uniform mat3 u_inv_view_rot;
uniform vec2 u_tan;          // tan(fov_x / 2), tan(fov_y / 2)
uniform vec3 u_sun;
uniform vec3 u_horizon;
layout(location = 0) out vec4 o_color;
void main() {
    vec3 dir = normalize(u_inv_view_rot * vec3(v_ndc * u_tan, -1.0));
    vec3 zenith = vec3(0.22, 0.42, 0.76);
    vec3 ground = vec3(0.40, 0.39, 0.37);
    vec3 c;
    if (dir.y >= 0.0) c = mix(u_horizon, zenith, pow(dir.y, 0.55));
    else c = mix(u_horizon, ground, smoothstep(0.0, 0.25, -dir.y));
    float s = max(dot(dir, u_sun), 0.0);
    c += vec3(1.0, 0.92, 0.75) * (6.0 * pow(s, 1500.0) + 0.25 * pow(s, 16.0));
    o_color = vec4(c, 1.0);
}
)";

const glm::vec3 kHorizon(0.80, 0.87, 0.95);

// ---- geometry -------------------------------------------------------------------------------

struct Vertex {
    float p[3], n[3], c[3], pattern;
};

struct Mesh {
    std::vector<Vertex> v;

    // One quad: centre c, normal n, half-axes u, w with u x w along n (CCW seen from n's side).
    void quad(glm::vec3 c, glm::vec3 n, glm::vec3 u, glm::vec3 w, glm::vec3 color, int pattern) {
        const glm::vec3 q[4] = {c - u - w, c + u - w, c + u + w, c - u + w};
        const int idx[6] = {0, 1, 2, 0, 2, 3};
        for (int i : idx) {
            Vertex x{};
            for (int a = 0; a < 3; ++a) {
                x.p[a] = q[i][a];
                x.n[a] = n[a];
                x.c[a] = color[a];
            }
            x.pattern = float(pattern);
            v.push_back(x);
        }
    }

    // Axis-aligned box. inward: faces point inside (visible from within; with back-face
    // culling only the far walls show from outside). skip_top leaves the +y face out.
    void box(glm::vec3 lo, glm::vec3 hi, glm::vec3 color, int pattern, bool inward = false, bool skip_top = false) {
        const glm::vec3 c = 0.5f * (lo + hi), h = 0.5f * (hi - lo);
        const glm::vec3 ex(h.x, 0, 0), ey(0, h.y, 0), ez(0, 0, h.z);
        struct F {
            glm::vec3 n, u, w, off;
        };
        // u x w = n for each (y x z = x, z x x = y, x x y = z).
        const F faces[6] = {
            {{1, 0, 0}, ey, ez, ex},   {{-1, 0, 0}, ez, ey, -ex},
            {{0, 1, 0}, ez, ex, ey},   {{0, -1, 0}, ex, ez, -ey},
            {{0, 0, 1}, ex, ey, ez},   {{0, 0, -1}, ey, ex, -ez},
        };
        for (int i = 0; i < 6; ++i) {
            if (skip_top && i == 2) continue;
            const F& f = faces[i];
            if (inward)
                quad(c + f.off, -f.n, f.w, f.u, color, pattern);
            else
                quad(c + f.off, f.n, f.u, f.w, color, pattern);
        }
    }
};

} // namespace

World::World(const Scene& scene, GLADloadfunc get_proc) {
    clip_control_ = load_clip_control(get_proc);
    lit_prog_ = link_program(kLitVS, with_sun_light(kLitFS).c_str(), "world shader");
    sky_prog_ = link_program(kSkyVS, kSkyFS, "sky shader");
    glGenVertexArrays(1, &empty_vao_);
    obstacle_renderer_ = std::make_unique<ObstacleRenderer>();
    build_geometry(scene);
    glGenFramebuffers(1, &fbo_);
    glGenTextures(1, &sky_cube_);
    glBindTexture(GL_TEXTURE_CUBE_MAP, sky_cube_);
    glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_RGBA8, 128, 128);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    check_gl("World setup");
}

World::~World() {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteTextures(1, &color_tex_);
    glDeleteTextures(1, &depth_tex_);
    glDeleteTextures(1, &sky_cube_);
    glDeleteProgram(lit_prog_);
    glDeleteProgram(sky_prog_);
    glDeleteVertexArrays(1, &vao_);
    glDeleteVertexArrays(1, &empty_vao_);
    glDeleteBuffers(1, &vbo_);
}

void World::build_geometry(const Scene& scene) {
    const vec3f lo3 = scene.domain_min(), hi3 = scene.domain_max();
    const glm::vec3 lo(lo3[0], lo3[1], lo3[2]), hi(hi3[0], hi3[1], hi3[2]);
    tank_min_ = lo;
    tank_max_ = hi;
    const glm::vec3 ext = hi - lo;
    const float m = std::max({ext.x, ext.y, ext.z});
    tile_ = m / 12.0f;
    checker_ = m / 5.0f;
    fog_start_ = 2.0f * m;
    fog_end_ = 6.0f * m;

    Mesh mesh;
    // Floor just below the tank bottom.
    const glm::vec3 c = 0.5f * (lo + hi);
    const float fy = lo.y - 0.002f * ext.y, fr = 6.5f * m;
    mesh.quad(glm::vec3(c.x, fy, c.z), glm::vec3(0, 1, 0), glm::vec3(0, 0, fr), glm::vec3(fr, 0, 0),
              glm::vec3(0.70f, 0.67f, 0.62f), 1);
    // Tank inside: far walls and bottom, tiled.
    mesh.box(lo, hi, glm::vec3(0.80f, 0.90f, 0.93f), 2, /*inward=*/true, /*skip_top=*/true);
    // Low rims all around (outside the domain), tiled darker.
    const float t = 0.025f * m, rim = lo.y + 0.12f * ext.y;
    const glm::vec3 rim_color(0.36f, 0.52f, 0.62f);
    // Their inner faces sit a hair outside the tank walls (no z-fighting with the inside).
    const float e = 1e-3f * m;
    mesh.box({lo.x - t, lo.y, lo.z - t}, {lo.x - e, rim, hi.z + t}, rim_color, 2);
    mesh.box({hi.x + e, lo.y, lo.z - t}, {hi.x + t, rim, hi.z + t}, rim_color, 2);
    mesh.box({lo.x - e, lo.y, lo.z - t}, {hi.x + e, rim, lo.z - e}, rim_color, 2);
    mesh.box({lo.x - e, lo.y, hi.z + e}, {hi.x + e, rim, hi.z + t}, rim_color, 2);
    // Corner posts and top bars (a frame for glass that is not drawn).
    const float pw = 0.45f * t; // not quite t / 2: no face coplanar with the tank walls
    const glm::vec3 metal(0.22f, 0.24f, 0.27f);
    const float xs[2] = {lo.x - 0.5f * t, hi.x + 0.5f * t}, zs[2] = {lo.z - 0.5f * t, hi.z + 0.5f * t};
    for (float x : xs)
        for (float z : zs) mesh.box({x - pw, lo.y, z - pw}, {x + pw, hi.y + pw, z + pw}, metal, 4);
    for (float z : zs) mesh.box({xs[0] - pw, hi.y - pw, z - pw}, {xs[1] + pw, hi.y + pw, z + pw}, metal, 4);
    for (float x : xs) mesh.box({x - pw, hi.y - pw, zs[0] - pw}, {x + pw, hi.y + pw, zs[1] + pw}, metal, 4);
    // Crates in front of the tank (+z side), partly hiding it from the default cameras.
    const float s = 0.3f * ext.y;
    const float cx = lo.x + 0.62f * ext.x, cz = hi.z + t + 0.12f * m + 0.5f * s;
    const glm::vec3 wood(0.66f, 0.47f, 0.29f);
    mesh.box({cx - 0.5f * s, lo.y, cz - 0.5f * s}, {cx + 0.5f * s, lo.y + s, cz + 0.5f * s}, wood, 3);
    const float s2 = 0.6f * s;
    mesh.box({cx + 0.5f * s + 0.1f * s, lo.y, cz - 0.2f * s}, {cx + 0.5f * s + 0.1f * s + s2, lo.y + s2, cz - 0.2f * s + s2},
             wood * 0.9f, 3);

    vertex_count_ = GLsizei(mesh.v.size());
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.v.size() * sizeof(Vertex)), mesh.v.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, p)));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, n)));
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, c)));
    glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, pattern)));
    for (GLuint i = 0; i < 4; ++i) glEnableVertexAttribArray(i);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void World::resize(int width, int height) {
    if (width == width_ && height == height_ && color_tex_) return;
    if (width < 1 || height < 1) throw Error("World::resize: empty size");
    glDeleteTextures(1, &color_tex_);
    glDeleteTextures(1, &depth_tex_);
    glGenTextures(1, &color_tex_);
    glGenTextures(1, &depth_tex_);
    glBindTexture(GL_TEXTURE_2D, color_tex_);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width, height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    // 32-bit float depth: what reversed-Z needs; fine for the standard convention too.
    glBindTexture(GL_TEXTURE_2D, depth_tex_);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, width, height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_tex_, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_tex_, 0);
    check_framebuffer("world framebuffer");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    width_ = width;
    height_ = height;
    check_gl("World::resize");
}

void World::set_sun(const glm::vec3& towards_sun) {
    const glm::vec3 s = glm::length(towards_sun) > 0 ? glm::normalize(towards_sun) : glm::vec3(0, 1, 0);
    if (s != sun_) sky_dirty_ = true;
    sun_ = s;
}

void World::draw_sky(const glm::mat3& inv_view_rot, float tan_x, float tan_y) {
    glUseProgram(sky_prog_);
    glUniformMatrix3fv(glGetUniformLocation(sky_prog_, "u_inv_view_rot"), 1, GL_FALSE, glm::value_ptr(inv_view_rot));
    glUniform2f(glGetUniformLocation(sky_prog_, "u_tan"), tan_x, tan_y);
    glUniform3fv(glGetUniformLocation(sky_prog_, "u_sun"), 1, glm::value_ptr(sun_));
    glUniform3fv(glGetUniformLocation(sky_prog_, "u_horizon"), 1, glm::value_ptr(kHorizon));
    glBindVertexArray(empty_vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void World::build_sky_cubemap() {
    // The usual cube-map face orientations (GL spec table 8.19): right-handed lookAt per face.
    static const glm::vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, 128, 128);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    for (int f = 0; f < 6; ++f) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), sky_cube_, 0);
        const glm::mat3 rot(glm::lookAt(glm::vec3(0), dirs[f], ups[f]));
        draw_sky(glm::transpose(rot), 1.0f, 1.0f);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    sky_dirty_ = false;
    check_gl("World sky cube map");
}

void World::draw(const OrbitCamera& cam) {
    if (!color_tex_) throw Error("World::draw before resize");
    if (sky_dirty_) build_sky_cubemap();

    if (cam.zero_to_one()) {
        if (!clip_control_) throw Error("depth convention " + std::string(depth_convention_name(cam.depth)) +
                                        " needs glClipControl (GL 4.5 or ARB_clip_control)");
        clip_control_(kGL_LOWER_LEFT, kGL_ZERO_TO_ONE);
        clip_changed_ = true;
    }

    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, width_, height_);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glClearDepth(cam.clear_depth());
    glClear(GL_DEPTH_BUFFER_BIT);

    const float aspect = float(width_) / float(height_);
    const glm::mat4 view = cam.view();
    const glm::mat4 vp = cam.proj(aspect) * view;
    const float ty = std::tan(0.5f * glm::radians(cam.fov_deg));

    // Sky: covers every pixel, no depth.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    draw_sky(glm::transpose(glm::mat3(view)), ty * aspect, ty);

    // Geometry.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(cam.greater_is_nearer() ? GL_GREATER : GL_LESS);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glUseProgram(lit_prog_);
    glUniformMatrix4fv(glGetUniformLocation(lit_prog_, "u_view_proj"), 1, GL_FALSE, glm::value_ptr(vp));
    glUniform3fv(glGetUniformLocation(lit_prog_, "u_sun"), 1, glm::value_ptr(sun_));
    const glm::vec3 eye = cam.eye();
    glUniform3fv(glGetUniformLocation(lit_prog_, "u_eye"), 1, glm::value_ptr(eye));
    glUniform3fv(glGetUniformLocation(lit_prog_, "u_tank_min"), 1, glm::value_ptr(tank_min_));
    glUniform3fv(glGetUniformLocation(lit_prog_, "u_tank_max"), 1, glm::value_ptr(tank_max_));
    glUniform1f(glGetUniformLocation(lit_prog_, "u_tile"), tile_);
    glUniform1f(glGetUniformLocation(lit_prog_, "u_checker"), checker_);
    glUniform2f(glGetUniformLocation(lit_prog_, "u_fog"), fog_start_, fog_end_);
    glUniform3fv(glGetUniformLocation(lit_prog_, "u_fog_color"), 1, glm::value_ptr(kHorizon));
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
    glBindVertexArray(0);
    glUseProgram(0);

    ObstacleView obstacle_view;
    obstacle_view.view_proj = vp;
    obstacle_view.eye = eye;
    obstacle_view.sun = sun_;
    obstacle_view.zero_to_one = cam.zero_to_one();
    obstacle_renderer_->draw(obstacles_, obstacle_view);

    glDisable(GL_CULL_FACE);
    glDepthFunc(GL_LESS);
    check_gl("World::draw");
}

void World::end_frame() {
    if (clip_changed_ && clip_control_) clip_control_(kGL_LOWER_LEFT, kGL_NEGATIVE_ONE_TO_ONE);
    clip_changed_ = false;
    glClearDepth(1.0);
}

void World::fit_clip_planes(OrbitCamera& camera) const {
    const glm::vec3 ext = tank_max_ - tank_min_;
    const float m = std::max({ext.x, ext.y, ext.z});
    camera.near_plane = std::max(0.005f * m, 1e-3f);
    camera.far_plane = camera.distance + 9.0f * m;
}

pf_render_target World::render_target(bool use_sky_cubemap) const {
    pf_render_target t{};
    t.framebuffer = fbo_;
    t.scene_color = color_tex_;
    t.scene_depth = depth_tex_;
    t.environment_cubemap = use_sky_cubemap ? sky_cube_ : 0;
    return t;
}

pf_result draw_frame(World& world, pf_sim* sim, const OrbitCamera& camera, const LiquidLook& look) {
    world.draw(camera);
    const pf_camera cam = camera.to_pf(0, 0, world.width(), world.height());
    const pf_render_target target = world.render_target(look.sky_cubemap);
    const pf_result r = look.ssf ? pf_render_ssf(sim, &cam, &target, &look.ssf_params)
                                 : pf_render_particles(sim, &cam, &target, &look.particle_params);
    world.end_frame();
    return r;
}

std::string flag_names(uint32_t flags) {
    std::string s;
    auto add = [&](uint32_t bit, const char* name) {
        if (flags & bit) s += std::string(s.empty() ? "" : " ") + name;
    };
    add(PF_FLAG_P2G_OVERFLOW, "P2G_OVERFLOW");
    add(PF_FLAG_NONFINITE, "NONFINITE");
    add(PF_FLAG_SPEED_CLAMPED, "SPEED_CLAMPED");
    add(PF_FLAG_SUBSTEPS_CLAMPED, "SUBSTEPS_CLAMPED");
    add(PF_FLAG_VOLUME_LOST, "VOLUME_LOST");
    add(PF_FLAG_ENERGY_GAINED, "ENERGY_GAINED");
    add(PF_FLAG_EMITTERS_FULL, "EMITTERS_FULL");
    add(PF_FLAG_WHITEWATER_FULL, "WHITEWATER_FULL");
    add(PF_FLAG_BUDGET_LIMITED, "BUDGET_LIMITED");
    return s.empty() ? "none" : s;
}

} // namespace pfs
