// The C boundary of rendering: defaults, pass names, argument validation (camera, params; the
// engine's GL objects are checked by the renderer before it draws) and the two render entry
// points. Nothing is drawn or changed when validation fails.
#include <cmath>
#include <memory>
#include <new>
#include <string>
#include <type_traits>

#include "api/abi.h"
#include "api/field_checks.h"
#include "api/handle.h"
#include "api/validate.h"
#include "pf/pf.h"

namespace {
using pf::enum_bits;

using pf::finite_n;
using pf::guarded;
using pf::number_string;

// Determinant of a column-major 4x4 matrix, in double.
double determinant(const float m[16]) {
    auto a = [&](int row, int col) { return double(m[col * 4 + row]); };
    double det = 0.0;
    for (int c = 0; c < 4; ++c) {
        double minor = 0.0;
        int cols[3], k = 0;
        for (int j = 0; j < 4; ++j) {
            if (j != c) cols[k++] = j;
        }
        minor = a(1, cols[0]) * (a(2, cols[1]) * a(3, cols[2]) - a(2, cols[2]) * a(3, cols[1])) -
                a(1, cols[1]) * (a(2, cols[0]) * a(3, cols[2]) - a(2, cols[2]) * a(3, cols[0])) +
                a(1, cols[2]) * (a(2, cols[0]) * a(3, cols[1]) - a(2, cols[1]) * a(3, cols[0]));
        det += ((c % 2) ? -1.0 : 1.0) * a(0, c) * minor;
    }
    return det;
}

struct Validator {
    const pf::Log& log;
    const char* fn;
    pf_result bad(const std::string& what) const {
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what);
    }

    pf_result camera(const pf_camera& c) const {
        if (!finite_n(c.view, 16)) return bad("camera->view must be finite");
        if (!finite_n(c.proj, 16)) return bad("camera->proj must be finite");
        if (!(std::fabs(determinant(c.view)) > 1e-30)) return bad("camera->view is singular");
        if (!(std::fabs(determinant(c.proj)) > 1e-30)) return bad("camera->proj is singular");
        if (c.viewport[0] < 0 || c.viewport[1] < 0)
            return bad("camera->viewport x, y must be >= 0, got " + std::to_string(c.viewport[0]) + ", " +
                       std::to_string(c.viewport[1]));
        for (int i = 2; i < 4; ++i) {
            if (c.viewport[i] < 1 || c.viewport[i] > 16384)
                return bad(std::string("camera->viewport ") + (i == 2 ? "width" : "height") + " must be in [1, 16384], got " +
                           std::to_string(c.viewport[i]));
        }
        if (!(std::isfinite(c.near_plane) && c.near_plane > 0.0f))
            return bad("camera->near_plane must be finite and > 0, got " + number_string(c.near_plane));
        if (!(std::isfinite(c.far_plane) && c.far_plane > c.near_plane))
            return bad("camera->far_plane must be finite and > near_plane, got " + number_string(c.far_plane));
        if (enum_bits(c.depth_convention) > PF_DEPTH_REVERSED_Z)
            return bad("camera->depth_convention is not a pf_depth_convention (" + std::to_string(int32_t(enum_bits(c.depth_convention))) + ")");
        return PF_OK;
    }

