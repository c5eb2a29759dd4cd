#include "sim/effects/whitewater/whitewater.h"

#include <string>

#include "common/slots.h"
#include "gl/allocation_check.h"

namespace pf {

static_assert(PF_GPU_FLAG_WHITEWATER_FULL == PF_FLAG_WHITEWATER_FULL, "flag bits shared with GLSL");

WhitewaterEffect::WhitewaterEffect(const pf_sim_desc& desc)
    : cells_(GridLayout::of(desc.grid_size).cells()),
      seed_(desc.seed),
      settings_(pf_default_whitewater()) {}

std::vector<gl::ProgramId> WhitewaterEffect::programs() const {
    return {gl::ProgramId::ww_fraction, gl::ProgramId::ww_advect, gl::ProgramId::ww_emit,
            gl::ProgramId::ww_commit, gl::ProgramId::ww_copy};
}

pf_result WhitewaterEffect::init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) {
    if (pf_result r = prepare_programs(runner, log, fn); r != PF_OK) return r;
    const uint64_t bytes = uint64_t(settings_.capacity) * 16;  // within every GL's block limit (kMaxCapacity)
    gl_ = &gl;
    allocate();
    if (pf_result r = gl::check_allocated(gl, log, std::string(fn) + ": allocating the whitewater (" +
                                                       std::to_string((4 * bytes + cells_ * 4) >> 20) + " MiB)");
        r != PF_OK)
        return r;
    stat_ = runner.add_stat("whitewater", PF_PASS_ADVECT);
    return PF_OK;
}

void WhitewaterEffect::allocate() {
    const gl::Api& gl = *gl_;
    const size_t bytes = size_t(settings_.capacity) * 16;
    pos_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "whitewater_positions");
    vel_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "whitewater_velocities");
    out_pos_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "whitewater_positions_out");
    out_vel_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "whitewater_velocities_out");
    if (fraction_.bytes() == 0) fraction_ = gl::Buffer(gl, size_t(cells_) * 4, GL_DYNAMIC_COPY, "whitewater_fraction");
    if (state_.bytes() == 0) state_ = gl::Buffer(gl, PF_WW_WORDS * 4, GL_DYNAMIC_COPY, "whitewater_state");
    allocated_ = settings_.capacity;
    clear();  // before any draw reads the records (a render call may come before the next step)
}

void WhitewaterEffect::clear() {
    const uint32_t none[PF_WW_WORDS] = {0, 1, 0, 0, 4, 0, 0, 0, 0, 0, 1, 1};
    state_.upload(0, sizeof(none), none);
    clear_ = false;
}

void WhitewaterEffect::begin_frame(const FrameInfo& frame) {
    frame_dt_ = frame.frame_dt;
    step_ = frame.step;
}

void WhitewaterEffect::begin_step() {
    if (allocated_ != settings_.capacity) allocate();
    if (clear_) clear();
}

void WhitewaterEffect::run(EffectStage stage, PassRunner& runner, const EffectBuffers& b) {
    if (stage != EffectStage::after_substeps) return;
    const pf_whitewater& w = settings_;
    const Bind face_vel{PF_SLOT_FACE_VEL, &b.face_vel}, cell_type{PF_SLOT_CELL_TYPE, &b.cell_type},
        fraction{PF_SLOT_WW_FRACTION, &fraction_}, out_pos{PF_SLOT_WW_OUT_POS, &out_pos_},
        out_vel{PF_SLOT_WW_OUT_VEL, &out_vel_}, state{PF_SLOT_WW_STATE, &state_}, status{PF_SLOT_WW_STATUS, &b.status};
    const Bind pos{PF_SLOT_WW_IN_POS, &pos_}, vel{PF_SLOT_WW_IN_VEL, &vel_};
    const Uniform capacity = Uniform::uint1(PF_LOC_WW_CAPACITY, allocated_);
    // The per-particle passes: one invocation per live particle (the last commit's record).
    const Indirect live{&state_, PF_WW_GROUPS * 4};
    runner.run({gl::ProgramId::ww_fraction, stat_, b.layout.cells(), {cell_type, fraction}});
    runner.run({gl::ProgramId::ww_advect,
                stat_,
                0,
                {pos, vel, face_vel, cell_type, fraction, out_pos, out_vel, state},
                live,
                {Uniform::vec4(PF_LOC_WW_MOTION, frame_dt_, w.bubble_buoyancy, w.bubble_drag, w.spray_drag)}});
    runner.run({gl::ProgramId::ww_emit,
                stat_,
                b.layout.cells(),
                {face_vel, cell_type, fraction, out_pos, out_vel, state, status},
                {},
                {capacity,
                 Uniform::vec4(PF_LOC_WW_LIMITS_A, w.trapped_air_range[0], w.trapped_air_range[1], w.wave_crest_range[0],
                               w.wave_crest_range[1]),
                 Uniform::vec4(PF_LOC_WW_LIMITS_B, w.energy_range[0], w.energy_range[1], w.lifetime[0], w.lifetime[1]),
                 Uniform::vec4(PF_LOC_WW_RATES, w.trapped_air_rate * frame_dt_, w.wave_crest_rate * frame_dt_, 0.0f, 0.0f),
                 Uniform::uint1(PF_LOC_WW_SEED, uint32_t(step_) * 0x9E3779B9u + seed_)}});
    runner.run({gl::ProgramId::ww_commit, stat_, 1, {state, status}, {}, {capacity}});
    runner.run({gl::ProgramId::ww_copy, stat_, 0, {pos, vel, out_pos, out_vel, state}, live});
}

void WhitewaterEffect::buffers(pf_whitewater_buffers& out) const {
    out.positions = pos_.id();
    out.velocities = vel_.id();
    out.capacity = allocated_;
    out.stride = 16;
    out.draw_indirect = state_.id();
}

pf_result WhitewaterEffect::restore_state(ByteReader& in, const Log& log, const char* fn) {
    pf_whitewater w{};
    if (!in.get(w)) return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": the whitewater in the snapshot is truncated");
    const Log silent;
    if (validate_whitewater(w, silent, fn) != PF_OK)
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": the whitewater in the snapshot is invalid");
    settings_ = w;
    clear_ = true;
    return PF_OK;
}

}  // namespace pf
