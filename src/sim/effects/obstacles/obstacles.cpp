#include "sim/effects/obstacles/obstacles.h"

#include <cmath>
#include <string>
#include <vector>

#include "api/validate.h"
#include "common/slots.h"
#include "effects/obstacles/obstacle_shapes.h"

namespace pf {

static_assert(PF_OBSTACLE_BOX_ID == PF_OBSTACLE_BOX, "shape ids shared with GLSL");
static_assert(PF_OBSTACLE_SPHERE_ID == PF_OBSTACLE_SPHERE, "shape ids shared with GLSL");
static_assert(PF_OBSTACLE_CAPSULE_ID == PF_OBSTACLE_CAPSULE, "shape ids shared with GLSL");

pf_result ObstaclesEffect::init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) {
    for (gl::ProgramId id : {gl::ProgramId::obstacle_cells, gl::ProgramId::obstacle_faces, gl::ProgramId::obstacle_push}) {
        if (std::string error = runner.prepare(id); !error.empty())
            return log.error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
    }
    records_ = gl::Buffer(gl, size_t(PF_MAX_OBSTACLES) * PF_OBSTACLE_VEC4S * 16, GL_DYNAMIC_DRAW, "obstacles");
    grid_stat_ = runner.add_stat("obstacles", PF_PASS_CLASSIFY);
    push_stat_ = runner.add_stat("obstacle_push", PF_PASS_ADVECT);
    dirty_ = true;
    return PF_OK;
}

void ObstaclesEffect::begin_step() {
    if (!dirty_ || records_.bytes() == 0) return;
    std::vector<float> words;
    for (const pf_obstacle& o : list_.items()) {
        // Unit quaternion; (0, 0, 0, 0) is the identity (validated finite).
        double q[4] = {o.rotation[0], o.rotation[1], o.rotation[2], o.rotation[3]};
        const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (n > 0.0) {
            for (double& c : q) c /= n;
        } else {
            q[3] = 1.0;
        }
        float size[3] = {o.half_extents[0], o.half_extents[1], o.half_extents[2]};
        if (o.shape != PF_OBSTACLE_BOX) size[0] = o.radius, size[1] = o.half_height, size[2] = 0.0f;
        const float record[PF_OBSTACLE_VEC4S * 4] = {
            o.position[0], o.position[1], o.position[2], float(o.shape),  //
            float(q[0]),   float(q[1]),   float(q[2]),   float(q[3]),     //
            size[0],       size[1],       size[2],       0.0f,            //
            0.0f,          0.0f,          0.0f,          0.0f};  // static: the surface does not move
        words.insert(words.end(), std::begin(record), std::end(record));
    }
    if (!words.empty()) records_.upload(0, words.size() * 4, words.data());
    uploaded_ = list_.size();
    dirty_ = false;
}

void ObstaclesEffect::run(EffectStage stage, PassRunner& runner, const EffectBuffers& b) {
    if (uploaded_ == 0) return;
    const Bind records{PF_SLOT_OBSTACLES, &records_};
    const Uniforms count{Uniform::uint1(PF_LOC_EFFECT_COUNT, uploaded_)};
    if (stage == EffectStage::after_classify) {
        runner.run({gl::ProgramId::obstacle_cells, grid_stat_, b.cells, {{PF_SLOT_CELL_TYPE, &b.cell_type}, records}, {}, count});
        runner.run({gl::ProgramId::obstacle_faces, grid_stat_, b.faces,
                    {{PF_SLOT_CELL_TYPE, &b.cell_type}, {PF_SLOT_FACE_VEL, &b.face_vel}, records},
                    {},
                    count});
    } else if (stage == EffectStage::after_advect && b.particles > 0) {
        runner.run({gl::ProgramId::obstacle_push, push_stat_, b.particles,
                    {{PF_SLOT_PARTICLE_POS, &b.pos}, {PF_SLOT_PARTICLE_VEL, &b.vel}, records},
                    {},
                    count});
    }
}

void ObstaclesEffect::save_state(ByteWriter& out) const { list_.save(out); }

pf_result ObstaclesEffect::restore_state(ByteReader& in, const Log& log, const char* fn) {
    List staged;
    const Log silent;  // one message for the whole list below
    const std::string error =
        List::load(in, staged, [&](const pf_obstacle& item) { return validate_obstacle(item, silent, fn) == PF_OK; });
    if (!error.empty()) return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": obstacles in the snapshot: " + error);
    list_ = std::move(staged);
    dirty_ = true;
    return PF_OK;
}

}  // namespace pf
