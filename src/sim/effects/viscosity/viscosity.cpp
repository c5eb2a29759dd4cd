#include "sim/effects/viscosity/viscosity.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "common/slots.h"
#include "effects/viscosity/viscosity_state.h"
#include "gl/allocation_check.h"

namespace pf {

static_assert(PF_STATUS_VISCOSITY_RESIDUAL == PF_STATUS_VISCOSITY_ITERATIONS + 1 &&
                  PF_VISC_MAX_RESIDUAL == PF_VISC_MAX_ITERATIONS + 1,
              "the step's solve figures are copied as one pair of words");
static_assert(PF_STATUS_SOLVER_FIRST_ROUND == PF_STATUS_SOLVER_RESIDUAL + 1 &&
                  PF_STATUS_VISCOSITY_PROJECTION_ITERATIONS == PF_STATUS_VISCOSITY_PROJECTION_RESIDUAL + 1,
              "the second projection's figures are copied as one pair of words");

ViscosityEffect::ViscosityEffect(const pf_sim_desc& desc)
    : density_(desc.density > 0.0f ? desc.density : 1000.0f),
      layout_(GridLayout::of(desc.grid_size)),
      settings_(pf_default_viscosity()) {}

std::vector<gl::ProgramId> ViscosityEffect::programs() const {
    return {gl::ProgramId::visc_setup,       gl::ProgramId::visc_stress_start, gl::ProgramId::visc_stress,
            gl::ProgramId::visc_apply_start, gl::ProgramId::visc_apply,        gl::ProgramId::visc_update,
            gl::ProgramId::visc_couple_update};
}

pf_result ViscosityEffect::init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) {
    if (pf_result r = prepare_programs(runner, log, fn); r != PF_OK) return r;
    const uint64_t faces = face_bound();
    if (pf_result r = gl::check_storage_block(gl, log, faces * 8, std::string(fn) + ": viscosity needs",
                                              "(8 per face)", "use a smaller grid");
        r != PF_OK)
        return r;
    const uint64_t groups = runner.workgroups(faces).total();
    coef_ = gl::Buffer(gl, size_t(faces * 8), GL_DYNAMIC_COPY, "viscosity_coefficients");
    r_ = gl::Buffer(gl, size_t(faces * 4), GL_DYNAMIC_COPY, "viscosity_residual");
    p_ = gl::Buffer(gl, size_t(faces * 4), GL_DYNAMIC_COPY, "viscosity_direction");
    q_ = gl::Buffer(gl, size_t(faces * 4), GL_DYNAMIC_COPY, "viscosity_product");
    solid_vel_ = gl::Buffer(gl, size_t(faces * 4), GL_DYNAMIC_COPY, "viscosity_solid_velocities");
    potential_ = gl::Buffer(gl, size_t(layout_.cells() * 4), GL_DYNAMIC_COPY, "viscosity_potential");
    report_ = gl::Buffer(gl, PF_STATUS_WORDS * 4, GL_DYNAMIC_COPY, "viscosity_projection_report");
    sigma_cell_ = gl::Buffer(gl, size_t(layout_.cells() * 16), GL_DYNAMIC_COPY, "viscosity_cell_stress");
    sigma_node_ = gl::Buffer(gl, size_t(layout_.nodes() * 16), GL_DYNAMIC_COPY, "viscosity_edge_stress");
    partials_ = gl::Buffer(gl, size_t(groups * 16), GL_DYNAMIC_COPY, "viscosity_partials");
    state_ = gl::Buffer(gl, PF_VISC_WORDS * 4, GL_DYNAMIC_COPY, "viscosity_state");
    const uint32_t zeros[PF_STATUS_WORDS > PF_VISC_WORDS ? PF_STATUS_WORDS : PF_VISC_WORDS] = {};
    state_.upload(0, PF_VISC_WORDS * 4, zeros);
    report_.upload(0, PF_STATUS_WORDS * 4, zeros);
    const uint64_t bytes = faces * 24 + layout_.cells() * 20 + layout_.nodes() * 16 + groups * 16;
    if (pf_result r = gl::check_allocated(gl, log, std::string(fn) + ": allocating the viscosity solve (" +
                                                       std::to_string(bytes >> 20) + " MiB)");
        r != PF_OK)
        return r;
    gl_ = &gl;
    if (pf_result r = make_round_buffers(settings_.coupling_rounds, log, fn); r != PF_OK) return r;
    stat_ = runner.add_stat("viscosity", PF_PASS_GRID_FORCES);
    projection_stat_ = runner.add_stat("viscosity_projection", PF_PASS_PRESSURE_SOLVE);
    return PF_OK;
}

