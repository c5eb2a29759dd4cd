#include "sim/pass_runner.h"

#include <algorithm>
#include <array>

#include "common/slots.h"
#include "gl/debug.h"

namespace pf {

PassRunner::PassRunner(const gl::Api& gl, const Log& log, const gl::Buffer& uniforms, GLuint uniform_slot,
                       gl::ProgramBinaryCache* binaries)
    : gl_(gl), log_(log), uniforms_(uniforms), uniform_slot_(uniform_slot), programs_(gl, binaries), timers_(gl),
      used_slots_(size_t(gl::ProgramId::count), 0u), used_uniforms_(size_t(gl::ProgramId::count), 0u),
      reported_(size_t(gl::ProgramId::count), false) {
    gl_.GetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &max_groups_x_);
}

StatId PassRunner::add_stat(const std::string& name, pf_pass group) {
    for (size_t i = 0; i < stats_.size(); ++i) {
        if (stats_[i].name == name) return StatId(i);
    }
    stats_.push_back(Stat{name, group, 0, "pflip/" + name});
    return StatId(stats_.size() - 1);
}

std::string PassRunner::prepare(gl::ProgramId id) {
    if (programs_.built(id)) return {};
    std::string error;
    const GLuint p = programs_.get(id, error);
    if (!p) return error;
    // The storage blocks the linker kept, and the slot each is bound to.
    GLint blocks = 0;
    gl_.GetProgramInterfaceiv(p, GL_SHADER_STORAGE_BLOCK, GL_ACTIVE_RESOURCES, &blocks);
    uint32_t mask = 0;
    for (GLint b = 0; b < blocks; ++b) {
        const GLenum prop = GL_BUFFER_BINDING;
        GLint slot = 0;
        gl_.GetProgramResourceiv(p, GL_SHADER_STORAGE_BLOCK, GLuint(b), 1, &prop, 1, nullptr, &slot);
        if (slot >= 0 && slot < 32) mask |= 1u << slot;
    }
    used_slots_[size_t(id)] = mask;
    // The default-block uniforms the linker kept, by explicit location (block members have none).
    // Samplers are bound to units by layout(binding) and take the textures a pass names.
    GLint uniforms = 0;
    gl_.GetProgramInterfaceiv(p, GL_UNIFORM, GL_ACTIVE_RESOURCES, &uniforms);
    uint32_t locations = 0;
    for (GLint u = 0; u < uniforms; ++u) {
        const GLenum props[3] = {GL_LOCATION, GL_BLOCK_INDEX, GL_TYPE};
        GLint values[3] = {-1, -1, 0};
        gl_.GetProgramResourceiv(p, GL_UNIFORM, GLuint(u), 3, props, 3, nullptr, values);
        if (values[2] == GL_SAMPLER_3D) continue;
        if (values[1] == -1 && values[0] >= 0 && values[0] < 32) locations |= 1u << values[0];
    }
    used_uniforms_[size_t(id)] = locations;
    return {};
}

void PassRunner::begin_step(uint64_t step, uint32_t substeps) {
    for (Stat& s : stats_) s.dispatches = 0;
    timers_.begin_step(step, substeps);
    step_open_ = true;
    pair_open_ = false;
}

void PassRunner::end_step() {
    if (pair_open_) timers_.end_pass();
    timers_.end_step();
    pair_open_ = false;
    step_open_ = false;
}

StatId PassRunner::kernel_stat(StatId stat, gl::ProgramId program) {
    if (stat >= stats_.size()) return stat;
    const uint32_t key = uint32_t(stat) << 16 | uint32_t(program);
    const auto found = kernel_stats_.find(key);
    if (found != kernel_stats_.end()) return found->second;
    const StatId id = add_stat(stats_[stat].name + ":" + gl::program_info(program).id, stats_[stat].group);
    kernel_stats_.emplace(key, id);
    return id;
}

void PassRunner::open_timing(StatId stat) {
    if (step_open_ && (!pair_open_ || open_stat_ != stat)) {
        if (pair_open_) timers_.end_pass();
        timers_.begin_pass(int(stat));
        pair_open_ = true;
        open_stat_ = stat;
    }
}

void PassRunner::run(const Pass& pass) {
    if (!pass.indirect.buffer && pass.invocations == 0) return;
    StatId stat = override_ != kNoOverride ? override_ : pass.stat;
    if (recording_) {
        RecordedOp op{RecordedOp::Kind::pass, pass};
        op.pass.stat = stat;
        recording_->push_back(op);
        return;
    }
    if (kernel_timing_ && step_open_) stat = kernel_stat(stat, pass.program);
    // Outside a step (creation, pf_clear_particles) passes run untimed and uncounted.
    open_timing(stat);
    if (step_open_ && stat < stats_.size()) ++stats_[stat].dispatches;
    issue(pass, stat, true, records_written_);
}

