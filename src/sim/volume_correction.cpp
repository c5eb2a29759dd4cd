#include "sim/volume_correction.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace pf {

std::string VolumeCorrection::init(const gl::Api& gl, PassRunner& runner, uint32_t cells) {
    rhs_ = gl::Buffer(gl, size_t(cells) * 4, GL_DYNAMIC_COPY, "volume_correction_rhs");
    potential_ = gl::Buffer(gl, size_t(cells) * 4, GL_DYNAMIC_COPY, "volume_correction_potential");
    // The solver reports iterations and residual into a status buffer: the correction's own,
    // so pf_stats's solver figures stay those of the pressure projection.
    const std::vector<uint32_t> zeros(PF_STATUS_WORDS, 0u);
    report_ = gl::Buffer(gl, zeros.size() * 4, GL_DYNAMIC_COPY, "volume_correction_report");
    report_.upload(0, zeros.size() * 4, zeros.data());
    setup_stat_ = runner.add_stat("volume_correction_setup", PF_PASS_PRESSURE_SETUP);
    solve_stat_ = runner.add_stat("volume_correction_solve", PF_PASS_PRESSURE_SOLVE);
    move_stat_ = runner.add_stat("volume_correction_move", PF_PASS_ADVECT);
    for (gl::ProgramId id : {gl::ProgramId::volume_correction_setup, gl::ProgramId::volume_correction_move}) {
        if (std::string error = runner.prepare(id); !error.empty()) return error;
    }
    return {};
}

pf_sim_params VolumeCorrection::solve_params(const pf_sim_params& params) {
    pf_sim_params p = params;
    p.separation = 0;
    p.pressure_tolerance = std::max(params.pressure_tolerance, kTolerance);
    const bool stationary =
        params.pressure_solver == PF_PRESSURE_SOLVER_JACOBI || params.pressure_solver == PF_PRESSURE_SOLVER_RBGS;
    if (!stationary) p.pressure_iterations = std::min(params.pressure_iterations, kMaxKrylovIterations);
    return p;
}

void VolumeCorrection::run(PassRunner& runner, PressureSolver& solver, const pf_sim_params& params, const Inputs& in) {
    if (params.volume_correction <= 0.0f) return;
    setup(runner, in);
    solve(runner, solver, params, in);
    move(runner, in);
}

void VolumeCorrection::setup(PassRunner& runner, const Inputs& in) {
    runner.run({gl::ProgramId::volume_correction_setup,
                setup_stat_,
                in.cells,
                {{PF_SLOT_CELL_TYPE, &in.cell_type},
                 {PF_SLOT_CELL_COUNT, &in.cell_count},
                 {PF_SLOT_PRESSURE, &in.pressure},
                 {PF_SLOT_RHS, &rhs_},
                 {PF_SLOT_VOLUME_POTENTIAL_OUT, &potential_}}});
}

void VolumeCorrection::solve(PassRunner& runner, PressureSolver& solver, const pf_sim_params& params, const Inputs& in) {
    const PassRunner::StatScope as_correction(runner, solve_stat_);
    const pf_sim_params p = solve_params(params);
    solver.solve(runner, problem(in, p));
}

void VolumeCorrection::solve_paired(PassRunner& runner, PressureSolver& solver, const pf_sim_params& params,
                                    const Inputs& in, const PressureProblem& projection) {
    // Counted with the projection's solve: its passes are the projection's passes.
    const pf_sim_params p = solve_params(params);
    solver.solve_pair(runner, projection, problem(in, p));
}

PressureProblem VolumeCorrection::problem(const Inputs& in, const pf_sim_params& solve) const {
    const bool converged = recent_residual_ >= 0.0f && recent_residual_ <= solve.pressure_tolerance;
    return PressureProblem{in.cell_type, rhs_, potential_, report_, solve,
                           recent_iterations_, kUnknownIterations, converged, recent_residual_};
}

void VolumeCorrection::begin_step(const uint32_t* status_words, bool same_solver) {
    // A step without the correction says nothing, nor does a need of 0 (no cell was over-full):
    // issued 2 on it, the next solve was cut short where cells filled up, and the particles
    // changed (SurfaceTension.CubeRelaxesTowardASphere's volume 2.02% high, bound 2%).
    const uint32_t needed = status_words[PF_STATUS_CORRECTION_ITERATIONS];
    const bool known = same_solver && status_words[PF_STATUS_CORRECTION_RAN] == 1u && needed > 0;
    recent_iterations_ = known ? needed : kUnknownIterations;
    recent_residual_ = -1.0f;
    if (known) std::memcpy(&recent_residual_, &status_words[PF_STATUS_CORRECTION_RESIDUAL], sizeof recent_residual_);
    const uint32_t zeros[4] = {};
    static_assert(PF_STATUS_SOLVER_LATER_ROUNDS == PF_STATUS_SOLVER_ITERATIONS + 3, "contiguous words");
    report_.upload(PF_STATUS_SOLVER_ITERATIONS * 4, sizeof zeros, zeros);
}

void VolumeCorrection::report(PassRunner& runner, const gl::Buffer& status) {
    static_assert(PF_STATUS_SOLVER_FIRST_ROUND == PF_STATUS_SOLVER_RESIDUAL + 1 &&
                      PF_STATUS_CORRECTION_ITERATIONS == PF_STATUS_CORRECTION_RESIDUAL + 1,
                  "the residual and the first round's iterations are contiguous in both");
    runner.copy(report_, PF_STATUS_SOLVER_RESIDUAL * 4, status, PF_STATUS_CORRECTION_RESIDUAL * 4, 8);
}

void VolumeCorrection::move(PassRunner& runner, const Inputs& in) {
    Bindings binds{{PF_SLOT_PARTICLE_POS, &in.positions},
                   {PF_SLOT_CELL_TYPE, &in.cell_type},
                   {PF_SLOT_VOLUME_POTENTIAL, &potential_},
                   {PF_SLOT_FACE_FRACTION, &in.face_fraction}};
    if (in.order) binds.add({PF_SLOT_PARTICLE_ORDER, in.order});
    runner.run({in.order ? gl::ProgramId::volume_correction_move_ordered : gl::ProgramId::volume_correction_move,
                move_stat_, in.particles, binds});
}

}  // namespace pf
