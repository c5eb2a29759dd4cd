#include "surface_metric.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace pfs {

pf_sim_desc pool_desc(uint32_t cells, float box) {
    pf_sim_desc d = pf_default_sim_desc();
    for (int a = 0; a < 3; ++a) d.grid_size[a] = cells;
    d.cell_size = box / float(cells);
    d.max_particles = cells * cells * cells * 8;
    return d;
}

namespace {

// A perspective camera at `eye` looking at `at`, standard depth convention, near 0.1 m, far 10 m.
pf_camera look_at_camera(glm::dvec3 eye, glm::dvec3 at, double fovy_deg, int width, int height, glm::dmat4& view,
                         glm::dmat4& proj) {
    const double near_plane = 0.1, far_plane = 10.0;
    view = glm::lookAt(eye, at, glm::dvec3(0.0, 1.0, 0.0));
    proj = glm::perspectiveNO(glm::radians(fovy_deg), double(width) / height, near_plane, far_plane);
    pf_camera c{};
    for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) {
            c.view[col * 4 + row] = float(view[col][row]);
            c.proj[col * 4 + row] = float(proj[col][row]);
        }
    }
    c.viewport[2] = width;
    c.viewport[3] = height;
    c.near_plane = float(near_plane);
    c.far_plane = float(far_plane);
    c.depth_convention = PF_DEPTH_STANDARD;
    return c;
}

}  // namespace

pf_camera pool_camera(float box, int width, int height, glm::dmat4& view, glm::dmat4& proj) {
    const glm::dvec3 at(0.5 * box, kPoolDepth * box, 0.5 * box);
    return look_at_camera(at + glm::dvec3(0.0, 1.0, 1.0), at, 30.0, width, height, view, proj);
}

pf_sim_desc dam_break_desc(uint32_t cells) {
    pf_sim_desc d = pf_default_sim_desc();
    d.grid_size[0] = cells;
    d.grid_size[1] = d.grid_size[2] = cells / 2;
    d.cell_size = 2.0f / float(cells);
    d.max_particles = cells * (cells / 2) * (cells / 2) * 8 / 2;  // the column is under half the tank
    return d;
}

pf_camera dam_break_camera(int width, int height, glm::dmat4& view, glm::dmat4& proj) {
    return look_at_camera({1.4, 1.3, 2.6}, {0.6, 0.2, 0.5}, 40.0, width, height, view, proj);
}

