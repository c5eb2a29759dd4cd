#include "api/validate.h"

#include "api/field_checks.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pf {

namespace {
constexpr float kMinCellSize = 1e-5f, kMaxCellSize = 1e5f;
constexpr double kMaxCellsFromWorldOrigin = 65536.0;
}  // namespace

// The solver's stopping rule, pressure_iterations and pressure_tolerance, is not resolved: with
// struct_size set a 0 there is a request validation refuses (issue 6: an iteration cap of 0 or a
// tolerance of 0 is invalid, not "the default"); a zero-initialised struct has its defaults from
// read_input already.
pf_sim_params resolve_params(const pf_sim_params& in) {
    const pf_sim_params d = pf_default_sim_params();
    pf_sim_params p = in;
    if (p.jacobi_omega == 0.0f) p.jacobi_omega = d.jacobi_omega;
    if (p.cfl == 0.0f) p.cfl = d.cfl;
    if (p.max_substeps == 0) p.max_substeps = d.max_substeps;
    if (p.extrapolation_layers == 0) p.extrapolation_layers = d.extrapolation_layers;
    if (p.sor_omega == 0.0f) p.sor_omega = d.sor_omega;
    if (p.volume_loss_limit == 0.0f) p.volume_loss_limit = d.volume_loss_limit;
    if (p.energy_gain_limit == 0.0f) p.energy_gain_limit = d.energy_gain_limit;
    return p;
}

pf_sim_desc resolve_desc(const pf_sim_desc& in) {
    const pf_sim_desc d = pf_default_sim_desc();
    pf_sim_desc r = in;
    if (r.max_speed == 0.0f) r.max_speed = d.max_speed;
    if (r.density == 0.0f) r.density = d.density;
    if (r.fill_particles_per_cell == 0) r.fill_particles_per_cell = d.fill_particles_per_cell;
    r.params = resolve_params(in.params);
    return r;
}

pf_result validate_params(const pf_sim_params& p, const Log& log, const char* fn) {
    auto bad = [&](const std::string& what) {
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what);
    };
    if (!finite3(p.gravity)) return bad("params.gravity must be finite");
    if (!(p.flip_ratio >= 0.0f && p.flip_ratio <= 1.0f)) return bad("params.flip_ratio must be in [0, 1], got " + number_string(p.flip_ratio));
    if (p.pressure_iterations < 1 || p.pressure_iterations > 10000)
        return bad("params.pressure_iterations must be in [1, 10000], got " + std::to_string(p.pressure_iterations));
    if (!(p.jacobi_omega > 0.0f && p.jacobi_omega <= 1.0f)) return bad("params.jacobi_omega must be in (0, 1], got " + number_string(p.jacobi_omega));
    if (!(p.cfl > 0.0f && p.cfl <= 16.0f)) return bad("params.cfl must be in (0, 16], got " + number_string(p.cfl));
    if (p.max_substeps < 1 || p.max_substeps > 64)
        return bad("params.max_substeps must be in [1, 64], got " + std::to_string(p.max_substeps));
    if (p.separation > 1) return bad("params.separation must be 0 or 1, got " + std::to_string(p.separation));
    if (enum_bits(p.pressure_solver) >= PF_PRESSURE_SOLVER_COUNT)
        return bad("params.pressure_solver is not a pf_pressure_solver value, got " + std::to_string(int32_t(enum_bits(p.pressure_solver))));
    if (!(p.pressure_tolerance > 0.0f && p.pressure_tolerance < 1.0f))
        return bad("params.pressure_tolerance must be in (0, 1), got " + number_string(p.pressure_tolerance));
    if (!(p.sor_omega > 0.0f && p.sor_omega < 2.0f)) return bad("params.sor_omega must be in (0, 2), got " + number_string(p.sor_omega));
    if (enum_bits(p.p2g) >= PF_P2G_COUNT) return bad("params.p2g is not a pf_p2g value, got " + std::to_string(int32_t(enum_bits(p.p2g))));
    if (enum_bits(p.free_surface) >= PF_FREE_SURFACE_COUNT)
        return bad("params.free_surface is not a pf_free_surface value, got " + std::to_string(int32_t(enum_bits(p.free_surface))));
    if (enum_bits(p.transfer) >= PF_TRANSFER_COUNT)
        return bad("params.transfer is not a pf_transfer value, got " + std::to_string(int32_t(enum_bits(p.transfer))));
    if (enum_bits(p.advection) >= PF_ADVECTION_COUNT)
        return bad("params.advection is not a pf_advection value, got " + std::to_string(int32_t(enum_bits(p.advection))));
    if (!(p.volume_correction >= 0.0f && p.volume_correction <= 1.0f))
        return bad("params.volume_correction must be in [0, 1], got " + number_string(p.volume_correction));
    if (!(p.energy_gain_limit > 0.0f && p.energy_gain_limit <= 100.0f))
        return bad("params.energy_gain_limit must be in (0, 100], got " + number_string(p.energy_gain_limit));
    if (!(p.volume_loss_limit > 0.0f && p.volume_loss_limit <= 1.0f))
        return bad("params.volume_loss_limit must be in (0, 1], got " + number_string(p.volume_loss_limit));
    if (p.extrapolation_layers < 1 || p.extrapolation_layers > 16)
        return bad("params.extrapolation_layers must be in [1, 16], got " + std::to_string(p.extrapolation_layers));
    return PF_OK;
}

