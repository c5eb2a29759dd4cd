#include "sim/effects/surface_tension/surface_tension.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/constants.hpp>

#include "common/slots.h"
#include "gl/allocation_check.h"

namespace pf {

SurfaceTensionEffect::SurfaceTensionEffect(const pf_sim_desc& desc)
    : cells_(GridLayout::of(desc.grid_size).cells()),
      density_(desc.density > 0.0f ? desc.density : 1000.0f),
      dx_(desc.cell_size),
      settings_(pf_default_surface_tension()) {}

std::vector<gl::ProgramId> SurfaceTensionEffect::programs() const {
    return {gl::ProgramId::st_fraction, gl::ProgramId::st_fraction_float, gl::ProgramId::st_liquid,
            gl::ProgramId::st_force};
}

pf_result SurfaceTensionEffect::init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) {
    if (pf_result r = prepare_programs(runner, log, fn); r != PF_OK) return r;
    const uint64_t bytes = cells_ * 4;
    if (pf_result r = gl::check_storage_block(gl, log, bytes, std::string(fn) + ": surface tension needs",
                                              "(4 per cell)", "use a smaller grid");
        r != PF_OK)
        return r;
    fraction_ = gl::Buffer(gl, size_t(bytes), GL_DYNAMIC_COPY, "surface_tension_fraction");
    liquid_ = gl::Buffer(gl, size_t(bytes), GL_DYNAMIC_COPY, "surface_tension_liquid");
    if (pf_result r = gl::check_allocated(gl, log, std::string(fn) + ": allocating the surface tension's fields (" +
                                                       std::to_string((2 * bytes) >> 20) + " MiB)");
        r != PF_OK)
        return r;
    stat_ = runner.add_stat("surface_tension", PF_PASS_GRID_FORCES);
    return PF_OK;
}

CflBound SurfaceTensionEffect::cfl_bound(float speed) const {
    (void)speed;
    CflBound bound;
    if (settings_.tension > 0.0f)
        bound.max_dt = kLimitShare * float(std::sqrt(0.5 * double(density_) * double(dx_) * dx_ * dx_ /
                                                     (2.0 * glm::pi<double>() * settings_.tension)));
    return bound;
}

float SurfaceTensionEffect::stable_tension(float dt) const {
    // The limit goes as 1 / sqrt(sigma): the tension whose limit is dt is sigma (max_dt / dt)^2.
    const double ratio = double(cfl_bound(0.0f).max_dt) / double(dt);
    return float(std::min(double(settings_.tension), double(settings_.tension) * ratio * ratio));
}

void SurfaceTensionEffect::run(EffectStage stage, PassRunner& runner, const EffectBuffers& b) {
    if (stage != EffectStage::after_classify || settings_.tension <= 0.0f) return;
    runner.run({b.p2g_float ? gl::ProgramId::st_fraction_float : gl::ProgramId::st_fraction, stat_, b.layout.cells(),
                {{PF_SLOT_FACE_ACCUM, &b.face_accum}, {PF_SLOT_ST_FRACTION, &fraction_}}});
    runner.run({gl::ProgramId::st_liquid, stat_, b.layout.cells(),
                {{PF_SLOT_ST_FRACTION, &fraction_}, {PF_SLOT_CELL_TYPE, &b.cell_type}, {PF_SLOT_ST_LIQUID, &liquid_}}});
    runner.run({gl::ProgramId::st_force, stat_, b.layout.faces(),
                {{PF_SLOT_FACE_VEL, &b.face_vel}, {PF_SLOT_FACE_FRACTION, &b.face_fraction},
                 {PF_SLOT_CELL_TYPE, &b.cell_type}, {PF_SLOT_ST_LIQUID, &liquid_}},
                {},
                {Uniform::float1(PF_LOC_ST_TENSION, stable_tension(frame_dt_ / float(b.substeps)))}});
}

pf_result SurfaceTensionEffect::restore_state(ByteReader& in, const Log& log, const char* fn) {
    pf_surface_tension t{};
    if (!in.get(t))
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": the surface tension in the snapshot is truncated");
    const Log silent;
    if (validate_surface_tension(t, silent, fn) != PF_OK)
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": the surface tension in the snapshot is invalid");
    settings_ = t;
    return PF_OK;
}

}  // namespace pf
