#include "support/render_scene.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace pf::test {

EngineTarget::EngineTarget(int w, int h, GLenum color_format, bool with_depth) : width(w), height(h) {
    glGenTextures(1, &color);
    glBindTexture(GL_TEXTURE_2D, color);
    glTexStorage2D(GL_TEXTURE_2D, 1, color_format, w, h);
    if (with_depth) {
        glGenTextures(1, &depth);
        glBindTexture(GL_TEXTURE_2D, depth);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, w, h);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    GLint previous = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    if (with_depth) glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previous));
}

EngineTarget::~EngineTarget() {
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &color);
    if (depth) glDeleteTextures(1, &depth);
}

void EngineTarget::write_color(const std::vector<float>& rgba) {
    glBindTexture(GL_TEXTURE_2D, color);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

void EngineTarget::write_depth(const std::vector<float>& d) {
    glBindTexture(GL_TEXTURE_2D, depth);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, d.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

std::vector<float> EngineTarget::read_color() const {
    std::vector<float> out(size_t(width) * height * 4);
    glFinish();
    glBindTexture(GL_TEXTURE_2D, color);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    return out;
}

std::vector<float> EngineTarget::read_depth() const {
    std::vector<float> out(size_t(width) * height);
    glBindTexture(GL_TEXTURE_2D, depth);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, out.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    return out;
}

TestCamera make_camera(glm::dvec3 eye, glm::dvec3 at, double fovy_deg, const int viewport[4], double n, double f,
                       pf_depth_convention convention) {
    TestCamera c;
    c.view = glm::lookAt(eye, at, glm::dvec3(0, 1, 0));
    const double aspect = double(viewport[2]) / viewport[3], fovy = glm::radians(fovy_deg);
    switch (convention) {
        case PF_DEPTH_STANDARD: c.proj = glm::perspectiveNO(fovy, aspect, n, f); break;
        case PF_DEPTH_ZERO_TO_ONE: c.proj = glm::perspectiveZO(fovy, aspect, n, f); break;
        default: c.proj = glm::perspectiveZO(fovy, aspect, f, n); break;  // swapped planes: near -> 1, far -> 0
    }
    for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) {
            c.cam.view[col * 4 + row] = float(c.view[col][row]);
            c.cam.proj[col * 4 + row] = float(c.proj[col][row]);
        }
    }
    for (int i = 0; i < 4; ++i) c.cam.viewport[i] = viewport[i];
    c.cam.near_plane = float(n);
    c.cam.far_plane = float(f);
    c.cam.depth_convention = convention;
    return c;
}

namespace {
double ndc_to_window(pf_depth_convention conv, double z) { return conv == PF_DEPTH_STANDARD ? 0.5 * z + 0.5 : z; }
double window_to_ndc(pf_depth_convention conv, double w) { return conv == PF_DEPTH_STANDARD ? 2.0 * w - 1.0 : w; }

glm::dvec2 pixel_ndc(const TestCamera& c, double px, double py) {
    const int* vp = c.cam.viewport;
    return {(px - vp[0]) / vp[2] * 2.0 - 1.0, (py - vp[1]) / vp[3] * 2.0 - 1.0};
}

// Unit direction (eye space) of the ray through target pixel centre (x, y).
glm::dvec3 pixel_ray(const TestCamera& c, int x, int y) {
    const glm::dvec2 ndc = pixel_ndc(c, x + 0.5, y + 0.5);
    const glm::dvec4 h = glm::inverse(c.proj) * glm::dvec4(ndc, window_to_ndc(c.cam.depth_convention, 0.5), 1.0);
    return glm::normalize(glm::dvec3(h) / h.w);
}
}  // namespace

double window_depth_of(const TestCamera& c, const glm::dvec3& p) {
    const glm::dvec4 clip = c.proj * glm::dvec4(p, 1.0);
    return ndc_to_window(c.cam.depth_convention, clip.z / clip.w);
}

double eye_depth_of(const TestCamera& c, double px, double py, double window) {
    const glm::dvec4 h =
        glm::inverse(c.proj) * glm::dvec4(pixel_ndc(c, px, py), window_to_ndc(c.cam.depth_convention, window), 1.0);
    return -h.z / h.w;
}

double window_depth_at(const TestCamera& c, int x, int y, double depth) {
    const glm::dvec3 d = pixel_ray(c, x, y);
    return window_depth_of(c, d * (depth / -d.z));
}

double far_window_depth(pf_depth_convention convention) { return convention == PF_DEPTH_REVERSED_Z ? 0.0 : 1.0; }

SphereCoverage project_spheres(const TestCamera& c, int tw, int th, const std::vector<float>& xyz, double r,
                               double margin) {
    SphereCoverage s;
    s.depth.assign(size_t(tw) * th, 0.0);
    s.ambiguous.assign(size_t(tw) * th, 0);
    const int* vp = c.cam.viewport;
    std::vector<glm::dvec3> centers;
    for (size_t i = 0; i + 2 < xyz.size(); i += 3) centers.push_back(glm::dvec3(c.view * glm::dvec4(xyz[i], xyz[i + 1], xyz[i + 2], 1.0)));
    for (int y = vp[1]; y < vp[1] + vp[3] && y < th; ++y) {
        for (int x = vp[0]; x < vp[0] + vp[2] && x < tw; ++x) {
            const glm::dvec3 d = pixel_ray(c, x, y);
            double best = 0.0;
            bool ambiguous = false;
            for (const glm::dvec3& ctr : centers) {
                const double tc = glm::dot(ctr, d);
                const double dist = glm::length(ctr - tc * d);
                if (std::fabs(dist - r) < margin * r) ambiguous = true;
                if (dist >= r) continue;
                const double t0 = tc - std::sqrt(r * r - dist * dist);
                const double depth = -t0 * d.z;
                if (depth < c.cam.near_plane || depth > c.cam.far_plane) continue;
                if (best == 0.0 || depth < best) best = depth;
            }
            const size_t i = size_t(y) * tw + x;
            s.depth[i] = best;
            s.ambiguous[i] = ambiguous;
            s.covered += best > 0.0;
        }
    }
    return s;
}

std::vector<float> checkerboard(int w, int h, int cell) {
    std::vector<float> out(size_t(w) * h * 4);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const bool odd = ((x / cell) + (y / cell)) % 2;
            float* p = &out[(size_t(y) * w + x) * 4];
            p[0] = odd ? 0.9f : 0.2f;
            p[1] = odd ? 0.8f : 0.3f + 0.4f * float(y) / float(h);
            p[2] = odd ? 0.3f : 0.6f;
            p[3] = 1.0f;
        }
    }
    return out;
}

}  // namespace pf::test
