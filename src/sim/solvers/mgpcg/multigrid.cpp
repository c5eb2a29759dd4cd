#include "sim/solvers/mgpcg/multigrid.h"

#include "solvers/common/solver_state.h"
#include "solvers/mgpcg/multigrid_limits.h"

namespace pf {

using gl::ProgramId;

std::string Multigrid::init(const gl::Api& gl, PassRunner& runner, SolveControl& control) {
    gl_ = &gl;
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
            level.type = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY);
            level.r = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY);
            level.e = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY);
        }
        const glm::ivec3 next = (dims + 1) / 2;
        const bool coarsest = level.cells <= PF_MG_COARSE_CELLS || glm::any(glm::lessThan(next, glm::ivec3(2))) ||
                              levels_.size() + 1 == PF_MG_MAX_LEVELS;
        if (!coarsest) level.tmp = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY);
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
    gl.ProgramUniform1f(runner.program(ProgramId::mg_smooth), PF_LOC_SOLVER_OMEGA, 1.0f);
    gl.ProgramUniform1f(runner.program(ProgramId::mg_smooth_from_zero), PF_LOC_SOLVER_OMEGA, 1.0f);
    return {};
}

void Multigrid::set_dims(GLuint program, const Level& level, const Level* coarse) const {
    control_->set_dims(program, level.dims);
    if (coarse) {
        gl_->ProgramUniform4i(program, PF_LOC_SOLVER_COARSE_DIMS, coarse->dims.x, coarse->dims.y, coarse->dims.z,
                              int(coarse->cells));
    }
}

void Multigrid::begin(PassRunner& runner, StatId stat, const gl::Buffer& cell_type) {
    fine_type_ = &cell_type;
    const GLuint program = runner.program(ProgramId::mg_coarsen_types);
    for (size_t l = 0; l + 1 < levels_.size(); ++l) {
        set_dims(program, levels_[l], &levels_[l + 1]);
        runner.run({ProgramId::mg_coarsen_types, stat, 0,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_COARSE_TYPE, &levels_[l + 1].type}},
                    levels_[l + 1].record});
    }
}

void Multigrid::smooth(PassRunner& runner, StatId stat, size_t l, bool from_zero, bool red_first) {
    const Level& level = levels_[l];
    for (uint32_t half = 0; half < 2; ++half) {
        const ProgramId id = from_zero && half == 0 ? ProgramId::mg_smooth_from_zero : ProgramId::mg_smooth;
        const GLuint program = runner.program(id);
        set_dims(program, level, nullptr);
        gl_->ProgramUniform1ui(program, PF_LOC_SOLVER_COLOR, (half == 0) == red_first ? 0u : 1u);
        runner.run({id, stat, 0,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &e_of(l)},
                     {PF_SLOT_SOLVER_STATE, &control_->state()}},
                    level.record});
    }
}

void Multigrid::vcycle(PassRunner& runner, StatId stat, size_t l) {
    const Level& level = levels_[l];
    if (l + 1 == levels_.size()) {
        const GLuint program = runner.program(ProgramId::mg_coarse_solve);
        set_dims(program, level, nullptr);
        runner.run({ProgramId::mg_coarse_solve, stat, PF_WORKGROUP_SIZE,
                    {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &e_of(l)},
                     {PF_SLOT_SOLVER_STATE, &control_->state()}}});
        return;
    }
    const Level& coarse = levels_[l + 1];
    for (uint32_t s = 0; s < kSmoothSweeps; ++s) smooth(runner, stat, l, s == 0, true);
    set_dims(runner.program(ProgramId::mg_residual), level, nullptr);
    runner.run({ProgramId::mg_residual, stat, 0,
                {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_R, &r_of(l)}, {PF_SLOT_MG_E, &e_of(l)},
                 {PF_SLOT_MG_TMP, &level.tmp}},
                level.record});
    set_dims(runner.program(ProgramId::mg_restrict), level, &coarse);
    runner.run({ProgramId::mg_restrict, stat, 0,
                {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_TMP, &level.tmp}, {PF_SLOT_MG_COARSE_TYPE, &coarse.type},
                 {PF_SLOT_MG_COARSE_R, &coarse.r}},
                coarse.record});
    vcycle(runner, stat, l + 1);
    set_dims(runner.program(ProgramId::mg_prolong), level, &coarse);
    runner.run({ProgramId::mg_prolong, stat, 0,
                {{PF_SLOT_MG_TYPE, &type_of(l)}, {PF_SLOT_MG_E, &e_of(l)}, {PF_SLOT_MG_COARSE_TYPE, &coarse.type},
                 {PF_SLOT_MG_COARSE_E, &coarse.e}},
                level.record});
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
