#include "sim/solvers/mgpcg/multigrid.h"

#include "solvers/common/solver_state.h"
#include "solvers/mgpcg/multigrid_limits.h"

static_assert(3 + 2 * PF_MG_MAX_LEVELS <= PF_SOLVER_MAX_RECORDS, "the multigrid's indirect records must fit the solver state");

namespace pf {

using gl::ProgramId;

std::string Multigrid::init(const gl::Api& gl, PassRunner& runner, SolveControl& control) {
    control_ = &control;
    glm::ivec3 dims = control.dims();
    levels_.clear();
    for (;;) {
        Level level;
        level.dims = dims;
        const GridLayout layout{dims}, next = layout.coarsened();
        level.cells = uint32_t(layout.cells());
        const bool fine = levels_.empty();
        // Axes of two or three cells coarsen to one and two like any other (the prolongation clamps
        // onto the level); only an axis of one cell stays as it is.
        // Galerkin levels: the coarsest is at least level 2 (its 3^3 stencil is what mg_galerkin_coarse
        // colours; level 1's 5^3 is not), unless the fine level is the coarsest or nothing coarsens.
        const bool small = level.cells <= PF_MG_COARSE_CELLS && (!galerkin_ || levels_.size() != 1 || next.dims == dims);
        const bool last = small || levels_.size() + 1 == PF_MG_MAX_LEVELS;
        const size_t bytes = size_t(level.cells) * (control.pairs() ? 8 : 4);  // a pair's: two values a cell
        if (fine) {
            start_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "mg_start");
        } else {
            level.type = gl::Buffer(gl, size_t(level.cells) * 4, GL_DYNAMIC_COPY, "mg_type");
            level.r = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "mg_r");
            level.out = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "mg_out");
            if (!last && !galerkin_) level.e = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "mg_e");
            if (galerkin_)
                level.stencil = gl::Buffer(gl, size_t(level.cells) * (levels_.size() == 1 ? 125 : 27) * 4, GL_DYNAMIC_COPY, "mg_stencil");
        }
        // Indirect records, which convergence zeroes: mg_down's and mg_up's tiles on a fused level;
        // the level's cells where an unfused pass works on them (its own passes, the restriction
        // from an unfused finer level). At most 3 + 2 per level (solver_state.h).
        // The fine level never: its tiles' repeated halo work costs more than its launches save
        // wherever it holds most of the work (a large grid; a CPU rasteriser, which has no launch
        // cost to save).
        level.fused = !fine && !galerkin_ && level.cells <= PF_MG_FUSED_CELLS;
        // The bottom of the V-cycle in one workgroup (mg_bottom.comp): the level above the coarsest.
        level.bottom = !fine && !galerkin_ && !last && level.cells <= PF_MG_BOTTOM_CELLS && next.cells() <= PF_MG_COARSE_CELLS;
        const bool finer_unfused = !fine && !levels_.back().fused;
        if (fine) level.record = control.record(0);
        else if (!level.fused || finer_unfused) level.record = control.record(control.add_record(level.cells));
        if (galerkin_ && !fine && !last) level.down_cells = control.record(control.add_record(uint64_t(next.cells()) * 8));
        if (!last && level.fused && (!level.bottom || control.pairs())) {
            level.down = control.record(control.add_record(next.tiles(PF_MG_DOWN_TILE) * PF_WORKGROUP_SIZE));
            if (!fine) level.up = control.record(control.add_record(layout.tiles(PF_MG_UP_TILE) * PF_WORKGROUP_SIZE));
        }
        levels_.push_back(std::move(level));
        if (last) break;
        dims = next.dims;
    }
    if (levels_.back().cells > PF_MG_COARSE_CELLS)
        return "multigrid: the coarsest level has " + std::to_string(levels_.back().cells) + " cells (more than " +
               std::to_string(PF_MG_COARSE_CELLS) + ")";
    // The passes of the levels above the coarsest, fused or not, and the bottom's: only those
    // built (for a pair's cycle as well when the control solves pairs; the bottom's are fused there).
    for (bool pair : {false, true}) {
        if (pair && !control.pairs()) break;
        pair_ = pair;
        std::vector<ProgramId> programs{galerkin_ ? ProgramId::mg_coarsen_types_galerkin : ProgramId::mg_coarsen_types,
                                        program(ProgramId::mg_smooth_from_zero),
                                        program(ProgramId::mg_prolong_smooth), program(ProgramId::mg_smooth_zstats),
                                        program(ProgramId::cg_zstats)};
        if (galerkin_) {
            for (ProgramId id : {ProgramId::mg_galerkin_first, ProgramId::mg_galerkin_aggregate_r2,
                                 ProgramId::mg_galerkin_aggregate_r1, program(ProgramId::mg_galerkin_down_r2),
                                 program(ProgramId::mg_galerkin_down_r1), program(ProgramId::mg_galerkin_up_r2),
                                 program(ProgramId::mg_galerkin_up_r1), program(ProgramId::mg_galerkin_coarse),
                                 program(ProgramId::mg_smooth), program(ProgramId::mg_residual), program(ProgramId::mg_restrict),
                                 program(ProgramId::mg_coarse_solve)})
                programs.push_back(id);
            for (ProgramId id : programs) {
                if (std::string error = runner.prepare(id); !error.empty()) return error;
            }
            continue;
        }
        bool fused = false, unfused = false, bottom_level = false;
        for (size_t l = 0; l + 1 < levels_.size(); ++l) {
            if (bottom(l)) bottom_level = true;
            else (levels_[l].fused ? fused : unfused) = true;
        }
        programs.push_back(program(bottom_level ? ProgramId::mg_bottom : ProgramId::mg_coarse_solve));
        if (fused) {
            for (ProgramId id : {ProgramId::mg_down, ProgramId::mg_down_start, ProgramId::mg_up}) programs.push_back(program(id));
        }
        if (unfused) {
            for (ProgramId id : {ProgramId::mg_smooth, ProgramId::mg_residual, ProgramId::mg_restrict, ProgramId::mg_restrict_start})
                programs.push_back(program(id));
        }
        for (ProgramId id : programs) {
            if (std::string error = runner.prepare(id); !error.empty()) return error;
        }
    }
    pair_ = false;
    return {};
}

