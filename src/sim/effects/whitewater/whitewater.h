// Whitewater (PF_FEATURE_WHITEWATER; after Ihmsen et al. 2012): spray, foam and bubbles made
// where the liquid traps air, breaks at crests and moves fast, carried by the liquid without
// acting on it. Once per step, after the last substep, five passes over the step's final grid
// (shaders/effects/whitewater/): the liquid fraction around each cell (ww_fraction.comp), last
// step's particles aged, moved by their kind and compacted into a scratch pair of buffers
// (ww_advect.comp), new particles appended there (ww_emit.comp), the live count committed
// (ww_commit.comp) and the live particles copied back into the buffers engines and the
// renderer read, so their names stay put (ww_copy.comp; the per-particle passes are dispatched
// indirectly, one invocation per live particle). No readback: the count lives on the GPU and
// reaches pf_stats through the status words. Pass list entry "whitewater" in the PF_PASS_ADVECT
// group (docs/effects.md).
#pragma once
#include "sim/effects/effect.h"

namespace pf {

// Every field of `w` within its documented range (pf.h); PF_OK or PF_ERROR_INVALID_ARGUMENT
// logged with `fn` first. Also checks a snapshot's values on restore. (whitewater_api.cpp)
pf_result validate_whitewater(const pf_whitewater& w, const Log& log, const char* fn);

class WhitewaterEffect final : public Effect {
public:
    explicit WhitewaterEffect(const pf_sim_desc& desc);
    static constexpr uint32_t kFeature = PF_FEATURE_WHITEWATER;
    uint32_t feature() const override { return kFeature; }
    const char* name() const override { return "whitewater"; }
    uint32_t stages() const override { return stage_bit(EffectStage::after_substeps); }
    pf_result init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) override;
    std::vector<gl::ProgramId> programs() const override;
    void begin_frame(const FrameInfo& frame) override;
    void begin_step() override;
    void run(EffectStage stage, PassRunner& runner, const EffectBuffers& buffers) override;
    // Particles of an earlier period are stale: cleared at the next step.
    void turned_on() override { clear_ = true; }
    void save_state(ByteWriter& out) const override { out.put(settings_); }
    // Whitewater particles are not saved: a restore clears them.
    pf_result restore_state(ByteReader& in, const Log& log, const char* fn) override;

    // pf_set_whitewater (validated): a new capacity reallocates (and clears) at the next step.
    void set(const pf_whitewater& w) { settings_ = w; }
    const pf_whitewater& settings() const { return settings_; }
    // pf_get_whitewater_buffers; the state record is the draw-indirect buffer.
    void buffers(pf_whitewater_buffers& out) const;
    const gl::Buffer& state() const { return state_; }
    const gl::Buffer& positions() const { return pos_; }

    // The most particles a buffer of 16 bytes each may hold within GL 4.3's smallest allowed
    // GL_MAX_SHADER_STORAGE_BLOCK_SIZE (2^27 bytes), so no capacity can fail that limit.
    static constexpr uint32_t kMaxCapacity = 1u << 23;

private:
    // (Re)makes the buffers for settings_.capacity, with no particles.
    void allocate();
    // No particles: zero live counts in the state record.
    void clear();

    const gl::Api* gl_ = nullptr;
    uint64_t cells_ = 0;
    uint32_t seed_ = 0;
    pf_whitewater settings_{};
    uint32_t allocated_ = 0;  // capacity of the buffers below
    bool clear_ = false;      // clear() at the next begin_step
    float frame_dt_ = 0.0f;
    uint64_t step_ = 0;
    gl::Buffer pos_, vel_;            // the live particles (pf_whitewater_buffers)
    gl::Buffer out_pos_, out_vel_;    // the step's output, copied back into pos_ and vel_
    gl::Buffer fraction_;             // per cell: the liquid fraction around it
    gl::Buffer state_;                // PF_WW_WORDS (common/slots.h)
    StatId stat_ = 0;
};

}  // namespace pf
