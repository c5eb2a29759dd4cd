#include "obstacle_renderer.h"
#include "sun_light_glsl.h"

#include "gl_util.h"
#include "obstacle_shapes.h"

#include <glm/gtc/type_ptr.hpp>

namespace pfs {

namespace {

// The obstacle's local box [-u_bounds, u_bounds] from 36 vertex ids: face f = id / 6 lies on
// axis f / 2 at sign (+ for even f); its two triangles wind counter-clockwise seen from outside
// (a mirrored face swaps its u, v to keep that).
const char* kObstacleVS = R"(#version 430 core
uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform vec3 u_bounds;
out vec3 v_local;
const vec2 kCorner[6] = vec2[6](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
void main() {
    int face = gl_VertexID / 6;
    int axis = face / 2;
    float side = (face % 2 == 0) ? 1.0 : -1.0;
    vec2 uv = kCorner[gl_VertexID % 6];
    if (side < 0.0) uv = uv.yx;
    vec3 p;
    p[axis] = side;
    p[(axis + 1) % 3] = uv.x;
    p[(axis + 2) % 3] = uv.y;
    v_local = p * u_bounds;
    gl_Position = u_view_proj * (u_model * vec4(v_local, 1.0));
}
)";

// Shapes: 0 box, 1 sphere, 2 capsule, 3 SDF texture (pf_obstacle_shape).
const char* kObstacleFS = R"(#version 430 core
in vec3 v_local;
uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform vec3 u_eye_local;     // the eye in the obstacle's frame
uniform vec3 u_bounds;        // half sizes of the local box around the shape
uniform int u_shape;
uniform vec3 u_size;          // box / SDF: half extents; sphere / capsule: (radius, half height, 0)
uniform float u_sdf_scale;    // metres per texture unit
uniform bool u_sdf_normalized;
uniform vec3 u_sun;
uniform vec3 u_eye;
uniform vec3 u_color;
uniform bool u_zero_to_one;
layout(binding = 0) uniform sampler3D u_sdf;
layout(location = 0) out vec4 o_color;

#pragma sun_light

// The library's signed distances (shaders/effects/obstacles/obstacle_sdf.glsl), local frame.
float shape_distance(vec3 p) {
    if (u_shape == 3) {
        vec3 q = clamp(p, -u_size, u_size);
        float t = textureLod(u_sdf, q / (2.0 * u_size) + 0.5, 0.0).r;
        if (u_sdf_normalized) t = 2.0 * t - 1.0;
        return t * u_sdf_scale + length(p - q);
    }
    if (u_shape == 0) {
        vec3 q = abs(p) - u_size;
        return length(max(q, vec3(0.0))) + min(max(q.x, max(q.y, q.z)), 0.0);
    }
    if (u_shape == 2) p.y -= clamp(p.y, -u_size.y, u_size.y);
    return length(p) - u_size.x;
}

vec3 shape_normal(vec3 p, float h) {
    vec2 e = vec2(h, 0.0);
    return normalize(vec3(shape_distance(p + e.xyy) - shape_distance(p - e.xyy),
                          shape_distance(p + e.yxy) - shape_distance(p - e.yxy),
                          shape_distance(p + e.yyx) - shape_distance(p - e.yyx)));
}

void main() {
    vec3 dir = normalize(v_local - u_eye_local);
    // The ray's span inside the local box (from the eye when the eye is inside).
    vec3 inv = 1.0 / dir;
    vec3 ta = (-u_bounds - u_eye_local) * inv, tb = (u_bounds - u_eye_local) * inv;
    vec3 tmin = min(ta, tb), tmax = max(ta, tb);
    float t = max(max(tmin.x, max(tmin.y, tmin.z)), 0.0);
    float t_exit = min(tmax.x, min(tmax.y, tmax.z));
    float size = max(u_bounds.x, max(u_bounds.y, u_bounds.z));
    float eps = 1e-3 * size;
    // A texture's distances are exact only at its texels: shorter steps never tunnel through.
    float step_scale = u_shape == 3 ? 0.8 : 1.0;
    bool hit = false;
    for (int i = 0; i < 160 && t <= t_exit + eps; ++i) {
        float d = shape_distance(u_eye_local + t * dir);
        if (d < eps) {
            hit = true;
            break;
        }
        t += step_scale * d;
    }
    if (!hit) discard;
    vec3 p = u_eye_local + t * dir;
    float h = eps;
    if (u_shape == 3) h = max(h, 0.5 * 2.0 * u_size.x / float(textureSize(u_sdf, 0).x));
    vec3 n = normalize(mat3(u_model) * shape_normal(p, h));
    vec3 world = (u_model * vec4(p, 1.0)).xyz;

    o_color = vec4(sun_lit(u_color, n, world, 0.3, 40.0), 1.0);

    vec4 clip = u_view_proj * vec4(world, 1.0);
    float z = clip.z / clip.w;
    gl_FragDepth = u_zero_to_one ? z : 0.5 * z + 0.5;
}
)";

// One colour per shape, so each reads at a glance (and none looks like the tank's tiles).
glm::vec3 shape_color(pf_obstacle_shape shape) {
    switch (shape) {
    case PF_OBSTACLE_BOX: return {0.72f, 0.50f, 0.30f};
    case PF_OBSTACLE_SPHERE: return {0.80f, 0.30f, 0.25f};
    case PF_OBSTACLE_CAPSULE: return {0.35f, 0.45f, 0.70f};
    default: return {0.40f, 0.65f, 0.35f};
    }
}

/// Local size parameters as the fragment shader reads them (u_size).
glm::vec3 shape_size(const pf_obstacle& o) {
    if (o.shape == PF_OBSTACLE_SPHERE || o.shape == PF_OBSTACLE_CAPSULE) return {o.radius, o.half_height, 0.0f};
    return {o.half_extents[0], o.half_extents[1], o.half_extents[2]};
}

/// Whether the SDF texture's format stores 2 distance - 1 (GL_R8 / GL_R16), as the library reads it.
bool sdf_texture_normalized(GLuint texture) {
    GLint format = 0;
    glBindTexture(GL_TEXTURE_3D, texture);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    return format == GL_R8 || format == GL_R16;
}

} // namespace

