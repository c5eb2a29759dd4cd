// Viscosity (PF_FEATURE_VISCOSITY; the variational viscosity of Batty & Bridson 2008): per
// substep, after the pressure projection, the face velocities become those that balance the
// liquid's inertia against its strain rate, an implicit solve (stable at any viscosity and step)
// by Jacobi-preconditioned conjugate gradients with its scalars on the GPU
// (shaders/effects/viscosity/): per-face weights (visc_setup.comp), the first residual
// (visc_stress.comp and visc_apply.comp from u*), then per iteration stresses, their divergence
// with p.Ap, and the update with r.z; the solve stops on the GPU at the tolerance. Then the
// simulation's projection runs again (Projector); with coupling rounds, what the projection did
// is fed back into another solve and projection (Uzawa's iteration on the coupled Stokes step).
// Pass list entries "viscosity" (grid_forces) and "viscosity_projection" (pressure_solve);
// docs/design.md §9.8, docs/effects.md.
#pragma once
#include "sim/effects/effect.h"

namespace pf {

// Viscosity finite, above 0 and at most kMaxViscosity (Pa s); iterations 1..1000;
// tolerance 1e-8..0.5; free_slip 0 or 1; coupling_rounds 1..kMaxCouplingRounds. PF_OK or
// PF_ERROR_INVALID_ARGUMENT logged with `fn` first. Also checks a snapshot's value on restore.
// (viscosity_api.cpp, with the entry points)
pf_result validate_viscosity(const pf_viscosity& v, const Log& log, const char* fn);

class ViscosityEffect final : public Effect {
public:
    explicit ViscosityEffect(const pf_sim_desc& desc);
    static constexpr uint32_t kFeature = PF_FEATURE_VISCOSITY;
    static constexpr float kMaxViscosity = 1e5f;  // Pa s
    static constexpr uint32_t kMaxCouplingRounds = 16;
    uint32_t feature() const override { return kFeature; }
    const char* name() const override { return "viscosity"; }
    uint32_t stages() const override {
        return stage_bit(EffectStage::after_classify) | stage_bit(EffectStage::after_velocity_update) |
               stage_bit(EffectStage::after_substeps);
    }
    pf_result init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) override;
    std::vector<gl::ProgramId> programs() const override;
    void begin_step() override { first_substep_ = true; }
    // Learns what recent solves needed from the newest status readback.
    void begin_frame(const FrameInfo& frame) override;
    void turned_on() override {
        recent_ = kUnknownIterations;
        projection_recent_ = kUnknownIterations;
        projection_residual_ = -1.0f;
        known_after_ = step_;  // the status words kept what it measured before it was turned off
    }
    void run(EffectStage stage, PassRunner& runner, const EffectBuffers& buffers) override;
    // Its settings and what recent solves needed (the iterations the next steps issue).
    void save_state(ByteWriter& out) const override;
    pf_result restore_state(ByteReader& in, const Log& log, const char* fn) override;

    // pf_set_viscosity (validated): what earlier solves needed no longer says anything; makes the
    // coupling rounds' buffers when more than one round is first asked for. On an error (logged
    // with `fn` first) nothing changes.
    pf_result set(const pf_viscosity& v, const Log& log, const char* fn);
    // Iterations to issue per solve: the pressure solvers' rule (issued_iterations in
    // src/sim/solvers/pressure_solver.h) on what recent solves needed, within
    // settings().iterations: every issued iteration costs three dispatches even once the GPU has
    // found convergence and emptied them.
    uint32_t issued_iterations() const { return pf::issued_iterations(settings_.iterations, recent_, recent_converged_); }
    const pf_viscosity& settings() const { return settings_; }

private:
    void solve(PassRunner& runner, const EffectBuffers& b);
    // Makes round_input_ and round_before_ if `rounds` needs them and the effect is initialised
    // (init makes them otherwise); PF_OK or the allocation's error.
    pf_result make_round_buffers(uint32_t rounds, const Log& log, const char* fn);
    // Faces its per-face buffers hold: at most 3 per cell plus one layer per axis, bounded by the
    // nodes' count times 3.
    uint64_t face_bound() const { return 3 * layout_.nodes(); }
    void project(PassRunner& runner, const EffectBuffers& b);

    float density_ = 1000.0f;  // kg/m^3
    GridLayout layout_{};  // the grid (its cells and corner nodes)
    const gl::Api* gl_ = nullptr;  // set by init
    bool first_substep_ = true;
    uint32_t recent_ = kUnknownIterations;    // most iterations of a substep's solve in the newest readback
    bool recent_converged_ = false;  // and whether all its solves met the tolerance
    uint64_t step_ = 0, known_after_ = 0;  // the current step; readbacks of steps after this one count
    uint32_t projection_recent_ = kUnknownIterations;  // the second projection's need, as recent_
    float projection_residual_ = -1.0f;
    pf_viscosity settings_{};
    // Per face: mass weight and inverse diagonal (vec2), residual, search direction, A p; per
    // cell: normal stresses (vec4); per cell corner: shear stresses (vec4); the solve's state.
    gl::Buffer coef_, r_, p_, q_, sigma_cell_, sigma_node_, partials_, state_;
    // The face velocities as the walls and obstacles set them after classify (velocity_update
    // zeroes a face inside a solid, whose obstacle velocity the no-slip ghost needs).
    gl::Buffer solid_vel_;
    // The second projection's potential (per cell) and its solver's status words.
    gl::Buffer potential_, report_;
    // Coupling rounds: the next round's input and a round's viscous velocities before its
    // projection (per face); made when more than one round is first asked for.
    gl::Buffer round_input_, round_before_;
    StatId stat_ = 0, projection_stat_ = 0;
};

}  // namespace pf