    pf_result ssf(const pf_ssf_params& p) const {
        if (!(std::isfinite(p.particle_radius) && p.particle_radius > 0.0f))
            return bad("params->particle_radius must be finite and >= 0 (0 = default), got " + number_string(p.particle_radius));
        if (enum_bits(p.filter) > PF_SSF_FILTER_NONE)
            return bad("params->filter is not a pf_ssf_filter (" + std::to_string(int32_t(enum_bits(p.filter))) + ")");
        if (p.filter_radius < 1 || p.filter_radius > 64)
            return bad("params->filter_radius must be in [1, 64] (0 = default), got " + std::to_string(p.filter_radius));
        if (p.filter_iterations < 1 || p.filter_iterations > 16)
            return bad("params->filter_iterations must be in [1, 16] (0 = default), got " +
                       std::to_string(p.filter_iterations));
        if (!(std::isfinite(p.filter_depth_range) && p.filter_depth_range > 0.0f))
            return bad("params->filter_depth_range must be finite and >= 0 (0 = default), got " + number_string(p.filter_depth_range));
        for (int c = 0; c < 3; ++c) {
            if (!(std::isfinite(p.absorption[c]) && p.absorption[c] >= 0.0f))
                return bad("params->absorption[" + std::to_string(c) + "] must be finite and >= 0, got " + number_string(p.absorption[c]));
        }
        if (!(std::isfinite(p.refraction) && std::fabs(p.refraction) <= 1.0f))
            return bad("params->refraction must be in [-1, 1], got " + number_string(p.refraction));
        if (!(p.fresnel_f0 >= 0.0f && p.fresnel_f0 <= 1.0f)) return bad("params->fresnel_f0 must be in [0, 1], got " + number_string(p.fresnel_f0));
        if (!(std::isfinite(p.specular) && p.specular >= 0.0f))
            return bad("params->specular must be finite and >= 0, got " + number_string(p.specular));
        if (!(p.shininess >= 1.0f && p.shininess <= 10000.0f))
            return bad("params->shininess must be in [1, 10000], got " + number_string(p.shininess));
        const float* l = p.light_direction;
        if (!finite_n(l, 3) || double(l[0]) * l[0] + double(l[1]) * l[1] + double(l[2]) * l[2] < 1e-12)
            return bad("params->light_direction must be finite and non-zero");
        if (enum_bits(p.path) != PF_SSF_PATH_COMPUTE && enum_bits(p.path) != PF_SSF_PATH_RASTER)
            return bad("params->path is not a pf_ssf_path (" + std::to_string(int32_t(enum_bits(p.path))) + ")");
        return PF_OK;
    }

    pf_result particles(const pf_particle_params& p) const {
        if (!(std::isfinite(p.particle_radius) && p.particle_radius > 0.0f))
            return bad("params->particle_radius must be finite and >= 0 (0 = default), got " + number_string(p.particle_radius));
        if (enum_bits(p.color_by) > PF_PARTICLE_COLOR_UNIFORM)
            return bad("params->color_by is not a pf_particle_color (" + std::to_string(int32_t(enum_bits(p.color_by))) + ")");
        if (!finite_n(p.range, 2) || p.range[0] == p.range[1])
            return bad("params->range must be finite with range[0] != range[1], got [" + number_string(p.range[0]) + ", " +
                       number_string(p.range[1]) + "]");
        if (!finite_n(p.color_low, 3) || !finite_n(p.color_high, 3))
            return bad("params->color_low and color_high must be finite");
        return PF_OK;
    }
};

// Zero fields take their defaults (pf.h); the radius default is half a cell.
pf_ssf_params resolve(const pf_ssf_params& in, float cell_size) {
    pf_ssf_params p = in;
    if (p.particle_radius == 0.0f) p.particle_radius = 0.5f * cell_size;
    if (p.filter_radius == 0) p.filter_radius = 8;
    if (p.filter_iterations == 0) p.filter_iterations = p.filter == PF_SSF_FILTER_NARROW_RANGE ? 2 : 1;
    if (p.filter_depth_range == 0.0f) p.filter_depth_range = 2.0f * p.particle_radius;
    return p;
}

pf_particle_params resolve(const pf_particle_params& in, float cell_size) {
    pf_particle_params p = in;
    if (p.particle_radius == 0.0f) p.particle_radius = 0.5f * cell_size;
    return p;
}

