#include "sim/effects/obstacles/obstacles.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "api/validate.h"
#include "common/slots.h"
#include "gl/debug.h"
#include "effects/obstacles/obstacle_shapes.h"
#include "sim/effects/unit_quaternion.h"

namespace pf {

static_assert(PF_OBSTACLE_BOX_ID == PF_OBSTACLE_BOX, "shape ids shared with GLSL");
static_assert(PF_OBSTACLE_SPHERE_ID == PF_OBSTACLE_SPHERE, "shape ids shared with GLSL");
static_assert(PF_OBSTACLE_CAPSULE_ID == PF_OBSTACLE_CAPSULE, "shape ids shared with GLSL");
static_assert(PF_OBSTACLE_SDF_ID == PF_OBSTACLE_SDF, "shape ids shared with GLSL");
static_assert(PF_OBSTACLE_MAX <= Textures::kMaxTextures, "one texture unit per obstacle");
static_assert(PF_OBSTACLE_MAX == PF_MAX_OBSTACLES, "obstacle capacity shared with GLSL");

namespace {
constexpr size_t kForceBytes = size_t(PF_MAX_OBSTACLES) * PF_OBSTACLE_FORCE_WORDS * 4;

float length3(const float v[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
}  // namespace

pf_result check_sdf_texture(const gl::Api& gl, const Log& log, const char* fn, GLuint name, bool& normalized) {
    const std::string what = std::string(fn) + ": sdf_texture " + std::to_string(name);
    auto bad = [&](const std::string& why) { return log.error(PF_ERROR_INVALID_ARGUMENT, what + " " + why); };
    if (GLenum pending = gl.GetError(); pending != GL_NO_ERROR)
        log.warning(std::string(fn) + ": a GL error (" + gl::hex(pending) + ") was pending before the call; it was consumed");
    if (!gl.IsTexture(name)) return bad("is not a texture");
    GLint previous = 0;
    gl.GetIntegerv(GL_TEXTURE_BINDING_3D, &previous);
    // Binding a texture to a target it was not created for is GL_INVALID_OPERATION: the one GL 4.3
    // way to learn a texture's target (glGetTextureParameteriv(GL_TEXTURE_TARGET) is 4.5).
    gl.BindTexture(GL_TEXTURE_3D, name);
    if (gl.GetError() != GL_NO_ERROR) {
        gl.BindTexture(GL_TEXTURE_3D, GLuint(previous));
        return bad("is not a GL_TEXTURE_3D");
    }
    GLint size[3] = {}, format = 0;
    gl.GetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &size[0]);
    gl.GetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_HEIGHT, &size[1]);
    gl.GetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &size[2]);
    gl.GetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    gl.BindTexture(GL_TEXTURE_3D, GLuint(previous));
    if (size[0] <= 0 || size[1] <= 0 || size[2] <= 0)
        return bad("has no level-0 image (" + std::to_string(size[0]) + "x" + std::to_string(size[1]) + "x" +
                   std::to_string(size[2]) + ")");
    switch (format) {
        case GL_R32F:
        case GL_R16F: normalized = false; return PF_OK;
        case GL_R8:
        case GL_R16: normalized = true; return PF_OK;
        default:
            return bad("has internal format " + gl::hex(GLenum(format)) +
                       "; a signed distance texture is single-channel GL_R32F, GL_R16F, GL_R8 or GL_R16");
    }
}

ObstaclesEffect::~ObstaclesEffect() = default;

std::vector<gl::ProgramId> ObstaclesEffect::programs() const {
    return {gl::ProgramId::obstacle_cells, gl::ProgramId::obstacle_faces, gl::ProgramId::obstacle_push,
            gl::ProgramId::obstacle_forces};
}

