// Emitters (PF_FEATURE_EMITTERS): boxes, spheres and discs that add particles at a rate, up to
// PF_MAX_EMITTERS. At the start of each step the host turns every emitter's rate into a whole
// number of particles for the frame (fractions carry over), writes one record per emitter with
// its share of the step's emission, and two passes before the first substep add them on the GPU
// after the live particles: emit (one invocation per new particle; pass list entry "emit",
// PF_PASS_ADVECT group) and emit_commit (raises the GPU's live count, capped at the capacity).
// No readback: the host only keeps an upper bound of the count (docs/design.md §9.3).
#pragma once
#include "sim/effects/effect.h"
#include "sim/effects/object_list.h"

namespace pf {

// An emitter's arguments: every field finite, known shape and rate unit, positive sizes, rate
// >= 0, inside the domain of `desc` and no faster than desc.max_speed; PF_OK or
// PF_ERROR_INVALID_ARGUMENT logged with `fn` first. Also checks a snapshot's emitters on
// restore. (emitters_api.cpp, with the entry points)
pf_result validate_emitter(const pf_emitter& emitter, const pf_sim_desc& desc, const Log& log, const char* fn);

class EmittersEffect final : public Effect {
public:
    // An emitter and the fraction of a particle it still owes (carried to the next step).
    struct Emitter {
        pf_emitter desc{};
        double owed = 0.0;
        uint64_t asked = 0;  // particles it asked for so far (its position in its point sequence)
    };
    using List = ObjectList<Emitter, PF_MAX_EMITTERS>;

    // `desc` resolved and validated: its capacity, seed and domain (snapshots validate against it).
    explicit EmittersEffect(const pf_sim_desc& desc) : desc_(desc), capacity_(desc.max_particles), seed_(desc.seed) {}
    static constexpr uint32_t kFeature = PF_FEATURE_EMITTERS;
    uint32_t feature() const override { return kFeature; }
    const char* name() const override { return "emitters"; }
    uint32_t stages() const override {
        return stage_bit(EffectStage::before_substeps);
    }
    pf_result init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) override;
    std::vector<gl::ProgramId> programs() const override;
    void begin_frame(const FrameInfo& frame) override;
    void begin_step() override;
    void run(EffectStage stage, PassRunner& runner, const EffectBuffers& buffers) override;
    bool does_work() const override { return total_ > 0; }
    uint32_t particles_added() const override { return total_; }
    bool changes_particles() const override { return total_ > 0; }
    bool adds_particles() const override { return true; }
    float added_speed() const override;
    void save_state(ByteWriter& out) const override { list_.save(out); }
    pf_result restore_state(ByteReader& in, const Log& log, const char* fn) override;

    List& list() { return list_; }
    // pf_set_emitter: replaces the description, keeps what the emitter still owes.
    bool set(uint32_t id, const pf_emitter& emitter);

private:
    pf_sim_desc desc_;
    uint32_t capacity_;
    List list_;
    gl::Buffer records_;  // PF_MAX_EMITTERS records (effects/emitters/emitter_records.h)
    StatId stat_ = 0;
    uint32_t total_ = 0;      // particles the current step emits (all emitters)
    uint32_t seed_ = 0;       // the simulation's seed (desc.seed): shifts every emitter's sequence
    uint32_t recorded_ = 0;   // records written for the current step
    std::vector<float> words_;  // the current step's records, uploaded by begin_step
};

}  // namespace pf
