#include "sim/solvers/mgpcg/multigrid.h"

#include "solvers/common/solver_state.h"
#include "solvers/mgpcg/multigrid_limits.h"

namespace pf {

using gl::ProgramId;

std::string Multigrid::init(const gl::Api& gl, PassRunner& runner, SolveControl& control) {
    control_ = &control;
    glm::ivec3 dims = control.dims();
    levels_.clear();
    for (;;) {
        Level level;
        level.dims = dims;
        level.cells = uint32_t(dims.x * dims.y * dims.z);
        const bool fine = levels_.empty();
        level.record = fine ? control.record(0) : control.record(control.add_record(level.cells));
        const size_t bytes = size_t(level.cells) * 4;
        if (!fine) {
            level.type = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "mg_type");
            level.r = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "mg_r");
            level.e = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "mg_e");
        }
        const glm::ivec3 next = (dims + 1) / 2;
        const bool coarsest = level.cells <= PF_MG_COARSE_CELLS || glm::any(glm::lessThan(next, glm::ivec3(2))) ||
                              levels_.size() + 1 == PF_MG_MAX_LEVELS;
        if (!coarsest) level.tmp = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "mg_tmp");
        levels_.push_back(std::move(level));
        if (coarsest) break;
        dims = next;
    }
    if (levels_.back().cells > PF_MG_COARSE_CELLS)
        return "multigrid: the coarsest level has " + std::to_string(levels_.back().cells) + " cells (more than " +
               std::to_string(PF_MG_COARSE_CELLS) + ")";
    for (ProgramId id : {ProgramId::mg_smooth, ProgramId::mg_smooth_from_zero, ProgramId::mg_coarsen_types,
                         ProgramId::mg_residual, ProgramId::mg_restrict, ProgramId::mg_prolong, ProgramId::mg_coarse_solve}) {
        if (std::string error = runner.prepare(id); !error.empty()) return error;
    }
    return {};
}

Uniform Multigrid::coarse_dims(const Level& coarse) {
    return Uniform::ivec4(PF_LOC_SOLVER_COARSE_DIMS, coarse.dims.x, coarse.dims.y, coarse.dims.z, int(coarse.cells));
}

void Multigrid::begin(PassRunner& runner, StatId stat, const gl::Buffer& cell_type) {
    fine_type_ = &cell_type;
    for (size_t l = 0; l + 1 < levels_.size(); ++l) {
        runner.run({ProgramId::mg_coarsen_types, stat, 0,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_COARSE_TYPE, &levels_[l + 1].type}},
                    levels_[l + 1].record,
                    {SolveControl::dims_uniform(levels_[l].dims), coarse_dims(levels_[l + 1])}});
    }
}

void Multigrid::smooth(PassRunner& runner, StatId stat, size_t l, bool from_zero, bool red_first) {
    const Level& level = levels_[l];
    for (uint32_t half = 0; half < 2; ++half) {
        const ProgramId id = from_zero && half == 0 ? ProgramId::mg_smooth_from_zero : ProgramId::mg_smooth;
        runner.run({id, stat, 0,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &e_of(l)},
                     {PF_SLOT_SOLVER_STATE, &control_->state()}},
                    level.record,
                    {SolveControl::dims_uniform(level.dims),
                     Uniform::uint1(PF_LOC_SOLVER_COLOR, (half == 0) == red_first ? 0u : 1u),
                     Uniform::float1(PF_LOC_SOLVER_OMEGA, 1.0f)}});
    }
}

void Multigrid::vcycle(PassRunner& runner, StatId stat, size_t l) {
    const Level& level = levels_[l];
    const Uniform dims = SolveControl::dims_uniform(level.dims);
    if (l + 1 == levels_.size()) {
        runner.run({ProgramId::mg_coarse_solve, stat, PF_WORKGROUP_SIZE,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &e_of(l)},
                     {PF_SLOT_SOLVER_STATE, &control_->state()}},
                    {},
                    {dims}});
        return;
    }
    const Level& coarse = levels_[l + 1];
    for (uint32_t s = 0; s < kSmoothSweeps; ++s) smooth(runner, stat, l, s == 0, true);
    runner.run({ProgramId::mg_residual, stat, 0,
                {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &e_of(l)},
                 {PF_SLOT_MG_TMP, &level.tmp}},
                level.record,
                {dims}});
    runner.run({ProgramId::mg_restrict, stat, 0,
                {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_TMP, &level.tmp}, {PF_SLOT_MG_COARSE_TYPE, &coarse.type},
                 {PF_SLOT_MG_COARSE_R, &coarse.r}},
                coarse.record,
                {dims, coarse_dims(coarse)}});
    vcycle(runner, stat, l + 1);
    runner.run({ProgramId::mg_prolong, stat, 0,
                {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_E, &e_of(l)}, {PF_SLOT_MG_COARSE_TYPE, &coarse.type},
                 {PF_SLOT_MG_COARSE_E, &coarse.e}},
                level.record,
                {dims, coarse_dims(coarse)}});
    for (uint32_t s = 0; s < kSmoothSweeps; ++s) smooth(runner, stat, l, false, false);
}

void Multigrid::apply(PassRunner& runner, StatId stat, const gl::Buffer& cell_type, const gl::Buffer& r,
                      const gl::Buffer& z) {
    fine_type_ = &cell_type;
    fine_r_ = &r;
    fine_e_ = &z;
    vcycle(runner, stat, 0);
}

}  // namespace pf
