// Force fields (PF_FEATURE_FORCE_FIELDS): wind, attractors/repulsors and vortices, up to
// PF_MAX_FORCE_FIELDS, applied to the grid velocity by one pass per substep right after gravity
// (shaders/effects/force_fields/force_fields.comp; pass list entry "force_fields" in the
// PF_PASS_GRID_FORCES group). The fields live on the host (validated by the API) and are
// uploaded, 48 bytes each, at the start of a step after they changed.
#pragma once
#include "sim/effects/effect.h"
#include "sim/effects/object_list.h"

namespace pf {

// A force field's arguments: every field finite, a known type, drag >= 0 (directional), radius
// > 0 and a vortex's axis non-zero; PF_OK or PF_ERROR_INVALID_ARGUMENT logged with `fn` first.
// Also checks a snapshot's fields on restore. (force_fields_api.cpp, with the entry points)
pf_result validate_force_field(const pf_force_field& field, const Log& log, const char* fn);

class ForceFieldsEffect final : public Effect, public UploadedObjects<pf_force_field, PF_MAX_FORCE_FIELDS> {
public:
    static constexpr uint32_t kFeature = PF_FEATURE_FORCE_FIELDS;
    uint32_t feature() const override { return kFeature; }
    const char* name() const override { return "force_fields"; }
    uint32_t stages() const override {
        return stage_bit(EffectStage::after_grid_forces);
    }
    pf_result init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) override;
    std::vector<gl::ProgramId> programs() const override;
    void begin_step() override;
    void save_state(ByteWriter& out) const override;
    pf_result restore_state(ByteReader& in, const Log& log, const char* fn) override;
    void run(EffectStage stage, PassRunner& runner, const EffectBuffers& buffers) override;
    bool does_work() const override { return list_.size() > 0; }

    // The CFL estimate (design.md §5): the largest acceleration the fields without drag can add,
    // and the fastest wind a drag field pulls towards (drag never pulls beyond it).
    CflBound cfl_bound(float) const override { return {max_acceleration(), max_wind_speed()}; }

private:
    float max_acceleration() const;  // m/s^2
    float max_wind_speed() const;    // m/s

    gl::Buffer records_;  // PF_MAX_FORCE_FIELDS records (force_field_types.h)
    StatId stat_ = 0;
    uint32_t uploaded_ = 0;  // records live on the GPU
};

}  // namespace pf
