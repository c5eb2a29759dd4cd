#include "sim/effects/force_fields/force_fields.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "api/validate.h"
#include "common/slots.h"
#include "effects/force_fields/force_field_types.h"

namespace pf {

static_assert(PF_FORCE_FIELD_DIRECTIONAL_ID == PF_FORCE_FIELD_DIRECTIONAL, "type ids shared with GLSL");
static_assert(PF_FORCE_FIELD_POINT_ID == PF_FORCE_FIELD_POINT, "type ids shared with GLSL");
static_assert(PF_FORCE_FIELD_VORTEX_ID == PF_FORCE_FIELD_VORTEX, "type ids shared with GLSL");

std::vector<gl::ProgramId> ForceFieldsEffect::programs() const {
    return {gl::ProgramId::force_fields};
}

pf_result ForceFieldsEffect::init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) {
    if (pf_result r = prepare_programs(runner, log, fn); r != PF_OK) return r;
    records_ = gl::Buffer(gl, size_t(PF_MAX_FORCE_FIELDS) * PF_FORCE_FIELD_VEC4S * 16, GL_DYNAMIC_DRAW, "force_fields");
    stat_ = runner.add_stat("force_fields", PF_PASS_GRID_FORCES);
    dirty_ = true;
    return PF_OK;
}

void ForceFieldsEffect::begin_step() {
    if (!dirty_ || records_.bytes() == 0) return;
    std::vector<float> words;
    for (const pf_force_field& f : list_.items()) {
        float axis[3] = {f.vector[0], f.vector[1], f.vector[2]};
        if (f.type == PF_FORCE_FIELD_VORTEX) {  // the kernel takes a unit axis (validated non-zero)
            const double n = std::sqrt(double(axis[0]) * axis[0] + double(axis[1]) * axis[1] + double(axis[2]) * axis[2]);
            for (float& a : axis) a = float(a / n);
        }
        const float record[PF_FORCE_FIELD_VEC4S * 4] = {
            f.position[0], f.position[1], f.position[2], f.radius,  //
            axis[0],       axis[1],       axis[2],       f.strength,  //
            float(f.type), f.drag,        0.0f,          0.0f};
        words.insert(words.end(), std::begin(record), std::end(record));
    }
    if (!words.empty()) records_.upload(0, words.size() * 4, words.data());
    uploaded_ = list_.size();
    dirty_ = false;
}

namespace {
double length3(const float v[3]) { return std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]); }
}  // namespace

float ForceFieldsEffect::max_acceleration() const {
    double sum = 0;  // fields add up where they overlap
    for (const pf_force_field& f : list_.items()) {
        if (f.type == PF_FORCE_FIELD_DIRECTIONAL) sum += f.drag > 0.0f ? 0.0 : length3(f.vector);
        else sum += std::abs(double(f.strength));  // the peak of the point and vortex profiles
    }
    return float(sum);
}

float ForceFieldsEffect::max_wind_speed() const {
    double fastest = 0;
    for (const pf_force_field& f : list_.items()) {
        if (f.type == PF_FORCE_FIELD_DIRECTIONAL && f.drag > 0.0f) fastest = std::max(fastest, length3(f.vector));
    }
    return float(fastest);
}

void ForceFieldsEffect::run(EffectStage stage, PassRunner& runner, const EffectBuffers& b) {
    if (stage != EffectStage::after_grid_forces || uploaded_ == 0) return;
    runner.run({gl::ProgramId::force_fields, stat_, b.layout.faces(),
                {{PF_SLOT_FACE_ACCUM, &b.face_accum}, {PF_SLOT_FACE_VEL, &b.face_vel}, {PF_SLOT_FORCE_FIELDS, &records_}},
                {},
                {Uniform::uint1(PF_LOC_EFFECT_COUNT, uploaded_)}});
}

void ForceFieldsEffect::save_state(ByteWriter& out) const { list_.save(out); }

pf_result ForceFieldsEffect::restore_state(ByteReader& in, const Log& log, const char* fn) {
    List staged;
    const Log silent;  // one message for the whole list below
    const std::string error =
        List::load(in, staged, [&](const pf_force_field& item) { return validate_force_field(item, silent, fn) == PF_OK; });
    if (!error.empty()) return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": force fields in the snapshot: " + error);
    list_ = std::move(staged);
    dirty_ = true;
    return PF_OK;
}

}  // namespace pf
