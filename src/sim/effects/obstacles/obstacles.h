// Static obstacles (PF_FEATURE_OBSTACLES): boxes, spheres and capsules, up to PF_MAX_OBSTACLES,
// as signed-distance primitives (shaders/effects/obstacles/obstacle_sdf.glsl). Per substep:
// after classify, cells whose centre lies inside become SOLID (obstacle_cells) and faces of
// SOLID cells take the obstacle's velocity (obstacle_faces; pass list entry "obstacles", in the
// PF_PASS_CLASSIFY group); after advection, particles inside are pushed out along the distance
// gradient (obstacle_push; entry "obstacle_push", PF_PASS_ADVECT group). Each GPU record holds
// the obstacle's surface velocity (zero here: static), which the solid faces already take, so
// moving obstacles only have to fill it in.
#pragma once
#include "sim/effects/effect.h"
#include "sim/effects/object_list.h"

namespace pf {

class ObstaclesEffect final : public Effect {
public:
    using List = ObjectList<pf_obstacle, PF_MAX_OBSTACLES>;
    uint32_t feature() const override { return PF_FEATURE_OBSTACLES; }
    pf_result init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) override;
    void begin_step() override;
    void save_state(ByteWriter& out) const override;
    pf_result restore_state(ByteReader& in, const Log& log, const char* fn) override;
    void run(EffectStage stage, PassRunner& runner, const EffectBuffers& buffers) override;

    // The host list; call changed() after editing it.
    List& list() { return list_; }
    void changed() { dirty_ = true; }

private:
    List list_;
    bool dirty_ = true;
    gl::Buffer records_;  // PF_MAX_OBSTACLES records (obstacle_shapes.h)
    StatId grid_stat_ = 0, push_stat_ = 0;
    uint32_t uploaded_ = 0;  // records live on the GPU
};

}  // namespace pf