pf_result ViscosityEffect::set(const pf_viscosity& v, const Log& log, const char* fn) {
    if (pf_result r = make_round_buffers(v.coupling_rounds, log, fn); r != PF_OK) return r;
    settings_ = v;
    recent_ = kUnknownIterations;
    known_after_ = step_;
    return PF_OK;
}

pf_result ViscosityEffect::make_round_buffers(uint32_t rounds, const Log& log, const char* fn) {
    if (rounds <= 1 || !gl_ || round_input_.bytes() != 0) return PF_OK;
    const uint64_t faces = face_bound();
    gl::Buffer input(*gl_, size_t(faces * 4), GL_DYNAMIC_COPY, "viscosity_round_input");
    gl::Buffer before(*gl_, size_t(faces * 4), GL_DYNAMIC_COPY, "viscosity_round_before");
    if (pf_result r = gl::check_allocated(*gl_, log, std::string(fn) + ": allocating the viscosity's coupling rounds (" +
                                                         std::to_string((faces * 8) >> 20) + " MiB)");
        r != PF_OK)
        return r;
    round_input_ = std::move(input);
    round_before_ = std::move(before);
    return PF_OK;
}

void ViscosityEffect::begin_frame(const FrameInfo& frame) {
    step_ = frame.step;
    if (frame.status && frame.status_step > known_after_ && frame.status[PF_STATUS_VISCOSITY_ITERATIONS] > 0) {
        recent_ = frame.status[PF_STATUS_VISCOSITY_ITERATIONS];
        float residual = 0.0f;
        std::memcpy(&residual, &frame.status[PF_STATUS_VISCOSITY_RESIDUAL], sizeof residual);
        recent_converged_ = residual <= settings_.tolerance;
        if (frame.status[PF_STATUS_VISCOSITY_PROJECTION_ITERATIONS] > 0) {
            projection_recent_ = frame.status[PF_STATUS_VISCOSITY_PROJECTION_ITERATIONS];
            std::memcpy(&projection_residual_, &frame.status[PF_STATUS_VISCOSITY_PROJECTION_RESIDUAL],
                        sizeof projection_residual_);
        }
    }
}

void ViscosityEffect::run(EffectStage stage, PassRunner& runner, const EffectBuffers& b) {
    if (stage == EffectStage::after_classify) {
        if (first_substep_) {
            // The second projection's figures restart every step, as the first's do.
            const uint32_t zeros[4] = {};
            report_.upload(PF_STATUS_SOLVER_ITERATIONS * 4, sizeof zeros, zeros);
            static_assert(PF_STATUS_SOLVER_LATER_ROUNDS == PF_STATUS_SOLVER_ITERATIONS + 3, "contiguous words");
        }
        runner.copy(b.face_vel, solid_vel_, size_t(b.layout.faces()) * 4);
    } else if (stage == EffectStage::after_velocity_update) {
        // Coupling rounds need a projector; without one (never in a simulation) one round.
        const uint32_t rounds = b.projector ? settings_.coupling_rounds : 1u;
        if (rounds > 1) runner.copy(b.face_vel, round_input_, size_t(b.layout.faces()) * 4);
        for (uint32_t round = 0; round < rounds; ++round) {
            solve(runner, b);
            first_substep_ = false;
            const bool last = round + 1 == rounds;
            if (last) {
                project(runner, b);
                break;
            }
            // Uzawa's round: what the projection does to this round's viscous velocities (its
            // pressure, as a velocity change) is added to the input of the next round's solve.
            runner.copy(b.face_vel, round_before_, size_t(b.layout.faces()) * 4);
            project(runner, b);
            runner.run({gl::ProgramId::visc_couple_update, stat_, b.layout.faces(),
                        {{PF_SLOT_VISC_X, &b.face_vel}, {PF_SLOT_VISC_TARGET, &round_input_},
                         {PF_SLOT_VISC_BEFORE, &round_before_}, {PF_SLOT_CELL_TYPE, &b.cell_type}}});
        }
    } else if (stage == EffectStage::after_substeps) {
        // The step's most iterations and largest final residual, read back with the status.
        runner.copy(state_, PF_VISC_MAX_ITERATIONS * 4, b.status, PF_STATUS_VISCOSITY_ITERATIONS * 4, 8);
        runner.copy(report_, PF_STATUS_SOLVER_RESIDUAL * 4, b.status, PF_STATUS_VISCOSITY_PROJECTION_RESIDUAL * 4, 8);
    }
}

