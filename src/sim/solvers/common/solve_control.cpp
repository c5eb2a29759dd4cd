#include "sim/solvers/common/solve_control.h"

#include <algorithm>
#include <vector>

#include "solvers/common/solver_state.h"

namespace pf {

std::string SolveControl::init(const gl::Api& gl, PassRunner& runner, const SolverGrid& grid, bool pairs) {
    grid_ = grid;
    runner_ = &runner;
    pairs_ = pairs;
    std::vector<uint32_t> zeros(PF_SOLVER_PAIR_WORDS, 0u);
    state_ = gl::Buffer(gl, zeros.size() * 4, GL_DYNAMIC_COPY, "solver_state");
    state_.upload(0, zeros.size() * 4, zeros.data());
    orbits_ = uint32_t(orbits(grid.layout.dims));
    // One workgroup per PF_WORKGROUP_SIZE orbits in either mapping (orbit_main.glsl).
    partials_ = runner.workgroups(orbits_).total();  // a 2D dispatch may add idle workgroups
    partials_buffer_ = gl::Buffer(gl, size_t(partials_) * (pairs ? 32 : 16), GL_DYNAMIC_COPY, "solver_partials");
    add_record(grid.layout.cells());
    orbit_record_ = add_record(orbits_);
    for (gl::ProgramId id : {reduction(gl::ProgramId::solver_rhs_stats), gl::ProgramId::solver_begin,
                             reduction(gl::ProgramId::solver_residual), gl::ProgramId::solver_check,
                             gl::ProgramId::solver_report}) {
        if (std::string error = runner.prepare(id); !error.empty()) return error;
    }
    if (!pairs) return {};
    for (gl::ProgramId id : {gl::ProgramId::solver_rhs_stats, gl::ProgramId::solver_begin, gl::ProgramId::solver_residual,
                             gl::ProgramId::solver_report}) {
        if (std::string error = runner.prepare(program(id, true)); !error.empty()) return error;
    }
    return {};
}

gl::ProgramId SolveControl::paired(gl::ProgramId id) {
    using gl::ProgramId;
    switch (id) {
        case ProgramId::solver_rhs_stats: return ProgramId::solver_rhs_stats_pair;
        case ProgramId::solver_begin: return ProgramId::solver_begin_pair;
        case ProgramId::solver_residual: return ProgramId::solver_residual_pair;
        case ProgramId::solver_report: return ProgramId::solver_report_pair;
        case ProgramId::cg_init_stored: return ProgramId::cg_init_stored_pair;
        case ProgramId::cg_update_stored: return ProgramId::cg_update_stored_pair;
        case ProgramId::cg_matvec_stored: return ProgramId::cg_matvec_stored_pair;
        case ProgramId::cg_zstats: return ProgramId::cg_zstats_pair;
        case ProgramId::mg_smooth_from_zero: return ProgramId::mg_smooth_from_zero_pair;
        case ProgramId::mg_smooth: return ProgramId::mg_smooth_pair;
        case ProgramId::mg_residual: return ProgramId::mg_residual_pair;
        case ProgramId::mg_restrict: return ProgramId::mg_restrict_pair;
        case ProgramId::mg_restrict_start: return ProgramId::mg_restrict_start_pair;
        case ProgramId::mg_down: return ProgramId::mg_down_pair;
        case ProgramId::mg_down_start: return ProgramId::mg_down_start_pair;
        case ProgramId::mg_up: return ProgramId::mg_up_pair;
        case ProgramId::mg_prolong_smooth: return ProgramId::mg_prolong_smooth_pair;
        case ProgramId::mg_smooth_zstats: return ProgramId::mg_smooth_zstats_pair;
        case ProgramId::mg_coarse_solve: return ProgramId::mg_coarse_solve_pair;
        case ProgramId::mg_galerkin_down_r2: return ProgramId::mg_galerkin_down_r2_pair;
        case ProgramId::mg_galerkin_down_r1: return ProgramId::mg_galerkin_down_r1_pair;
        case ProgramId::mg_galerkin_up_r2: return ProgramId::mg_galerkin_up_r2_pair;
        case ProgramId::mg_galerkin_up_r1: return ProgramId::mg_galerkin_up_r1_pair;
        case ProgramId::mg_galerkin_coarse: return ProgramId::mg_galerkin_coarse_pair;
        default: return id;
    }
}

gl::ProgramId SolveControl::reduction(gl::ProgramId id) const {
    using gl::ProgramId;
    if (!grid_.one_cell_an_invocation) return id;
    switch (id) {
        case ProgramId::solver_rhs_stats: return ProgramId::solver_rhs_stats_cells;
        case ProgramId::solver_residual: return ProgramId::solver_residual_cells;
        case ProgramId::cg_init_none: return ProgramId::cg_init_none_cells;
        case ProgramId::cg_init_jacobi: return ProgramId::cg_init_jacobi_cells;
        case ProgramId::cg_update_none: return ProgramId::cg_update_none_cells;
        case ProgramId::cg_update_jacobi: return ProgramId::cg_update_jacobi_cells;
        case ProgramId::cg_matvec_none: return ProgramId::cg_matvec_none_cells;
        case ProgramId::cg_matvec_jacobi: return ProgramId::cg_matvec_jacobi_cells;
        case ProgramId::cg_matvec_stored: return ProgramId::cg_matvec_stored_cells;
        case ProgramId::cg_zstats: return ProgramId::cg_zstats_cells;
        case ProgramId::mg_smooth_zstats: return ProgramId::mg_smooth_zstats_cells;
        case ProgramId::solver_rhs_stats_pair: return ProgramId::solver_rhs_stats_pair_cells;
        case ProgramId::solver_residual_pair: return ProgramId::solver_residual_pair_cells;
        case ProgramId::cg_matvec_stored_pair: return ProgramId::cg_matvec_stored_pair_cells;
        case ProgramId::cg_zstats_pair: return ProgramId::cg_zstats_pair_cells;
        case ProgramId::mg_smooth_zstats_pair: return ProgramId::mg_smooth_zstats_pair_cells;
        default: return id;
    }
}

uint32_t SolveControl::add_record(uint64_t invocations) {
    const uint32_t k = records_++;
    const Workgroups groups = runner_->workgroups(invocations);
    const uint32_t full[4] = {groups.x, groups.y, 1u, 0u};
    // The live record and its full size (begin_solve copies one onto the other), and the count.
    state_.upload((PF_SOLVER_SCALARS + 4 * k) * 4, 16, full);
    state_.upload((PF_SOLVER_SCALARS + 4 * (PF_SOLVER_MAX_RECORDS + k)) * 4, 16, full);
    state_.upload(PF_SOLVER_RECORDS * 4, 4, &records_);
    return k;
}

Indirect SolveControl::record(uint32_t k) const { return Indirect{&state_, (PF_SOLVER_SCALARS + 4 * k) * 4}; }

Uniform SolveControl::dims_uniform(glm::ivec3 dims) {
    return Uniform::ivec4(PF_LOC_SOLVER_DIMS, dims.x, dims.y, dims.z, int(GridLayout{dims}.cells()));
}

void SolveControl::rhs_stats(PassRunner& runner, StatId stat, const PressureProblem& problem,
                             const PressureProblem* second) {
    Bindings binds{{PF_SLOT_CELL_TYPE, &problem.cell_type}, {PF_SLOT_RHS, &problem.rhs},
                   {PF_SLOT_SOLVER_PARTIALS, &partials_buffer_}};
    if (second) binds.add({PF_SLOT_SOLVER_RHS_SECOND, &second->rhs});
    runner.run({program(gl::ProgramId::solver_rhs_stats, second != nullptr), stat, orbits_, binds, {}, {dims_uniform()}});
}

void SolveControl::begin(PassRunner& runner, StatId stat, const PressureProblem& problem, bool another_round) {
    rhs_stats(runner, stat, problem, nullptr);
    runner.run({gl::ProgramId::solver_begin,
                stat,
                PF_WORKGROUP_SIZE,
                {{PF_SLOT_SOLVER_PARTIALS, &partials_buffer_}, {PF_SLOT_SOLVER_STATE, &state_}},
                {},
                {Uniform::uint1(PF_LOC_SOLVER_COUNT, partials_),
                 Uniform::float1(PF_LOC_SOLVER_TOLERANCE, problem.params.pressure_tolerance),
                 Uniform::uint1(PF_LOC_SOLVER_ITERATIONS, another_round ? 1u : 0u),
                 Uniform::uint1(PF_LOC_SOLVER_NONNEGATIVE, problem.params.separation ? 1u : 0u)}});
}

void SolveControl::begin_pair(PassRunner& runner, StatId stat, const PressureProblem& first,
                              const PressureProblem& second, const uint32_t caps[2]) {
    rhs_stats(runner, stat, first, &second);
    runner.run({gl::ProgramId::solver_begin_pair,
                stat,
                PF_WORKGROUP_SIZE,
                {{PF_SLOT_SOLVER_PARTIALS, &partials_buffer_}, {PF_SLOT_SOLVER_STATE, &state_}},
                {},
                {Uniform::uint1(PF_LOC_SOLVER_COUNT, partials_),
                 Uniform::float1(PF_LOC_SOLVER_TOLERANCE, first.params.pressure_tolerance),
                 Uniform::float1(PF_LOC_SOLVER_TOLERANCE_SECOND, second.params.pressure_tolerance),
                 Uniform::uint1(PF_LOC_SOLVER_ITERATIONS, 0u), Uniform::uint1(PF_LOC_SOLVER_CAP, caps[0]),
                 Uniform::uint1(PF_LOC_SOLVER_CAP_SECOND, caps[1])}});
}

void SolveControl::residual(PassRunner& runner, StatId stat, const PressureProblem& problem, bool direct,
                            const PressureProblem* second) {
    Bindings binds{{PF_SLOT_CELL_TYPE, &problem.cell_type},
                   {PF_SLOT_RHS, &problem.rhs},
                   {PF_SLOT_SOLVER_X, &problem.pressure},
                   {PF_SLOT_SOLVER_PARTIALS, &partials_buffer_},
                   {PF_SLOT_SOLVER_STATE, &state_}};
    if (second) {
        binds.add({PF_SLOT_SOLVER_RHS_SECOND, &second->rhs});
        binds.add({PF_SLOT_SOLVER_X_SECOND, &second->pressure});
    }
    runner.run({program(gl::ProgramId::solver_residual, second != nullptr), stat, orbits_, binds,
                direct ? Indirect{} : orbit_record(), {dims_uniform()}});
}

void SolveControl::check(PassRunner& runner, StatId stat, const PressureProblem& problem, uint32_t iterations) {
    residual(runner, stat, problem, false);
    runner.run({gl::ProgramId::solver_check,
                stat,
                PF_WORKGROUP_SIZE,
                {{PF_SLOT_SOLVER_PARTIALS, &partials_buffer_}, {PF_SLOT_SOLVER_STATE, &state_}},
                {},
                {Uniform::uint1(PF_LOC_SOLVER_COUNT, partials_), Uniform::uint1(PF_LOC_SOLVER_ITERATIONS, iterations)}});
}

void SolveControl::finish(PassRunner& runner, StatId stat, const PressureProblem& problem,
                          const PressureProblem* second) {
    residual(runner, stat, problem, true, second);
    Bindings binds{{PF_SLOT_SOLVER_PARTIALS, &partials_buffer_},
                   {PF_SLOT_SOLVER_STATE, &state_},
                   {PF_SLOT_SOLVER_STATUS, &problem.status}};
    if (second) binds.add({PF_SLOT_SOLVER_STATUS_SECOND, &second->status});
    runner.run({program(gl::ProgramId::solver_report, second != nullptr), stat, PF_WORKGROUP_SIZE, binds, {},
                {Uniform::uint1(PF_LOC_SOLVER_COUNT, partials_)}});
}

}  // namespace pf