void PassRunner::issue(const Pass& pass, StatId stat, bool barrier, bool& records_written) {
    const GLuint program = programs_.built(pass.program);
    const size_t pid = size_t(pass.program);
    const uint32_t missing = used_slots_[pid] & ~pass.binds.mask();
    const uint32_t unset = used_uniforms_[pid] & ~pass.uniforms.mask();
    const bool overflow = pass.binds.overflow() || pass.uniforms.overflow();
    const uint32_t twice = pass.binds.twice();
    if (!program || missing || unset || overflow || twice) {
        ++binding_errors_;
        if (!reported_[pid]) {
            reported_[pid] = true;
            std::string what = !program   ? " was run before its program was prepared"
                               : overflow ? " names more bindings or uniforms than a pass holds"
                               : twice    ? " binds two buffers to one storage slot (mask " + gl::hex(twice) + ")"
                               : missing  ? " leaves storage slots unbound (mask " + gl::hex(missing) + ")"
                                          : " leaves uniform locations unset (mask " + gl::hex(unset) + ")";
            log_.error(PF_ERROR_INVALID_STATE, std::string("internal: pass ") + gl::program_info(pass.program).id + what);
        }
        if (!program || overflow || twice) return;
    }
    set_uniforms(program, pid, pass.uniforms);
    // Every pass may read what earlier passes wrote; an indirect one also reads its workgroup
    // counts, which the record-writing programs change (the barrier goes before the dispatch,
    // so a copy or readback after the last pass brings its own: copy() and the step's end).
    const bool command = pass.indirect.buffer && records_written;
    if (barrier || command) gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | (command ? GL_COMMAND_BARRIER_BIT : 0));
    if (command) records_written = false;
    if (writes_indirect_records(pass.program)) records_written = true;
    const gl::DebugGroup debug_group(gl_, stat < stats_.size() ? stats_[stat].debug_group.c_str() : "pflip/pass");
    gl_.UseProgram(program);
    gl_.BindBufferBase(GL_UNIFORM_BUFFER, uniform_slot_, uniforms_.id());
    for (const Bind& b : pass.binds) gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, b.slot, b.buffer->id());
    // Textures: bound for this dispatch only, the engine's bindings of those units put back after.
    struct Saved {
        GLint texture = 0, sampler = 0;
    };
    std::array<Saved, Textures::kMaxTextures> saved{};
    GLint active = 0;
    if (!pass.textures.empty()) {
        gl_.GetIntegerv(GL_ACTIVE_TEXTURE, &active);
        size_t i = 0;
        for (const Textures::Bind& t : pass.textures) {
            gl_.ActiveTexture(GL_TEXTURE0 + t.unit);
            gl_.GetIntegerv(GL_TEXTURE_BINDING_3D, &saved[i].texture);
            gl_.GetIntegerv(GL_SAMPLER_BINDING, &saved[i].sampler);
            gl_.BindTexture(GL_TEXTURE_3D, t.texture);
            gl_.BindSampler(t.unit, t.sampler);
            ++i;
        }
    }
    if (pass.indirect.buffer) {
        gl_.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, pass.indirect.buffer->id());
        gl_.DispatchComputeIndirect(GLintptr(pass.indirect.offset));
    } else {
        const Workgroups groups = workgroups_for(pass.invocations, max_groups_x_);
        gl_.DispatchCompute(groups.x, groups.y, 1);
    }
    if (!pass.textures.empty()) {
        size_t i = 0;
        for (const Textures::Bind& t : pass.textures) {
            gl_.ActiveTexture(GL_TEXTURE0 + t.unit);
            gl_.BindTexture(GL_TEXTURE_3D, GLuint(saved[i].texture));
            gl_.BindSampler(t.unit, GLuint(saved[i].sampler));
            ++i;
        }
        gl_.ActiveTexture(GLenum(active));
    }
}

void PassRunner::run_interleaved(const Recorded& a, const Recorded& b) {
    for (const Recorded* stream : {&a, &b}) {
        const auto first = std::find_if(stream->begin(), stream->end(),
                                        [](const RecordedOp& op) { return op.kind == RecordedOp::Kind::pass; });
        if (first == stream->end()) continue;
        open_timing(first->pass.stat);
        break;
    }
    // Each stream's own "a record may have changed" (the other's records are not its concern);
    // the barrier before a pair carries the command bit when either needs it.
    bool written[2] = {records_written_, records_written_};
    const Recorded* streams[2] = {&a, &b};
    for (size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
        const bool command = written[0] || written[1];
        gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | (command ? GL_COMMAND_BARRIER_BIT : 0));
        if (command) written[0] = written[1] = false;
        for (int s = 0; s < 2; ++s) {
            if (i >= streams[s]->size()) continue;
            const RecordedOp& op = (*streams[s])[i];
            if (op.kind == RecordedOp::Kind::copy) {
                copy(*op.copy_src, op.copy_src_offset, *op.copy_dst, op.copy_dst_offset, op.copy_bytes);
                continue;
            }
            if (step_open_ && op.pass.stat < stats_.size()) ++stats_[op.pass.stat].dispatches;
            issue(op.pass, op.pass.stat, false, written[s]);
        }
    }
    records_written_ = written[0] || written[1];
}

