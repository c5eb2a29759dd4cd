#include "sim/effects/vorticity_confinement/vorticity_confinement.h"

#include <string>

#include "common/slots.h"
#include "gl/allocation_check.h"

namespace pf {

VorticityConfinementEffect::VorticityConfinementEffect(const pf_sim_desc& desc)
    : cells_(GridLayout::of(desc.grid_size).cells()),
      settings_(pf_default_vorticity_confinement()) {}

std::vector<gl::ProgramId> VorticityConfinementEffect::programs() const {
    return {gl::ProgramId::vorticity, gl::ProgramId::confinement_force};
}

pf_result VorticityConfinementEffect::init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) {
    if (pf_result r = prepare_programs(runner, log, fn); r != PF_OK) return r;
    const uint64_t bytes = cells_ * 16;
    if (pf_result r = gl::check_storage_block(gl, log, bytes, std::string(fn) + ": vorticity confinement needs",
                                              "(16 per cell)", "use a smaller grid");
        r != PF_OK)
        return r;
    vorticity_ = gl::Buffer(gl, size_t(bytes), GL_DYNAMIC_COPY, "vorticity");
    if (pf_result r = gl::check_allocated(gl, log, std::string(fn) + ": allocating the vorticity (" +
                                                       std::to_string(bytes >> 20) + " MiB)");
        r != PF_OK)
        return r;
    stat_ = runner.add_stat("vorticity_confinement", PF_PASS_GRID_FORCES);
    return PF_OK;
}

void VorticityConfinementEffect::run(EffectStage stage, PassRunner& runner, const EffectBuffers& b) {
    if (stage != EffectStage::after_classify || settings_.strength <= 0.0f) return;
    runner.run({gl::ProgramId::vorticity, stat_, uint32_t(b.layout.cells()),
                {{PF_SLOT_FACE_VEL, &b.face_vel}, {PF_SLOT_CELL_TYPE, &b.cell_type}, {PF_SLOT_VORTICITY, &vorticity_}}});
    runner.run({gl::ProgramId::confinement_force, stat_, uint32_t(b.layout.faces()),
                {{PF_SLOT_FACE_VEL, &b.face_vel}, {PF_SLOT_VORTICITY, &vorticity_}},
                {},
                {Uniform::float1(PF_LOC_VORTICITY_STRENGTH, settings_.strength)}});
}

pf_result VorticityConfinementEffect::restore_state(ByteReader& in, const Log& log, const char* fn) {
    pf_vorticity_confinement c{};
    if (!in.get(c))
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": the vorticity confinement in the snapshot is truncated");
    const Log silent;
    if (validate_vorticity_confinement(c, silent, fn) != PF_OK)
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": the vorticity confinement in the snapshot is invalid");
    settings_ = c;
    return PF_OK;
}

}  // namespace pf
