#include "sim/effects/emitters/emitters.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "api/validate.h"
#include "common/slots.h"
#include "effects/emitters/emitter_records.h"
#include "sim/effects/unit_quaternion.h"

namespace pf {

static_assert(PF_EMITTER_BOX_ID == PF_EMITTER_BOX, "shape ids shared with GLSL");
static_assert(PF_EMITTER_SPHERE_ID == PF_EMITTER_SPHERE, "shape ids shared with GLSL");
static_assert(PF_EMITTER_DISC_ID == PF_EMITTER_DISC, "shape ids shared with GLSL");

namespace {
float uint_bits(uint32_t u) {
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}
}  // namespace

std::vector<gl::ProgramId> EmittersEffect::programs() const {
    return {gl::ProgramId::emit, gl::ProgramId::emit_apic, gl::ProgramId::emit_commit};
}

pf_result EmittersEffect::init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) {
    if (pf_result r = prepare_programs(runner, log, fn); r != PF_OK) return r;
    records_ = gl::Buffer(gl, size_t(PF_MAX_EMITTERS) * PF_EMITTER_VEC4S * 16, GL_DYNAMIC_DRAW, "emitters");
    stat_ = runner.add_stat("emit", PF_PASS_ADVECT);
    return PF_OK;
}

pf_result EmittersEffect::restore_state(ByteReader& in, const Log& log, const char* fn) {
    // The owed fractions and sequence positions come back too: emission continues exactly.
    List staged;
    const Log silent;  // one message for the whole list below
    const std::string error = List::load(in, staged, [&](const Emitter& e) {
        return validate_emitter(e.desc, desc_, silent, fn) == PF_OK && std::isfinite(e.owed) && e.owed >= 0.0;
    });
    if (!error.empty()) return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": emitters in the snapshot: " + error);
    list_ = std::move(staged);
    return PF_OK;
}

bool EmittersEffect::set(uint32_t id, const pf_emitter& emitter) {
    Emitter* e = list_.find(id);
    if (!e) return false;
    e->desc = emitter;
    return true;
}

float EmittersEffect::added_speed() const {
    float fastest = 0.0f;
    for (const Emitter& e : list_.items()) {
        if (e.desc.rate <= 0.0f) continue;
        const float* v = e.desc.velocity;
        fastest = std::max(fastest, std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    }
    return fastest;
}

void EmittersEffect::begin_frame(const FrameInfo& frame) {
    // Rates become whole particles per frame; the remainder is owed to the next frame, so the
    // emitted count never drifts from rate * time by a particle or more.
    total_ = 0;
    recorded_ = 0;
    words_.clear();
    for (Emitter& e : list_.items_mutable()) {
        const pf_emitter& d = e.desc;
        const double per_second = d.rate_unit == PF_RATE_VOLUME_PER_SECOND ? d.rate / frame.particle_volume : d.rate;
        e.owed += per_second * frame.frame_dt;
        // The step never asks for more than the capacity (the GPU caps it there anyway).
        const double whole = std::min(std::floor(e.owed), double(capacity_ - std::min(total_, capacity_)));
        e.owed -= whole;
        if (e.owed > double(capacity_)) e.owed = double(capacity_);  // a paused sim owes at most one fill
        const uint32_t n = uint32_t(whole);
        const std::array<float, 4> q = unit_quaternion(d.rotation);
        float size[3] = {d.half_extents[0], d.half_extents[1], d.half_extents[2]};
        if (d.shape != PF_EMITTER_BOX) size[0] = d.radius, size[1] = 0.0f, size[2] = 0.0f;
        const float record[PF_EMITTER_VEC4S * 4] = {
            d.position[0],  d.position[1],  d.position[2],  float(d.shape),           //
            q[0],    q[1],    q[2],    q[3],              //
            size[0],        size[1],        size[2],        0.0f,                     //
            d.velocity[0],  d.velocity[1],  d.velocity[2],  frame.frame_dt,           //
            uint_bits(total_), uint_bits(n), uint_bits(uint32_t(e.asked)), 0.0f};
        e.asked += n;
        words_.insert(words_.end(), std::begin(record), std::end(record));
        total_ += n;
        ++recorded_;
    }
}

void EmittersEffect::begin_step() {
    if (total_ > 0 && records_.bytes() != 0) records_.upload(0, words_.size() * 4, words_.data());
}

void EmittersEffect::run(EffectStage stage, PassRunner& runner, const EffectBuffers& b) {
    if (stage != EffectStage::before_substeps || total_ == 0) return;
    const Bind pos{PF_SLOT_PARTICLE_POS, &b.pos}, vel{PF_SLOT_PARTICLE_VEL, &b.vel}, records{PF_SLOT_EMITTERS, &records_},
        count{PF_SLOT_PARTICLE_COUNT, &b.count_record};
    const Uniforms uniforms{Uniform::uint1(PF_LOC_EFFECT_COUNT, recorded_), Uniform::uint1(PF_LOC_EMIT_TOTAL, total_),
                            Uniform::uint1(PF_LOC_EMIT_SEED, seed_), Uniform::uint1(PF_LOC_EMIT_CAPACITY, capacity_)};
    if (b.affine) {
        runner.run({gl::ProgramId::emit_apic, stat_, total_, {pos, vel, records, count, {PF_SLOT_PARTICLE_AFFINE, b.affine}}, {}, uniforms});
    } else {
        runner.run({gl::ProgramId::emit, stat_, total_, {pos, vel, records, count}, {}, uniforms});
    }
    runner.run({gl::ProgramId::emit_commit, stat_, 1, {count, {PF_SLOT_STATUS, &b.status}}, {},
                {Uniform::uint1(PF_LOC_EMIT_TOTAL, total_), Uniform::uint1(PF_LOC_EMIT_CAPACITY, capacity_)}});
}

}  // namespace pf