bool PassRunner::writes_indirect_records(gl::ProgramId id) {
    switch (id) {
        case gl::ProgramId::solver_begin:
        case gl::ProgramId::solver_check:
        case gl::ProgramId::solver_report:  // check.comp: its source has the check's stop_solve_in()
        // The CG passes whose last workgroup runs a scalar step, which may stop the solve.
        case gl::ProgramId::cg_init_none:
        case gl::ProgramId::cg_init_jacobi:
        case gl::ProgramId::cg_update_none:
        case gl::ProgramId::cg_update_jacobi:
        case gl::ProgramId::cg_matvec_none:
        case gl::ProgramId::cg_matvec_jacobi:
        case gl::ProgramId::cg_matvec_stored:
        case gl::ProgramId::cg_zstats:
        case gl::ProgramId::mg_smooth_zstats:
        case gl::ProgramId::cg_init_none_cells:
        case gl::ProgramId::cg_init_jacobi_cells:
        case gl::ProgramId::cg_update_none_cells:
        case gl::ProgramId::cg_update_jacobi_cells:
        case gl::ProgramId::cg_matvec_none_cells:
        case gl::ProgramId::cg_matvec_jacobi_cells:
        case gl::ProgramId::cg_matvec_stored_cells:
        case gl::ProgramId::cg_zstats_cells:
        case gl::ProgramId::mg_smooth_zstats_cells:
        // A pair solve's (two problems in the same passes).
        case gl::ProgramId::solver_begin_pair:
        case gl::ProgramId::solver_report_pair:
        case gl::ProgramId::cg_matvec_stored_pair:
        case gl::ProgramId::cg_zstats_pair:
        case gl::ProgramId::mg_smooth_zstats_pair:
        case gl::ProgramId::cg_matvec_stored_pair_cells:
        case gl::ProgramId::cg_zstats_pair_cells:
        case gl::ProgramId::mg_smooth_zstats_pair_cells:
        case gl::ProgramId::ww_commit:
        // The viscosity's setup (its records' full sizes) and its passes ending in a scalar step.
        case gl::ProgramId::visc_setup:
        case gl::ProgramId::visc_apply_start:
        case gl::ProgramId::visc_apply:
        case gl::ProgramId::visc_update: return true;
        default: return false;
    }
}

void PassRunner::copy(const gl::Buffer& src, size_t src_offset, const gl::Buffer& dst, size_t dst_offset, size_t bytes) {
    if (bytes == 0) return;
    if (recording_) {
        RecordedOp op{RecordedOp::Kind::copy, Pass{gl::ProgramId::fill, 0, 0, {}}};
        op.copy_src = &src, op.copy_dst = &dst;
        op.copy_src_offset = src_offset, op.copy_dst_offset = dst_offset, op.copy_bytes = bytes;
        recording_->push_back(op);
        return;
    }
    gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // copies read what shaders wrote
    gl_.BindBuffer(GL_COPY_READ_BUFFER, src.id());
    gl_.BindBuffer(GL_COPY_WRITE_BUFFER, dst.id());
    gl_.CopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, GLintptr(src_offset), GLintptr(dst_offset),
                          GLsizeiptr(bytes));
}

void PassRunner::set_uniforms(GLuint program, size_t pid, const Uniforms& uniforms) {
    for (const Uniform& u : uniforms) {
        if (u.location < 0 || u.location >= 32 || !(used_uniforms_[pid] & (1u << u.location))) continue;
        switch (u.kind) {
            case Uniform::Kind::uint1: gl_.ProgramUniform1ui(program, u.location, u.value.u); break;
            case Uniform::Kind::float1: gl_.ProgramUniform1f(program, u.location, u.value.f); break;
            case Uniform::Kind::ivec4:
                gl_.ProgramUniform4i(program, u.location, u.value.i[0], u.value.i[1], u.value.i[2], u.value.i[3]);
                break;
            case Uniform::Kind::vec4:
                gl_.ProgramUniform4f(program, u.location, u.value.v[0], u.value.v[1], u.value.v[2], u.value.v[3]);
                break;
        }
    }
}

void PassRunner::fill(const gl::Buffer& buffer, uint32_t words, uint32_t value, StatId stat) {
    run({gl::ProgramId::fill, stat, words, {{PF_SLOT_FILL, &buffer}}, {},
         {Uniform::uint1(PF_LOC_FILL_COUNT, words), Uniform::uint1(PF_LOC_FILL_VALUE, value)}});
}

}  // namespace pf