ObstacleRenderer::ObstacleRenderer() {
    program_ = link_program(kObstacleVS, with_sun_light(kObstacleFS).c_str(), "obstacle shader");
    glGenVertexArrays(1, &vao_);
    glGenSamplers(1, &sampler_);
    glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glSamplerParameteri(sampler_, wrap, GL_CLAMP_TO_EDGE);
    check_gl("ObstacleRenderer setup");
}

ObstacleRenderer::~ObstacleRenderer() {
    glDeleteProgram(program_);
    glDeleteVertexArrays(1, &vao_);
    glDeleteSamplers(1, &sampler_);
}

void ObstacleRenderer::draw(const std::vector<pf_obstacle>& obstacles, const ObstacleView& view) const {
    if (obstacles.empty()) return;
    glUseProgram(program_);
    glUniformMatrix4fv(glGetUniformLocation(program_, "u_view_proj"), 1, GL_FALSE, glm::value_ptr(view.view_proj));
    glUniform3fv(glGetUniformLocation(program_, "u_sun"), 1, glm::value_ptr(view.sun));
    glUniform3fv(glGetUniformLocation(program_, "u_eye"), 1, glm::value_ptr(view.eye));
    glUniform1i(glGetUniformLocation(program_, "u_zero_to_one"), view.zero_to_one ? 1 : 0);
    glBindVertexArray(vao_);
    // Back faces: the box is rasterised even with the eye inside it; the ray starts at the eye.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glFrontFace(GL_CCW);
    bool sdf_bound = false;
    for (const pf_obstacle& o : obstacles) {
        draw_one(o, view);
        sdf_bound = sdf_bound || o.shape == PF_OBSTACLE_SDF;
    }
    glCullFace(GL_BACK);
    glDisable(GL_CULL_FACE);
    if (sdf_bound) { // unit 0 as it was: the engine's texture unbound, no sampler object
        glBindSampler(0, 0);
        glBindTexture(GL_TEXTURE_3D, 0);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    check_gl("ObstacleRenderer::draw");
}

void ObstacleRenderer::bind_sdf_texture(const pf_obstacle& o) const {
    glActiveTexture(GL_TEXTURE0);
    const bool normalized = sdf_texture_normalized(o.sdf_texture);
    glBindTexture(GL_TEXTURE_3D, o.sdf_texture);
    glBindSampler(0, sampler_);
    glUniform1i(glGetUniformLocation(program_, "u_sdf_normalized"), normalized ? 1 : 0);
    glUniform1f(glGetUniformLocation(program_, "u_sdf_scale"), o.sdf_scale);
}

void ObstacleRenderer::draw_one(const pf_obstacle& o, const ObstacleView& view) const {
    const glm::mat4 model = obstacle_model_matrix(o);
    const glm::vec3 eye_local = glm::vec3(glm::inverse(model) * glm::vec4(view.eye, 1.0f));
    const glm::vec3 bounds = obstacle_local_bounds(o), size = shape_size(o), color = shape_color(o.shape);
    glUniformMatrix4fv(glGetUniformLocation(program_, "u_model"), 1, GL_FALSE, glm::value_ptr(model));
    glUniform3fv(glGetUniformLocation(program_, "u_eye_local"), 1, glm::value_ptr(eye_local));
    glUniform3fv(glGetUniformLocation(program_, "u_bounds"), 1, glm::value_ptr(bounds));
    glUniform3fv(glGetUniformLocation(program_, "u_size"), 1, glm::value_ptr(size));
    glUniform3fv(glGetUniformLocation(program_, "u_color"), 1, glm::value_ptr(color));
    glUniform1i(glGetUniformLocation(program_, "u_shape"), int(o.shape));
    if (o.shape == PF_OBSTACLE_SDF) bind_sdf_texture(o);
    glDrawArrays(GL_TRIANGLES, 0, 36);
}

} // namespace pfs
