// Sinks (PF_FEATURE_SINKS): boxes and spheres that remove the particles inside them, up to
// PF_MAX_SINKS. Once per step after the last substep, three passes compact the particles on the
// GPU (pass list entry "sinks", PF_PASS_ADVECT group): sink_mark counts the particles inside,
// sink_lists lists the holes below the new count and the survivors above it, sink_move moves
// each such survivor into a hole and writes the new live count. The host never reads the
// count back in the step (docs/design.md §9.4).
#pragma once
#include "sim/effects/effect.h"
#include "sim/effects/object_list.h"

namespace pf {

// A sink's arguments: every field finite, a known shape with positive sizes, overlapping the
// domain of `desc`; PF_OK or PF_ERROR_INVALID_ARGUMENT logged with `fn` first. Also checks a
// snapshot's sinks on restore. (sinks_api.cpp, with the entry points)
pf_result validate_sink(const pf_sink& sink, const pf_sim_desc& desc, const Log& log, const char* fn);

class SinksEffect final : public Effect, public UploadedObjects<pf_sink, PF_MAX_SINKS> {
public:
    // `desc` resolved and validated: its capacity and domain (snapshots validate against it).
    explicit SinksEffect(const pf_sim_desc& desc) : desc_(desc), capacity_(desc.max_particles) {}
    static constexpr uint32_t kFeature = PF_FEATURE_SINKS;
    uint32_t feature() const override { return kFeature; }
    const char* name() const override { return "sinks"; }
    uint32_t stages() const override {
        return stage_bit(EffectStage::after_substeps);
    }
    pf_result init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) override;
    std::vector<gl::ProgramId> programs() const override;
    void begin_step() override;
    void run(EffectStage stage, PassRunner& runner, const EffectBuffers& buffers) override;
    bool changes_particles() const override { return uploaded_ > 0; }
    void save_state(ByteWriter& out) const override { list_.save(out); }
    pf_result restore_state(ByteReader& in, const Log& log, const char* fn) override;


private:
    pf_sim_desc desc_;
    uint32_t capacity_;
    gl::Buffer records_;          // PF_MAX_SINKS records (effects/sinks/sink_records.h)
    gl::Buffer state_;            // the compaction counters (PF_SINK_* words)
    gl::Buffer holes_, movers_;   // slot lists, one uint per particle slot
    StatId stat_ = 0;
    uint32_t uploaded_ = 0;       // records live on the GPU
};

}  // namespace pf
