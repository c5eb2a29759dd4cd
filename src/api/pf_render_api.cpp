// The C boundary of rendering: defaults, pass names and the two render entry points. The
// arguments are checked by src/api/validate.cpp (camera, params) and the engine's GL objects by
// the renderer before it draws. Nothing is drawn or changed when validation fails.
#include <memory>
#include <new>
#include <string>

#include "api/abi.h"
#include "api/handle.h"
#include "api/validate.h"
#include "pf/pf.h"

namespace {
using pf::guarded;

// Shared head of both entry points: handle, pointers, camera; makes the renderer on first use.
template <typename Params, typename Draw>
pf_result render_call(pf_sim* handle, const char* fn, const pf_camera* camera, const pf_render_target* target,
                      const Params* params, Params defaults, Draw&& draw) {
    pf::SimEntry* const sim = pf::entry(handle);
    if (!sim) return pf::invalid_handle(handle, fn);
    pf::Simulation& s = *sim->impl;
    auto bad = [&](const char* what) {
        return s.log().error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what);
    };
    if (!camera) return bad("camera must not be NULL");
    if (!target) return bad("target must not be NULL");
    if (pf_result r = pf::validate_camera(*camera, s.log(), fn); r != PF_OK) return r;
    Params read = defaults;
    if (params) {
        if (pf_result r = pf::read_input(params, defaults, read, s.log(), fn); r != PF_OK) return r;
    }
    const Params resolved = pf::resolve_render_params(read, s.desc().cell_size);
    return guarded(s.log(), fn, [&] {
        if (pf_result r = pf::validate_render_params(resolved, s.log(), fn); r != PF_OK) return r;
        if (!sim->renderer) sim->renderer = std::make_unique<pf::Renderer>(s);
        return draw(*sim->renderer, resolved);
    });
}

pf_ssf_params full_default_ssf_params() {
    pf_ssf_params p{};
    p.struct_size = uint32_t(sizeof p);
    p.filter = PF_SSF_FILTER_NARROW_RANGE;
    // Per metre of liquid: a metre keeps 8% red, 43% green, 66% blue (a tinted pool's look; the
    // shipped images' look, which summed overlapping spheres' chords with 0.6, 0.2, 0.1).
    p.absorption[0] = 2.5f;
    p.absorption[1] = 0.84f;
    p.absorption[2] = 0.42f;
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
