// The pass pipeline's own contracts: the uniform block declared once has the same member
// offsets in C++ and in the GL's std140 layout; every pass binds every storage slot and sets
// every explicit-location uniform its program uses (checked by the runner against the linked
// program); a pass that forgets one is caught.
#include <cstring>
#include <vector>

#include "api/handle.h"
#include "common/slots.h"
#include "gl/shader_source.h"
#include "sim/pass_runner.h"
#include "sim/sim_uniforms.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class PassPipeline : public GpuTest {};

TEST_F(PassPipeline, UniformOffsetsMatchTheGl) {
    pf_sim_desc d = test_desc(8, 8, 8);
    d.params.p2g = PF_P2G_FIXED_POINT;  // its p2g program is the one read below
    SimPtr handle = create(d);
    ASSERT_TRUE(handle);
    const Simulation& sim = *pf::entry(handle)->impl;
    const gl::Api& gl = sim.api();
    // p2g includes common/sim.glsl; every member is active there only if used, so ask the GL
    // for the block's members by name through the program interface.
    const GLuint program = sim.runner().program(gl::ProgramId::p2g);
    ASSERT_NE(program, 0u);
    size_t checked = 0;
    for (const UniformMember& m : kSimUniformMembers) {
        const std::string name = std::string("SimUniforms.") + m.name;
        const GLuint index = gl.GetProgramResourceIndex(program, GL_UNIFORM, name.c_str());
        if (index == GL_INVALID_INDEX) continue;  // optimised away in this kernel: std140 still fixes it
        const GLenum prop = GL_OFFSET;
        GLint offset = -1;
        gl.GetProgramResourceiv(program, GL_UNIFORM, index, 1, &prop, 1, nullptr, &offset);
        EXPECT_EQ(size_t(offset), m.offset) << m.name;
        ++checked;
    }
    // std140 keeps every member of a uniform block active, so all of them were compared.
    EXPECT_EQ(checked, std::size(kSimUniformMembers));
    GLint block_size = 0;
    const GLuint block = gl.GetProgramResourceIndex(program, GL_UNIFORM_BLOCK, "SimUniforms");
    ASSERT_NE(block, GL_INVALID_INDEX);
    const GLenum size_prop = GL_BUFFER_DATA_SIZE;
    gl.GetProgramResourceiv(program, GL_UNIFORM_BLOCK, block, 1, &size_prop, 1, nullptr, &block_size);
    EXPECT_EQ(size_t(block_size), sizeof(SimUniforms));
}

TEST_F(PassPipeline, EveryPassBindsEverySlotItsProgramUses) {
    pf_sim_desc d = test_desc(12, 10, 8);
    SimPtr handle = create(d);
    ASSERT_TRUE(handle);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.6f, 0.5f, 0.8f};
    ASSERT_EQ(pf_fill_box(handle.get(), lo, hi, nullptr), PF_OK);
    const float c[3] = {0.3f, 0.3f, 0.3f}, dv[3] = {1, 0, 0};
    ASSERT_EQ(pf_push(handle.get(), c, 0.3f, dv), PF_OK);
    for (uint32_t solver = 0; solver < PF_PRESSURE_SOLVER_COUNT; ++solver) {
        for (uint32_t separation : {0u, 1u}) {
            for (uint32_t transfer = 0; transfer < PF_TRANSFER_COUNT; ++transfer) {
                for (uint32_t advection = 0; advection < PF_ADVECTION_COUNT; ++advection) {
                    pf_sim_params p = sized_params();
                    ASSERT_EQ(pf_get_params(handle.get(), &p), PF_OK);
                    p.pressure_solver = pf_pressure_solver(solver);
                    p.separation = separation;
                    p.flip_ratio = separation ? 0.95f : 0.0f;  // both PIC/FLIP G2P permutations
                    p.transfer = pf_transfer(transfer);
                    p.p2g = pf_p2g((transfer + advection + solver) % PF_P2G_COUNT);  // both schemes, every transfer
                    p.advection = pf_advection(advection);
                    ASSERT_EQ(pf_set_params(handle.get(), &p), PF_OK) << last_log();
                    for (int i = 0; i < 3; ++i) ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
                }
            }
        }
    }
    ASSERT_EQ(pf_clear_particles(handle.get()), PF_OK);
    EXPECT_EQ(pf::entry(handle)->impl->runner().binding_errors(), 0u) << last_log();
}