// The viscous velocities are not divergence-free where the liquid meets walls, the free surface
// or a change of strain: project them again (docs/design.md 9.8).
void ViscosityEffect::project(PassRunner& runner, const EffectBuffers& b) {
    if (!b.projector) return;
    // From zero, not from the last substep's potential: the continuation of a snapshot (which
    // does not hold it) stays bit-identical.
    runner.fill(potential_, uint32_t(layout_.cells()), 0u, projection_stat_);
    b.projector->project(runner, potential_, report_, projection_stat_, projection_recent_, projection_residual_);
}

void ViscosityEffect::solve(PassRunner& runner, const EffectBuffers& b) {
    const Workgroups face_groups = runner.workgroups(b.layout.faces()), node_groups = runner.workgroups(layout_.nodes());
    const Bind cell_type{PF_SLOT_CELL_TYPE, &b.cell_type}, coef{PF_SLOT_VISC_COEF, &coef_},
        state{PF_SLOT_VISC_STATE, &state_}, sigma_cell{PF_SLOT_VISC_SIGMA_CELL, &sigma_cell_},
        sigma_node{PF_SLOT_VISC_SIGMA_NODE, &sigma_node_}, r{PF_SLOT_VISC_R, &r_}, p{PF_SLOT_VISC_P, &p_},
        q{PF_SLOT_VISC_Q, &q_}, partials{PF_SLOT_VISC_PARTIALS, &partials_}, x{PF_SLOT_VISC_X, &b.face_vel};
    const Uniform nu = Uniform::float1(PF_LOC_VISC_NU, settings_.viscosity / density_),
                  slip = Uniform::uint1(PF_LOC_VISC_FREE_SLIP, settings_.free_slip);
    const Indirect over_faces{&state_, PF_VISC_FACE_RECORD * 4}, over_nodes{&state_, PF_VISC_NODE_RECORD * 4};

    runner.run({gl::ProgramId::visc_setup, stat_, b.layout.faces(), {cell_type, coef, state}, {},
                {nu, slip,
                 Uniform::ivec4(PF_LOC_VISC_RECORDS, int32_t(face_groups.x), int32_t(face_groups.y),
                                int32_t(node_groups.x), int32_t(node_groups.y)),
                 Uniform::uint1(PF_LOC_VISC_FIRST, first_substep_ ? 1u : 0u)}});
    // The first residual, from the projected velocities (the fixed faces at their solid's velocity).
    runner.run({gl::ProgramId::visc_stress_start, stat_, layout_.nodes(),
                {cell_type, {PF_SLOT_VISC_P, &b.face_vel}, {PF_SLOT_VISC_SOLID_VEL, &solid_vel_}, sigma_cell, sigma_node},
                {},
                {nu, slip}});
    runner.run({gl::ProgramId::visc_apply_start, stat_, b.layout.faces(), {sigma_cell, sigma_node, coef, r, p, state, partials}});
    const Uniform tolerance = Uniform::float1(PF_LOC_VISC_TOLERANCE, settings_.tolerance);
    const uint32_t issued = issued_iterations();
    for (uint32_t k = 0; k < issued; ++k) {
        runner.run({gl::ProgramId::visc_stress, stat_, 0, {cell_type, p, r, coef, state, sigma_cell, sigma_node},
                    over_nodes, {nu, slip}});
        runner.run({gl::ProgramId::visc_apply, stat_, 0, {sigma_cell, sigma_node, coef, r, p, q, state, partials},
                    over_faces});
        runner.run({gl::ProgramId::visc_update, stat_, 0, {x, coef, r, p, q, state, partials}, over_faces, {tolerance}});
    }
}

void ViscosityEffect::save_state(ByteWriter& out) const {
    out.put(settings_);
    out.put(recent_);
    out.put(uint32_t(recent_converged_ ? 1u : 0u));
    out.put(projection_recent_);
    out.put(projection_residual_);
}

pf_result ViscosityEffect::restore_state(ByteReader& in, const Log& log, const char* fn) {
    pf_viscosity v{};
    uint32_t recent = 0, converged = 0, projection_recent = 0;
    float projection_residual = 0.0f;
    if (!in.get(v) || !in.get(recent) || !in.get(converged) || !in.get(projection_recent) ||
        !in.get(projection_residual))
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": the viscosity in the snapshot is truncated");
    const Log silent;
    if (validate_viscosity(v, silent, fn) != PF_OK || converged > 1 || !std::isfinite(projection_residual))
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": the viscosity in the snapshot is invalid");
    if (pf_result r = make_round_buffers(v.coupling_rounds, log, fn); r != PF_OK) return r;
    settings_ = v;
    recent_ = recent;
    recent_converged_ = converged != 0;
    projection_recent_ = projection_recent;
    projection_residual_ = projection_residual;
    known_after_ = 0;  // the simulation restores the status words it read back then
    return PF_OK;
}

}  // namespace pf