namespace {

// World-space normals of the measured pixels (those whose (2 border + 1)^2 neighbourhood is all
// liquid), formed as the shading forms them; unmeasured pixels hold (0, 0, 0).
std::vector<glm::dvec3> surface_normals(const std::vector<float>& window_depth, const std::vector<uint8_t>& liquid,
                                        int width, int height, const glm::dmat4& view, const glm::dmat4& proj,
                                        pf_depth_convention convention, int border) {
    const glm::dmat4 inv_proj = glm::inverse(proj);
    const glm::dmat3 eye_to_world = glm::transpose(glm::dmat3(view));  // view is rigid
    const bool orthographic = proj[3][3] == 1.0;
    auto at = [&](int x, int y) { return size_t(y) * size_t(width) + size_t(x); };
    auto eye = [&](int x, int y) {
        const double d = window_depth[at(x, y)];
        const double z = convention == PF_DEPTH_STANDARD ? 2.0 * d - 1.0 : d;
        const glm::dvec4 p = inv_proj * glm::dvec4(2.0 * (x + 0.5) / width - 1.0, 2.0 * (y + 0.5) / height - 1.0, z, 1.0);
        return glm::dvec3(p) / p.w;
    };
    // The tangent along (dx, dy), as the shading picks it: the one-sided difference with the
    // smaller depth step (every neighbour is liquid here).
    auto tangent = [&](int x, int y, int dx, int dy) {
        const glm::dvec3 c = eye(x, y), ahead = eye(x + dx, y + dy), back = eye(x - dx, y - dy);
        return std::fabs(ahead.z - c.z) <= std::fabs(c.z - back.z) ? ahead - c : c - back;
    };
    std::vector<glm::dvec3> normals(size_t(width) * size_t(height), glm::dvec3(0.0));
    for (int y = border; y < height - border; ++y) {
        for (int x = border; x < width - border; ++x) {
            bool inside = true;
            for (int dy = -border; dy <= border && inside; ++dy)
                for (int dx = -border; dx <= border && inside; ++dx) inside = liquid[at(x + dx, y + dy)] != 0;
            if (!inside) continue;
            glm::dvec3 n = glm::normalize(glm::cross(tangent(x, y, 1, 0), tangent(x, y, 0, 1)));
            const glm::dvec3 to_camera = orthographic ? glm::dvec3(0.0, 0.0, 1.0) : -eye(x, y);
            if (glm::dot(n, to_camera) < 0.0) n = -n;
            normals[at(x, y)] = glm::normalize(eye_to_world * n);
        }
    }
    return normals;
}

// RMS and 95th percentile of angles in degrees.
NormalError summarize(std::vector<double>& angles) {
    NormalError e;
    e.pixels = int(angles.size());
    if (angles.empty()) return e;
    double sum = 0.0;
    for (double a : angles) sum += a * a;
    e.rms_deg = std::sqrt(sum / double(angles.size()));
    const size_t k = std::min(angles.size() - 1, size_t(0.95 * double(angles.size())));
    std::nth_element(angles.begin(), angles.begin() + std::ptrdiff_t(k), angles.end());
    e.p95_deg = angles[k];
    return e;
}

double angle_deg(const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace

NormalError normal_error(const std::vector<float>& window_depth, const std::vector<uint8_t>& liquid, int width,
                         int height, const glm::dmat4& view, const glm::dmat4& proj, pf_depth_convention convention,
                         glm::dvec3 true_normal, int border) {
    true_normal = glm::normalize(true_normal);
    std::vector<double> angles;
    for (const glm::dvec3& n : surface_normals(window_depth, liquid, width, height, view, proj, convention, border))
        if (n != glm::dvec3(0.0)) angles.push_back(angle_deg(n, true_normal));
    return summarize(angles);
}

NormalError normal_roughness(const std::vector<float>& window_depth, const std::vector<uint8_t>& liquid, int width,
                             int height, const glm::dmat4& view, const glm::dmat4& proj, pf_depth_convention convention,
                             int border, int window) {
    const std::vector<glm::dvec3> normals =
        surface_normals(window_depth, liquid, width, height, view, proj, convention, border);
    // Summed-area table of the normals (unmeasured pixels add 0): each window's sum in four reads.
    const size_t w1 = size_t(width) + 1;
    std::vector<glm::dvec3> table(w1 * (size_t(height) + 1), glm::dvec3(0.0));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            table[(y + 1) * w1 + (x + 1)] = normals[size_t(y) * size_t(width) + size_t(x)] + table[y * w1 + (x + 1)] +
                                            table[(y + 1) * w1 + x] - table[y * w1 + x];
    std::vector<double> angles;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const glm::dvec3& n = normals[size_t(y) * size_t(width) + size_t(x)];
            if (n == glm::dvec3(0.0)) continue;
            const size_t x0 = size_t(std::max(x - window, 0)), x1 = size_t(std::min(x + window, width - 1)) + 1;
            const size_t y0 = size_t(std::max(y - window, 0)), y1 = size_t(std::min(y + window, height - 1)) + 1;
            const glm::dvec3 sum = table[y1 * w1 + x1] - table[y0 * w1 + x1] - table[y1 * w1 + x0] + table[y0 * w1 + x0];
            angles.push_back(angle_deg(n, glm::normalize(sum)));
        }
    }
    return summarize(angles);
}

}  // namespace pfs