void Multigrid::half_sweep(PassRunner& runner, StatId stat, size_t l, const gl::Buffer& x, uint32_t color) {
    runner.run({program(ProgramId::mg_smooth), stat, 0,
                {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &x},
                 {PF_SLOT_SOLVER_STATE, &control_->state()}},
                levels_[l].record,
                {SolveControl::dims_uniform(levels_[l].dims), Uniform::uint1(PF_LOC_SOLVER_COLOR, color),
                 Uniform::float1(PF_LOC_SOLVER_OMEGA, 1.0f)}});
}

Uniform Multigrid::coarse_dims(const Level& coarse) {
    return Uniform::ivec4(PF_LOC_SOLVER_COARSE_DIMS, coarse.dims.x, coarse.dims.y, coarse.dims.z, int(coarse.cells));
}

void Multigrid::begin(PassRunner& runner, StatId stat, const gl::Buffer& cell_type) {
    fine_type_ = &cell_type;
    for (size_t l = 0; l + 1 < levels_.size(); ++l) {
        runner.run({galerkin_ ? ProgramId::mg_coarsen_types_galerkin : ProgramId::mg_coarsen_types, stat, levels_[l + 1].cells,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_COARSE_TYPE, &levels_[l + 1].type}},
                    {},
                    {SolveControl::dims_uniform(levels_[l].dims), coarse_dims(levels_[l + 1])}});
    }
    if (!galerkin_ || levels_.size() < 2) return;
    // The operators, finest first: level 1 from the fine level, each deeper one from the one above.
    runner.run({ProgramId::mg_galerkin_first, stat, levels_[1].cells * 125,
                {{PF_SLOT_MG_TYPE, &type_of(0)}, {PF_SLOT_MG_COARSE_TYPE, &levels_[1].type},
                 {PF_SLOT_MG_COARSE_STENCIL, &levels_[1].stencil}},
                {},
                {SolveControl::dims_uniform(levels_[0].dims), coarse_dims(levels_[1])}});
    for (size_t l = 1; l + 1 < levels_.size(); ++l) {
        runner.run({l == 1 ? ProgramId::mg_galerkin_aggregate_r2 : ProgramId::mg_galerkin_aggregate_r1, stat,
                    levels_[l + 1].cells * 27,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_STENCIL, &levels_[l].stencil},
                     {PF_SLOT_MG_COARSE_STENCIL, &levels_[l + 1].stencil}},
                    {},
                    {SolveControl::dims_uniform(levels_[l].dims), coarse_dims(levels_[l + 1])}});
    }
}