pf_result ObstaclesEffect::init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) {
    if (pf_result r = prepare_programs(runner, log, fn); r != PF_OK) return r;
    gl_ = &gl;
    records_ = gl::Buffer(gl, size_t(PF_MAX_OBSTACLES) * PF_OBSTACLE_VEC4S * 16, GL_DYNAMIC_DRAW, "obstacles");
    forces_ = gl::Buffer(gl, kForceBytes, GL_DYNAMIC_COPY, "obstacle_forces");
    readback_.init(gl, kForceBytes, "obstacle_forces_readback");
    sdf_sampler_ = gl::Object(gl, gl::ObjectKind::sampler);
    gl.SamplerParameteri(sdf_sampler_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl.SamplerParameteri(sdf_sampler_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        gl.SamplerParameteri(sdf_sampler_.id(), wrap, GL_CLAMP_TO_EDGE);
    // A generated sampler name becomes an object (which a label needs) at its first use:
    // labelling it before glSamplerParameteri is GL_INVALID_VALUE on NVIDIA (Mesa lets it pass).
    gl::label_object(gl, GL_SAMPLER, sdf_sampler_.id(), "obstacle_sdf_sampler");
    grid_stat_ = runner.add_stat("obstacles", PF_PASS_CLASSIFY);
    push_stat_ = runner.add_stat("obstacle_push", PF_PASS_ADVECT);
    force_stat_ = runner.add_stat("obstacle_forces", PF_PASS_VELOCITY_UPDATE);
    dirty_ = true;
    return PF_OK;
}

float ObstaclesEffect::max_surface_speed() const {
    float fastest = 0.0f;
    for (const ObstacleEntry& e : list_.items()) {
        const pf_obstacle& o = e.obstacle;
        const bool boxed = o.shape == PF_OBSTACLE_BOX || o.shape == PF_OBSTACLE_SDF;
        const float reach = boxed ? length3(o.half_extents) : o.radius + o.half_height;
        fastest = std::max(fastest, length3(o.velocity) + length3(o.angular_velocity) * reach);
    }
    return fastest;
}

void ObstaclesEffect::begin_step() {
    if (records_.bytes() == 0) return;
    if (dirty_) {
        std::vector<float> words;
        moving_ = false;
        sdf_textures_ = Textures{};
        for (const ObstacleEntry& e : list_.items()) {
            const pf_obstacle& o = e.obstacle;
            const std::array<float, 4> q = unit_quaternion(o.rotation);
            const bool sdf = o.shape == PF_OBSTACLE_SDF;
            float size[4] = {o.half_extents[0], o.half_extents[1], o.half_extents[2], sdf ? o.sdf_scale : 0.0f};
            if (o.shape == PF_OBSTACLE_SPHERE || o.shape == PF_OBSTACLE_CAPSULE)
                size[0] = o.radius, size[1] = o.half_height, size[2] = 0.0f;
            if (sdf) sdf_textures_.add(PF_TEX_UNIT_SDF + uint32_t(words.size() / (PF_OBSTACLE_VEC4S * 4)), o.sdf_texture,
                                       sdf_sampler_.id());
            const float record[PF_OBSTACLE_VEC4S * 4] = {
                o.position[0],         o.position[1],         o.position[2],         float(o.shape),  //
                q[0],           q[1],           q[2],           q[3],     //
                size[0],               size[1],               size[2],               size[3],         //
                o.velocity[0],         o.velocity[1],         o.velocity[2],         e.sdf_normalized ? 1.0f : 0.0f,  //
                o.angular_velocity[0], o.angular_velocity[1], o.angular_velocity[2], 0.0f};
            words.insert(words.end(), std::begin(record), std::end(record));
            moving_ = moving_ || length3(o.velocity) > 0.0f || length3(o.angular_velocity) > 0.0f;
        }
        if (!words.empty()) records_.upload(0, words.size() * 4, words.data());
        uploaded_ = list_.size();
        uploaded_ids_ = list_.ids();
        dirty_ = false;
    }
    // The force sums restart every step (each substep adds its share of the mean).
    if (uploaded_ > 0) {
        static const float zeros[PF_MAX_OBSTACLES * PF_OBSTACLE_FORCE_WORDS] = {};
        forces_.upload(0, size_t(uploaded_) * PF_OBSTACLE_FORCE_WORDS * 4, zeros);
    }
}

void ObstaclesEffect::run(EffectStage stage, PassRunner& runner, const EffectBuffers& b) {
    if (uploaded_ == 0) return;
    const Bind records{PF_SLOT_OBSTACLES, &records_};
    const Uniforms count{Uniform::uint1(PF_LOC_EFFECT_COUNT, uploaded_)};
    if (stage == EffectStage::before_first_move) {
        // Only the cells: a leapfrog's first half move stops before them as every move does.
        runner.run({gl::ProgramId::obstacle_cells, grid_stat_, b.layout.cells(), {{PF_SLOT_CELL_TYPE, &b.cell_type}, records}, {}, count, sdf_textures_});
    } else if (stage == EffectStage::after_classify) {
        runner.run({gl::ProgramId::obstacle_cells, grid_stat_, b.layout.cells(), {{PF_SLOT_CELL_TYPE, &b.cell_type}, records}, {}, count, sdf_textures_});
        runner.run({gl::ProgramId::obstacle_faces, grid_stat_, b.layout.faces(),
                    {{PF_SLOT_CELL_TYPE, &b.cell_type}, {PF_SLOT_FACE_VEL, &b.face_vel}, records},
                    {},
                    count,
                    sdf_textures_});
    } else if (stage == EffectStage::after_velocity_update) {
        runner.run({gl::ProgramId::obstacle_forces, force_stat_, b.layout.faces(),
                    {{PF_SLOT_CELL_TYPE, &b.cell_type}, {PF_SLOT_PRESSURE, &b.pressure}, {PF_SLOT_OBSTACLE_FORCES, &forces_}, records},
                    {},
                    {Uniform::uint1(PF_LOC_EFFECT_COUNT, uploaded_),
                     Uniform::float1(PF_LOC_OBSTACLE_FORCE_WEIGHT, 1.0f / float(std::max(b.substeps, 1u)))},
                    sdf_textures_});
    } else if (stage == EffectStage::after_advect && b.particles > 0) {
        runner.run({gl::ProgramId::obstacle_push, push_stat_, b.particles,
                    {{PF_SLOT_PARTICLE_POS, &b.pos}, {PF_SLOT_PARTICLE_VEL, &b.vel}, records},
                    {},
                    count,
                    sdf_textures_});
    }
}

void ObstaclesEffect::end_step(PassRunner& runner, uint64_t step) {
    if (uploaded_ == 0) return;
    const int slot = int(step % kReadbackSlots);
    // A slot still in flight is read (waiting if the GPU is kReadbackSlots steps behind), never
    // dropped: on a GPU that runs far behind, a dropped slot would mean no result ever arrives.
    if (readback_.pending(slot)) read_slot(slot);
    runner.copy(forces_, readback_.buffer(slot), size_t(uploaded_) * PF_OBSTACLE_FORCE_WORDS * 4);
    readback_.fence(slot);
    fence_step_[slot] = step;
    fence_ids_[slot] = uploaded_ids_;
}

void ObstaclesEffect::read_slot(int s) const {
    const std::vector<uint32_t>& ids = fence_ids_[s];
    std::vector<float> words(ids.size() * PF_OBSTACLE_FORCE_WORDS);
    readback_.take(s, words.data(), words.size() * 4);  // waits for the copy
    for (size_t i = 0; i < ids.size(); ++i) {
        pf_obstacle_force f{};
        std::memcpy(f.force, &words[i * PF_OBSTACLE_FORCE_WORDS], 12);
        std::memcpy(f.torque, &words[i * PF_OBSTACLE_FORCE_WORDS + 4], 12);
        f.step = fence_step_[s];
        auto it = std::find_if(latest_.begin(), latest_.end(), [&](const auto& e) { return e.first == ids[i]; });
        if (it == latest_.end()) {
            latest_.emplace_back(ids[i], f);
        } else if (it->second.step < f.step) {
            it->second = f;
        }
    }
}

void ObstaclesEffect::poll() const {
    if (!gl_) return;
    for (int s = 0; s < kReadbackSlots; ++s) {
        if (readback_.arrived(s)) read_slot(s);
    }
    // Removed obstacles' results go.
    const std::vector<uint32_t>& live = list_.ids();
    latest_.erase(std::remove_if(latest_.begin(), latest_.end(),
                                 [&](const auto& e) { return std::find(live.begin(), live.end(), e.first) == live.end(); }),
                  latest_.end());
}

bool ObstaclesEffect::force(uint32_t id, pf_obstacle_force& out) const {
    const std::vector<uint32_t>& live = list_.ids();
    if (std::find(live.begin(), live.end(), id) == live.end()) return false;
    poll();
    out = pf_obstacle_force{};
    for (const auto& e : latest_)
        if (e.first == id) out = e.second;
    return true;
}

void ObstaclesEffect::save_state(ByteWriter& out) const { list_.save(out); }

pf_result ObstaclesEffect::restore_state(ByteReader& in, const Log& log, const char* fn) {
    List staged;
    const Log silent;  // one message for the whole list below
    const std::string error =
        List::load(in, staged, [&](const ObstacleEntry& item) { return validate_obstacle(item.obstacle, silent, fn) == PF_OK; });
    if (!error.empty()) return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": obstacles in the snapshot: " + error);
    list_ = std::move(staged);
    dirty_ = true;
    return PF_OK;
}

}  // namespace pf