// The runner puts GL_COMMAND_BARRIER_BIT only after programs listed as writing indirect
// records; a program that writes them unlisted would let a later indirect dispatch read stale
// workgroup counts. Every program's expanded source is scanned for the three ways to write them.
// Whether `text` calls function `name` (an occurrence that is not its definition).
bool calls(const std::string& text, const std::string& name) {
    for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
        if (at < 5 || text.compare(at - 5, 5, "void ") != 0) return true;
    }
    return false;
}

TEST(PassPipelineSource, EveryProgramThatWritesIndirectRecordsIsListed) {
    size_t writers = 0;
    for (size_t i = 0; i < size_t(gl::ProgramId::count); ++i) {
        const gl::ProgramInfo& info = gl::program_info(gl::ProgramId(i));
        if (info.fragment) continue;
        const gl::ExpandedSource src = gl::expand_shader(info.file, info.defines);
        ASSERT_TRUE(src.error.empty()) << info.id << ": " << src.error;
        const bool writes = calls(src.text, "stop_solve_in(") ||
                            src.text.find("state[PF_SOLVER_SCALARS + w] =") != std::string::npos ||
                            src.text.find("state[PF_WW_GROUPS] =") != std::string::npos ||
                            src.text.find("state[PF_VISC_FACE_RECORD] =") != std::string::npos;
        EXPECT_EQ(writes, PassRunner::writes_indirect_records(gl::ProgramId(i))) << info.id;
        writers += writes;
    }
    // begin, check and report (one source); CG's scalar steps in the last workgroup of init and
    // update without a stored z (2 + 2), of matvec (3), of the z sums (cg_zstats, mg_smooth_zstats),
    // each also as its one-invocation-a-cell permutation (9 more); the whitewater's commit (its
    // per-particle dispatch record); the viscosity's setup (its records' full sizes) and its three
    // passes that end in a CG scalar step; a pair solve's begin, report, matvec and z sums (5),
    // three with their one-invocation-a-cell permutation (3 more).
    EXPECT_EQ(writers, 34u);
}