void Multigrid::galerkin_vcycle(PassRunner& runner, StatId stat, size_t l) {
    const Level& level = levels_[l];
    const Uniform dims = SolveControl::dims_uniform(level.dims);
    if (coarsest(l)) {
        runner.run({program(ProgramId::mg_galerkin_coarse), stat, PF_WORKGROUP_SIZE,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_STENCIL, &level.stencil},
                     {PF_SLOT_MG_TMP, &out_of(l)}, {PF_SLOT_SOLVER_STATE, &control_->state()}},
                    {},
                    {dims}});
        return;
    }
    const Level& coarse = levels_[l + 1];
    runner.run({program(l == 1 ? ProgramId::mg_galerkin_down_r2 : ProgramId::mg_galerkin_down_r1), stat, 0,
                {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_STENCIL, &level.stencil},
                 {PF_SLOT_MG_COARSE_R, &coarse.r}},
                level.down_cells,
                {dims, coarse_dims(coarse)}});
    galerkin_vcycle(runner, stat, l + 1);
    runner.run({program(l == 1 ? ProgramId::mg_galerkin_up_r2 : ProgramId::mg_galerkin_up_r1), stat, 0,
                {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_STENCIL, &level.stencil},
                 {PF_SLOT_MG_TMP, &out_of(l)}, {PF_SLOT_MG_COARSE_E, &out_of(l + 1)}},
                level.record,
                {dims, coarse_dims(coarse)}});
}