pf_result validate_desc(const pf_sim_desc& d, const Log& log) {
    auto bad = [&](const std::string& what) { return log.error(PF_ERROR_INVALID_ARGUMENT, "pf_create: " + what); };
    if (!d.gl_get_proc_address) return bad("desc.gl_get_proc_address is required (the engine's GL loader)");
    uint64_t cells = 1;
    for (int a = 0; a < 3; ++a) {
        if (d.grid_size[a] < 1 || d.grid_size[a] > 1024)
            return bad("desc.grid_size[" + std::to_string(a) + "] must be in [1, 1024], got " + std::to_string(d.grid_size[a]));
        cells *= d.grid_size[a];
    }
    if (cells > (uint64_t(1) << 26)) return bad("desc.grid_size has " + std::to_string(cells) + " cells; at most 2^26 are supported");
    if (!(std::isfinite(d.cell_size) && d.cell_size > 0.0f)) return bad("desc.cell_size must be finite and > 0, got " + number_string(d.cell_size));
    if (!finite3(d.origin)) return bad("desc.origin must be finite");
    if (d.cell_size < kMinCellSize || d.cell_size > kMaxCellSize)
        return bad("desc.cell_size must be in [" + number_string(kMinCellSize) + ", " + number_string(kMaxCellSize) + "] m, got " + number_string(d.cell_size));
    for (int a = 0; a < 3; ++a) {
        // Positions are floats: the far corner must exist as one, and a particle anywhere in the
        // domain must still resolve a fraction of a cell (float keeps 24 bits: at 2^16 cells from
        // the world origin a position is exact to 1/128 of a cell).
        const double lo = d.origin[a], hi = lo + double(d.cell_size) * d.grid_size[a];
        const double reach = std::max(std::abs(lo), std::abs(hi)) / d.cell_size;
        if (!(reach <= kMaxCellsFromWorldOrigin)) {
            return bad("desc.origin[" + std::to_string(a) + "] puts the domain " + number_string(reach) +
                       " cells from the world origin; at most 2^16 are resolvable in float (move the origin closer)");
        }
    }
    if (d.max_particles < 1 || d.max_particles > (1u << 28))
        return bad("desc.max_particles must be in [1, 2^28], got " + std::to_string(d.max_particles));
    // The fixed-point P2G resolves max_speed / 2^20 per full-weight particle: above 1e4 m/s a
    // particle's velocity would be rounded by more than 1 cm/s.
    if (!(d.max_speed > 0.0f && d.max_speed <= 1e4f)) return bad("desc.max_speed must be in (0, 1e4] m/s, got " + number_string(d.max_speed));
    if (!(std::isfinite(d.density) && d.density > 0.0f)) return bad("desc.density must be finite and > 0, got " + number_string(d.density));
    const uint32_t ppc = d.fill_particles_per_cell;
    if (ppc != 1 && ppc != 8 && ppc != 27 && ppc != 64)
        return bad("desc.fill_particles_per_cell must be 1, 8, 27 or 64, got " + std::to_string(ppc));
    if (!(d.fill_jitter >= 0.0f && d.fill_jitter <= 1.0f)) return bad("desc.fill_jitter must be in [0, 1], got " + number_string(d.fill_jitter));
    if (pf_result r = validate_features(d.features, log, "pf_create"); r != PF_OK) return r;
    if (pf_result r = validate_features(d.prepared_features, log, "pf_create: desc.prepared_features"); r != PF_OK) return r;
    return validate_params(d.params, log, "pf_create");
}