TEST_F(PassPipeline, AMissingBindingIsCaught) {
    SimPtr handle = create(test_desc(8, 8, 8));
    ASSERT_TRUE(handle);
    const Simulation& sim = *pf::entry(handle)->impl;
    gl::Buffer uniforms(sim.api(), sizeof(SimUniforms), GL_DYNAMIC_DRAW, "test_uniforms");
    gl::Buffer a(sim.api(), 64 * 4, GL_DYNAMIC_COPY, "test_a"), b(sim.api(), 64 * 4, GL_DYNAMIC_COPY, "test_b");
    Log log;
    PassRunner runner(sim.api(), log, uniforms, PF_UBO_SIM);
    const StatId stat = runner.add_stat("classify", PF_PASS_CLASSIFY);
    ASSERT_EQ(runner.prepare(gl::ProgramId::classify), "");
    runner.run({gl::ProgramId::classify, stat, 64, {{PF_SLOT_CELL_COUNT, &a}, {PF_SLOT_CELL_TYPE, &b}}});
    EXPECT_EQ(runner.binding_errors(), 0u);
    runner.run({gl::ProgramId::classify, stat, 64, {{PF_SLOT_CELL_COUNT, &a}}});  // cell_type unbound
    EXPECT_EQ(runner.binding_errors(), 1u);
    // A pass whose program was never prepared is refused, not dispatched.
    runner.run({gl::ProgramId::advect, stat, 64, {}});
    EXPECT_EQ(runner.binding_errors(), 2u);
    // The fill kernel reads two uniforms: a pass that sets one of them is caught (the other
    // would keep whatever value an earlier pass left in the program).
    ASSERT_EQ(runner.prepare(gl::ProgramId::fill), "");
    runner.run({gl::ProgramId::fill, stat, 64, {{PF_SLOT_FILL, &a}}, {},
                {Uniform::uint1(PF_LOC_FILL_COUNT, 64), Uniform::uint1(PF_LOC_FILL_VALUE, 7)}});
    EXPECT_EQ(runner.binding_errors(), 2u);
    runner.run({gl::ProgramId::fill, stat, 64, {{PF_SLOT_FILL, &a}}, {}, {Uniform::uint1(PF_LOC_FILL_COUNT, 64)}});
    EXPECT_EQ(runner.binding_errors(), 3u);
    // More uniforms than a pass holds are refused, not written past the pass's storage.
    const Uniform u = Uniform::uint1(PF_LOC_FILL_COUNT, 64);
    runner.run({gl::ProgramId::fill, stat, 64, {{PF_SLOT_FILL, &a}}, {}, {u, u, u, u, u, u, u}});
    EXPECT_EQ(runner.binding_errors(), 4u);
    // Two buffers on one slot are refused: the later would take the earlier's place, and the
    // kernel's blocks on that slot would read or write it (APIC's G2P with obstacles once wrote
    // its affine vectors into the cell types that way).
    runner.run({gl::ProgramId::classify, stat, 64, {{PF_SLOT_CELL_COUNT, &a}, {PF_SLOT_CELL_TYPE, &b}, {PF_SLOT_CELL_TYPE, &a}}});
    EXPECT_EQ(runner.binding_errors(), 5u);
}

// Passes and copies run under a Recording are kept, not issued; run_interleaved issues both
// recordings, each in its own order (a copy after the fill it reads).
TEST_F(PassPipeline, RecordedPassesRunWhenIssuedInterleaved) {
    SimPtr handle = create(test_desc(8, 8, 8));
    ASSERT_TRUE(handle);
    const Simulation& sim = *pf::entry(handle)->impl;
    gl::Buffer uniforms(sim.api(), sizeof(SimUniforms), GL_DYNAMIC_DRAW, "test_uniforms");
    const std::vector<uint32_t> zeros(64, 0u);
    gl::Buffer a(sim.api(), 64 * 4, GL_DYNAMIC_COPY, "test_a"), b(sim.api(), 64 * 4, GL_DYNAMIC_COPY, "test_b"),
        c(sim.api(), 64 * 4, GL_DYNAMIC_COPY, "test_c");
    for (gl::Buffer* x : {&a, &b, &c}) x->upload(0, 64 * 4, zeros.data());
    Log log;
    PassRunner runner(sim.api(), log, uniforms, PF_UBO_SIM);
    const StatId stat = runner.add_stat("fill", PF_PASS_CLEAR);
    ASSERT_EQ(runner.prepare(gl::ProgramId::fill), "");
    PassRunner::Recorded first, second;
    {
        const PassRunner::Recording recording(runner, first);
        runner.fill(a, 64, 7u, stat);
        runner.copy(a, c, 64 * 4);
    }
    {
        const PassRunner::Recording recording(runner, second);
        runner.fill(b, 64, 9u, stat);
    }
    ASSERT_EQ(first.size(), 2u);
    ASSERT_EQ(second.size(), 1u);
    const auto word = [](const gl::Buffer& x) {
        uint32_t w = 0;
        x.download(63 * 4, 4, &w);
        return w;
    };
    EXPECT_EQ(word(a), 0u) << "a recorded pass ran";
    EXPECT_EQ(word(c), 0u) << "a recorded copy ran";
    runner.run_interleaved(first, second);
    EXPECT_EQ(word(a), 7u);
    EXPECT_EQ(word(b), 9u);
    EXPECT_EQ(word(c), 7u) << "the copy did not wait for the fill it reads";
    EXPECT_EQ(runner.binding_errors(), 0u);
}

}  // namespace
}  // namespace pf::test
