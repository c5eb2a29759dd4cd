#include "sim/effects/sinks/sinks.h"

#include <cmath>
#include <string>
#include <vector>

#include "api/validate.h"
#include "common/slots.h"
#include "effects/sinks/sink_records.h"
#include "sim/effects/unit_quaternion.h"

namespace pf {

static_assert(PF_SINK_BOX_ID == PF_SINK_BOX, "shape ids shared with GLSL");
static_assert(PF_SINK_SPHERE_ID == PF_SINK_SPHERE, "shape ids shared with GLSL");

std::vector<gl::ProgramId> SinksEffect::programs() const {
    return {gl::ProgramId::sink_mark, gl::ProgramId::sink_lists, gl::ProgramId::sink_move,
            gl::ProgramId::sink_move_apic};
}

pf_result SinksEffect::init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) {
    if (pf_result r = prepare_programs(runner, log, fn); r != PF_OK) return r;
    records_ = gl::Buffer(gl, size_t(PF_MAX_SINKS) * PF_SINK_VEC4S * 16, GL_DYNAMIC_DRAW, "sinks");
    state_ = gl::Buffer(gl, PF_SINK_STATE_WORDS * 4, GL_DYNAMIC_COPY, "sink_state");
    // Each list holds at most the removed count (<= capacity) entries.
    holes_ = gl::Buffer(gl, size_t(capacity_) * 4, GL_DYNAMIC_COPY, "sink_holes", gl::Sizing::particles);
    movers_ = gl::Buffer(gl, size_t(capacity_) * 4, GL_DYNAMIC_COPY, "sink_movers", gl::Sizing::particles);
    stat_ = runner.add_stat("sinks", PF_PASS_ADVECT);
    dirty_ = true;
    return PF_OK;
}

pf_result SinksEffect::restore_state(ByteReader& in, const Log& log, const char* fn) {
    List staged;
    const Log silent;  // one message for the whole list below
    const std::string error =
        List::load(in, staged, [&](const pf_sink& k) { return validate_sink(k, desc_, silent, fn) == PF_OK; });
    if (!error.empty()) return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": sinks in the snapshot: " + error);
    list_ = std::move(staged);
    dirty_ = true;
    return PF_OK;
}

void SinksEffect::begin_step() {
    if (records_.bytes() == 0) return;
    if (dirty_) {
        std::vector<float> words;
        for (const pf_sink& k : list_.items()) {
            const std::array<float, 4> q = unit_quaternion(k.rotation);
            float size[3] = {k.half_extents[0], k.half_extents[1], k.half_extents[2]};
            if (k.shape != PF_SINK_BOX) size[0] = k.radius, size[1] = 0.0f, size[2] = 0.0f;
            const float record[PF_SINK_VEC4S * 4] = {
                k.position[0], k.position[1], k.position[2], float(k.shape),  //
                q[0],   q[1],   q[2],   q[3],     //
                size[0],       size[1],       size[2],       0.0f};
            words.insert(words.end(), std::begin(record), std::end(record));
        }
        if (!words.empty()) records_.upload(0, words.size() * 4, words.data());
        uploaded_ = list_.size();
        dirty_ = false;
    }
    if (uploaded_ == 0) return;
    const uint32_t zeros[PF_SINK_STATE_WORDS] = {};
    state_.upload(0, sizeof(zeros), zeros);
}

void SinksEffect::run(EffectStage stage, PassRunner& runner, const EffectBuffers& b) {
    if (stage != EffectStage::after_substeps || uploaded_ == 0 || b.particles == 0) return;
    const Bind pos{PF_SLOT_PARTICLE_POS, &b.pos}, records{PF_SLOT_SINKS, &records_}, state{PF_SLOT_SINK_STATE, &state_},
        holes{PF_SLOT_SINK_HOLES, &holes_}, movers{PF_SLOT_SINK_MOVERS, &movers_};
    const Uniforms count{Uniform::uint1(PF_LOC_EFFECT_COUNT, uploaded_)};
    runner.run({gl::ProgramId::sink_mark, stat_, b.particles, {pos, records, state}, {}, count});
    runner.run({gl::ProgramId::sink_lists, stat_, b.particles, {pos, records, state, holes, movers}, {}, count});
    const Bind vel{PF_SLOT_PARTICLE_VEL, &b.vel}, record{PF_SLOT_PARTICLE_COUNT, &b.count_record};
    if (b.affine) {
        runner.run({gl::ProgramId::sink_move_apic, stat_, b.particles,
                    {pos, vel, state, holes, movers, record, {PF_SLOT_PARTICLE_AFFINE, b.affine}}});
    } else {
        runner.run({gl::ProgramId::sink_move, stat_, b.particles, {pos, vel, state, holes, movers, record}});
    }
}

}  // namespace pf