void Multigrid::vcycle(PassRunner& runner, StatId stat, size_t l, uint32_t cg_step) {
    const Level& level = levels_[l];
    const Uniform dims = SolveControl::dims_uniform(level.dims);
    if (bottom(l)) {
        // This level and the coarsest in one workgroup (PF_WORKGROUP_SIZE invocations make one group).
        runner.run({ProgramId::mg_bottom, stat, PF_WORKGROUP_SIZE,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &e_of(l)},
                     {PF_SLOT_MG_COARSE_TYPE, &levels_[l + 1].type}, {PF_SLOT_MG_TMP, &out_of(l)},
                     {PF_SLOT_SOLVER_STATE, &control_->state()}},
                    {},
                    {dims, coarse_dims(levels_[l + 1])}});
        return;
    }
    if (coarsest(l)) {
        // One workgroup (of PF_MG_COARSE_INVOCATIONS): PF_WORKGROUP_SIZE invocations make one group.
        runner.run({program(ProgramId::mg_coarse_solve), stat, PF_WORKGROUP_SIZE,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &out_of(l)},
                     {PF_SLOT_SOLVER_STATE, &control_->state()}},
                    {},
                    {dims}});
        return;
    }
    const Level& coarse = levels_[l + 1];
    // e holds the red half-sweep from zero (made with r); the black one completes the
    // pre-smoothing, and its residual is restricted: one pass on a fused level (mg_down.comp).
    if (!level.fused) {
        half_sweep(runner, stat, l, e_of(l), 1u);
        runner.run({program(ProgramId::mg_residual), stat, 0,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &e_of(l)},
                     {PF_SLOT_MG_TMP, &out_of(l)}},
                    level.record,
                    {dims}});
        if (coarsest(l + 1) || galerkin_) {
            runner.run({program(ProgramId::mg_restrict), stat, 0,
                        {{PF_SLOT_MG_TMP, &out_of(l)}, {PF_SLOT_MG_COARSE_TYPE, &coarse.type},
                         {PF_SLOT_MG_COARSE_R, &coarse.r}},
                        coarse.record,
                        {dims, coarse_dims(coarse)}});
        } else {
            runner.run({program(ProgramId::mg_restrict_start), stat, 0,
                        {{PF_SLOT_MG_TMP, &out_of(l)}, {PF_SLOT_MG_COARSE_TYPE, &coarse.type},
                         {PF_SLOT_MG_COARSE_R, &coarse.r}, {PF_SLOT_MG_COARSE_E, &coarse.e}},
                        coarse.record,
                        {dims, coarse_dims(coarse)}});
        }
    } else if (coarsest(l + 1)) {
        runner.run({program(ProgramId::mg_down), stat, 0,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &e_of(l)},
                     {PF_SLOT_MG_COARSE_TYPE, &coarse.type}, {PF_SLOT_MG_COARSE_R, &coarse.r}},
                    level.down,
                    {dims, coarse_dims(coarse)}});
    } else {
        runner.run({program(ProgramId::mg_down_start), stat, 0,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &e_of(l)},
                     {PF_SLOT_MG_COARSE_TYPE, &coarse.type}, {PF_SLOT_MG_COARSE_R, &coarse.r},
                     {PF_SLOT_MG_COARSE_E, &coarse.e}},
                    level.down,
                    {dims, coarse_dims(coarse)}});
    }
    if (galerkin_) galerkin_vcycle(runner, stat, l + 1);
    else vcycle(runner, stat, l + 1, cg_step);
    // The correction, then black and red: one pass on a fused level (mg_up.comp); on the fine
    // level the red half-sweep carries CG's sums.
    if (l > 0 && level.fused) {
        runner.run({program(ProgramId::mg_up), stat, 0,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &e_of(l)},
                     {PF_SLOT_MG_TMP, &out_of(l)}, {PF_SLOT_MG_COARSE_E, &out_of(l + 1)}},
                    level.up,
                    {dims, coarse_dims(coarse)}});
        return;
    }
    runner.run({program(ProgramId::mg_prolong_smooth), stat, 0,
                {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &e_of(l)},
                 {PF_SLOT_MG_TMP, &out_of(l)}, {PF_SLOT_MG_COARSE_E, &out_of(l + 1)}},
                level.record,
                {dims, coarse_dims(coarse)}});
    if (l > 0) {
        half_sweep(runner, stat, l, out_of(l), 0u);
        return;
    }
    runner.run({program(ProgramId::mg_smooth_zstats), stat, 0,
                {{PF_SLOT_MG_TYPE, &type_of(0)}, {PF_SLOT_MG_R, &r_of(0)}, {PF_SLOT_MG_E, &out_of(0)},
                 {PF_SLOT_SOLVER_PARTIALS, &control_->partials()}, {PF_SLOT_SOLVER_STATE, &control_->state()}},
                control_->orbit_record(),
                {dims, Uniform::uint1(PF_LOC_SOLVER_CG_STEP, cg_step)}});
}

void Multigrid::apply(PassRunner& runner, StatId stat, const gl::Buffer& cell_type, const gl::Buffer& r,
                      const gl::Buffer& z, bool first_sweep_done, uint32_t cg_step, bool pair) {
    pair_ = pair;
    fine_type_ = &cell_type;
    fine_r_ = &r;
    fine_z_ = &z;
    const Uniform dims = SolveControl::dims_uniform(levels_[0].dims);
    if (!first_sweep_done && !coarsest(0)) {
        runner.run({program(ProgramId::mg_smooth_from_zero), stat, 0,
                    {{PF_SLOT_MG_TYPE, &cell_type}, {PF_SLOT_MG_R, &r}, {PF_SLOT_MG_E, &start_},
                     {PF_SLOT_SOLVER_STATE, &control_->state()}},
                    control_->record(0),
                    {dims, Uniform::uint1(PF_LOC_SOLVER_COLOR, 0u), Uniform::float1(PF_LOC_SOLVER_OMEGA, 1.0f)}});
    }
    vcycle(runner, stat, 0, cg_step);
    if (coarsest(0)) {
        // A grid small enough to be its own coarsest level: its solve has no fused sums.
        runner.run({program(ProgramId::cg_zstats), stat, 0,
                    {{PF_SLOT_CELL_TYPE, &cell_type}, {PF_SLOT_SOLVER_R, &r}, {PF_SLOT_SOLVER_Z, &z},
                     {PF_SLOT_SOLVER_PARTIALS, &control_->partials()}, {PF_SLOT_SOLVER_STATE, &control_->state()}},
                    control_->orbit_record(),
                    {dims, Uniform::uint1(PF_LOC_SOLVER_CG_STEP, cg_step)}});
    }
}

}  // namespace pf