pf_result validate_features(uint32_t features, const Log& log, const char* fn) {
    if (features & ~uint32_t(PF_FEATURE_ALL)) {
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": unknown feature bits " +
                                                        std::to_string(features & ~uint32_t(PF_FEATURE_ALL)) +
                                                        " (known: PF_FEATURE_ALL = " + std::to_string(PF_FEATURE_ALL) + ")");
    }
    return PF_OK;
}

pf_result validate_particles(const pf_sim_desc& d, const float* xyz, const float* vel, uint32_t n, const Log& log) {
    const double max_speed2 = double(d.max_speed) * d.max_speed;
    for (uint32_t i = 0; i < n; ++i) {
        const float* p = xyz + size_t(i) * 3;
        if (!finite3(p)) return log.error(PF_ERROR_INVALID_ARGUMENT, "pf_add_particles: position " + std::to_string(i) + " is not finite");
        for (int a = 0; a < 3; ++a) {
            const double lo = d.origin[a], hi = d.origin[a] + double(d.cell_size) * d.grid_size[a];
            if (!(p[a] >= lo && p[a] <= hi)) {
                return log.error(PF_ERROR_INVALID_ARGUMENT, "pf_add_particles: particle " + std::to_string(i) +
                                                                " lies outside the domain on axis " + std::to_string(a) +
                                                                " (" + number_string(p[a]) + " not in [" + number_string(lo) + ", " + number_string(hi) + "])");
            }
        }
        if (!vel) continue;
        const float* v = vel + size_t(i) * 3;
        if (!finite3(v)) return log.error(PF_ERROR_INVALID_ARGUMENT, "pf_add_particles: velocity " + std::to_string(i) + " is not finite");
        if (double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2] > max_speed2) {
            return log.error(PF_ERROR_INVALID_ARGUMENT, "pf_add_particles: velocity " + std::to_string(i) +
                                                            " exceeds desc.max_speed (" + number_string(d.max_speed) + " m/s)");
        }
    }
    return PF_OK;
}

namespace {
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

}  // namespace

pf_result validate_camera(const pf_camera& c, const Log& log, const char* fn) {
    auto bad = [&](const std::string& what) {
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what);
    };
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

pf_result validate_render_params(const pf_ssf_params& p, const Log& log, const char* fn) {
    auto bad = [&](const std::string& what) {
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what);
    };
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
    if (!(std::isfinite(p.filter_world_radius) && p.filter_world_radius > 0.0f))
        return bad("params->filter_world_radius must be finite and >= 0 (0 = default), got " +
                   number_string(p.filter_world_radius));
    if (!(std::isfinite(p.whitewater_radius) && p.whitewater_radius > 0.0f))
        return bad("params->whitewater_radius must be finite and >= 0 (0 = default), got " +
                   number_string(p.whitewater_radius));
    if (!(p.whitewater_opacity > 0.0f && p.whitewater_opacity <= 1.0f))
        return bad("params->whitewater_opacity must be in [0, 1] (0 = default), got " + number_string(p.whitewater_opacity));
    if (!(p.spray_radius_scale > 0.0f && p.spray_radius_scale <= 1.0f))
        return bad("params->spray_radius_scale must be in [0, 1] (0 = default), got " + number_string(p.spray_radius_scale));
    return PF_OK;
}

pf_result validate_render_params(const pf_particle_params& p, const Log& log, const char* fn) {
    auto bad = [&](const std::string& what) {
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what);
    };
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

// Zero fields take their defaults (pf.h); the radius default is half a cell.
pf_ssf_params resolve_render_params(const pf_ssf_params& in, float cell_size) {
    pf_ssf_params p = in;
    if (p.particle_radius == 0.0f) p.particle_radius = 0.5f * cell_size;
    if (p.filter_radius == 0) p.filter_radius = 32;
    if (p.filter_world_radius == 0.0f) p.filter_world_radius = cell_size;
    if (p.whitewater_radius == 0.0f) p.whitewater_radius = 0.25f * cell_size;
    if (p.whitewater_opacity == 0.0f) p.whitewater_opacity = 0.5f;
    if (p.spray_radius_scale == 0.0f) p.spray_radius_scale = 0.5f;
    if (p.filter_iterations == 0) p.filter_iterations = p.filter == PF_SSF_FILTER_NARROW_RANGE ? 2 : 1;
    if (p.filter_depth_range == 0.0f) p.filter_depth_range = 2.0f * p.particle_radius;
    return p;
}

pf_particle_params resolve_render_params(const pf_particle_params& in, float cell_size) {
    pf_particle_params p = in;
    if (p.particle_radius == 0.0f) p.particle_radius = 0.5f * cell_size;
    return p;
}

}  // namespace pf
