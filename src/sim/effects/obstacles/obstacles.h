// Obstacles (PF_FEATURE_OBSTACLES): boxes, spheres and capsules, up to PF_MAX_OBSTACLES, as
// signed-distance primitives (shaders/effects/obstacles/obstacle_sdf.glsl), static or moved by
// the engine (pose and linear/angular velocity set each frame). Per substep: after classify,
// cells whose centre lies inside become SOLID (obstacle_cells) and faces of SOLID cells take the
// normal velocity of the obstacle's surface there, v + w x r (obstacle_faces; pass list entry
// "obstacles", PF_PASS_CLASSIFY group); after the velocity update, the pressure on the faces
// between SOLID and FLUID cells is summed into each obstacle's force and torque (obstacle_forces;
// entry "obstacle_forces", PF_PASS_VELOCITY_UPDATE group); after advection, particles inside are
// pushed out along the distance gradient (obstacle_push; entry "obstacle_push", PF_PASS_ADVECT
// group). SDF obstacles sample the engine's 3D texture, bound to a texture unit for each of these
// passes only (PassRunner restores the unit). The step's mean force is copied into a readback ring behind fences at the step's end
// and read once the fence has passed (force()), never waited for.
#pragma once
#include <vector>

#include "gl/objects.h"
#include "gl/readback_ring.h"
#include "sim/effects/effect.h"
#include "sim/effects/object_list.h"

namespace pf {

// An obstacle's arguments: every field finite, a known shape with positive sizes, an SDF with a
// texture; PF_OK or PF_ERROR_INVALID_ARGUMENT logged with `fn` first. Also checks a snapshot's
// obstacles on restore. (obstacles_api.cpp, with the entry points)
pf_result validate_obstacle(const pf_obstacle& obstacle, const Log& log, const char* fn);

// An obstacle as the engine gave it, and how its SDF texture (if any) encodes distances.
struct ObstacleEntry {
    pf_obstacle obstacle{};
    bool sdf_normalized = false;  // GL_R8 / GL_R16: distance = 2 t - 1 (in texture units)
};

// Checks the engine's texture `name` of an SDF obstacle: a GL_TEXTURE_3D whose level 0 has storage
// in GL_R32F, GL_R16F, GL_R8 or GL_R16 (normalized: distance = 2 t - 1). PF_ERROR_INVALID_ARGUMENT,
// logged, otherwise. Puts back the active unit's 3D binding.
pf_result check_sdf_texture(const gl::Api& gl, const Log& log, const char* fn, GLuint name, bool& normalized);

class ObstaclesEffect final : public Effect, public UploadedObjects<ObstacleEntry, PF_MAX_OBSTACLES> {
public:
    ~ObstaclesEffect() override;
    static constexpr uint32_t kFeature = PF_FEATURE_OBSTACLES;
    uint32_t feature() const override { return kFeature; }
    const char* name() const override { return "obstacles"; }
    uint32_t stages() const override {
        return stage_bit(EffectStage::before_first_move) | stage_bit(EffectStage::after_classify) |
               stage_bit(EffectStage::after_velocity_update) | stage_bit(EffectStage::after_advect);
    }
    pf_result init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) override;
    std::vector<gl::ProgramId> programs() const override;
    void begin_step() override;
    void save_state(ByteWriter& out) const override;
    pf_result restore_state(ByteReader& in, const Log& log, const char* fn) override;
    void run(EffectStage stage, PassRunner& runner, const EffectBuffers& buffers) override;
    void end_step(PassRunner& runner, uint64_t step) override;
    // Moving obstacles put energy into the liquid.
    bool does_work() const override { return moving_; }

    // The CFL estimate: the liquid they push reaches at most their fastest surface point.
    CflBound cfl_bound(float) const override { return {0.0f, max_surface_speed()}; }
    // Fastest surface point of the obstacles on the list, m/s (|v| + |w| times the farthest
    // point of the shape from its centre).
    float max_surface_speed() const;
    // The newest force readback of obstacle `id` (step 0 and zeros while none); polls the ring.
    // False if no obstacle has that id.
    bool force(uint32_t id, pf_obstacle_force& out) const;

private:
    void poll() const;               // takes in the readbacks that have arrived
    void read_slot(int s) const;     // downloads one (waiting for its copy) and takes it in

    static constexpr int kReadbackSlots = 3;
    const gl::Api* gl_ = nullptr;
    bool moving_ = false;      // an uploaded obstacle has a non-zero velocity
    gl::Buffer records_;       // PF_MAX_OBSTACLES records (obstacle_shapes.h)
    gl::Object sdf_sampler_;   // linear, clamped: how the engine's SDF textures are sampled
    Textures sdf_textures_;    // the SDF obstacles' textures on their units (obstacle_sdf.glsl)
    gl::Buffer forces_;        // PF_MAX_OBSTACLES force records of the current step
    gl::ReadbackRing<kReadbackSlots> readback_;  // forces_ copies, a few steps late
    uint64_t fence_step_[kReadbackSlots] = {};
    std::vector<uint32_t> fence_ids_[kReadbackSlots];  // the ids of the records each readback holds
    std::vector<uint32_t> uploaded_ids_;                // ids of the records on the GPU, in order
    mutable std::vector<std::pair<uint32_t, pf_obstacle_force>> latest_;  // id -> newest readback
    StatId grid_stat_ = 0, force_stat_ = 0, push_stat_ = 0;
    uint32_t uploaded_ = 0;  // records live on the GPU
};

}  // namespace pf