// Shared head of both entry points: handle, pointers, camera; makes the renderer on first use.
template <typename Params, typename Draw>
pf_result render_call(pf_sim* handle, const char* fn, const pf_camera* camera, const pf_render_target* target,
                      const Params* params, Params defaults, Draw&& draw) {
    pf::SimEntry* const sim = pf::entry(handle);
    if (!sim) return pf::invalid_handle(handle, fn);
    pf::Simulation& s = *sim->impl;
    const Validator v{s.log(), fn};
    if (!camera) return v.bad("camera must not be NULL");
    if (!target) return v.bad("target must not be NULL");
    if (pf_result r = v.camera(*camera); r != PF_OK) return r;
    Params read = defaults;
    if (params) {
        if (pf_result r = pf::read_input(params, defaults, read, s.log(), fn); r != PF_OK) return r;
    }
    const Params resolved = resolve(read, s.desc().cell_size);
    return guarded(s.log(), fn, [&] {
        if constexpr (std::is_same_v<Params, pf_ssf_params>) {
            if (pf_result r = v.ssf(resolved); r != PF_OK) return r;
        } else {
            if (pf_result r = v.particles(resolved); r != PF_OK) return r;
        }
        if (!sim->renderer) sim->renderer = std::make_unique<pf::Renderer>(s);
        return draw(*sim->renderer, resolved);
    });
}

pf_ssf_params full_default_ssf_params() {
    pf_ssf_params p{};
    p.struct_size = uint32_t(sizeof p);
    p.filter = PF_SSF_FILTER_BILATERAL;
    // Per metre: about a metre of liquid keeps 55% red, 82% green, 90% blue (clear water, tinted).
    p.absorption[0] = 0.6f;
    p.absorption[1] = 0.2f;
    p.absorption[2] = 0.1f;
    p.refraction = 0.03f;
    p.fresnel_f0 = 0.02f;
    p.specular = 1.0f;
    p.shininess = 200.0f;
    p.light_direction[0] = 0.3f;
    p.light_direction[1] = 1.0f;
    p.light_direction[2] = 0.2f;
    p.path = PF_SSF_PATH_COMPUTE;
    return p;
}

pf_particle_params full_default_particle_params() {
    pf_particle_params p{};
    p.struct_size = uint32_t(sizeof p);
    p.color_by = PF_PARTICLE_COLOR_SPEED;
    p.range[0] = 0.0f;
    p.range[1] = 3.0f;
    p.color_low[0] = 0.1f;
    p.color_low[1] = 0.3f;
    p.color_low[2] = 0.9f;
    p.color_high[0] = p.color_high[1] = p.color_high[2] = 1.0f;
    return p;
}

}  // namespace

extern "C" {

pf_result pf_init_ssf_params(pf_ssf_params* out, uint32_t struct_size) {
    return pf::init_struct(out, struct_size, full_default_ssf_params(), "pf_init_ssf_params");
}

pf_result pf_init_particle_params(pf_particle_params* out, uint32_t struct_size) {
    return pf::init_struct(out, struct_size, full_default_particle_params(), "pf_init_particle_params");
}

const char* pf_render_pass_name(pf_render_pass pass) {
    static const char* const kNames[PF_RENDER_PASS_COUNT] = {"scene_copy", "thickness", "depth",    "smooth",
                                                             "shade",      "resolve",   "particles"};
    return (pass >= 0 && pass < PF_RENDER_PASS_COUNT) ? kNames[pass] : "unknown";
}

pf_result pf_render_ssf(pf_sim* sim, const pf_camera* camera, const pf_render_target* target,
                        const pf_ssf_params* params) {
    return render_call(sim, "pf_render_ssf", camera, target, params, pf_default_ssf_params(),
                       [&](pf::Renderer& r, const pf_ssf_params& p) { return r.render_ssf(*camera, *target, p); });
}

pf_result pf_render_particles(pf_sim* sim, const pf_camera* camera, const pf_render_target* target,
                              const pf_particle_params* params) {
    return render_call(sim, "pf_render_particles", camera, target, params, pf_default_particle_params(),
                       [&](pf::Renderer& r, const pf_particle_params& p) {
                           return r.render_particles(*camera, *target, p);
                       });
}

}  // extern "C"
