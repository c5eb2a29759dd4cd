// The effects mechanism from the inside (docs/design.md §9): an effect that is off builds no
// program; turning one on builds exactly its programs, once; every effect pass binds every
// slot and sets every uniform its program uses, under every solver, transfer and advection.
#include "api/handle.h"
#include "gl/shader_source.h"
#include "sim/pass_runner.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class EffectsPipeline : public GpuTest {};

const gl::ProgramId kForceFieldPrograms[] = {gl::ProgramId::force_fields};
// With G2P's permutation whose stencil stops at obstacles (this simulation's FLIP; Euler has none).
const gl::ProgramId kObstaclePrograms[] = {gl::ProgramId::obstacle_cells, gl::ProgramId::obstacle_faces,
                                           gl::ProgramId::obstacle_push, gl::ProgramId::obstacle_forces,
                                           gl::ProgramId::g2p_flip_walls};
const gl::ProgramId kEmitterPrograms[] = {gl::ProgramId::emit, gl::ProgramId::emit_apic, gl::ProgramId::emit_commit};
const gl::ProgramId kDomainPrograms[] = {gl::ProgramId::domain_forces};
const gl::ProgramId kVorticityPrograms[] = {gl::ProgramId::vorticity, gl::ProgramId::confinement_force};
const gl::ProgramId kWhitewaterPrograms[] = {gl::ProgramId::ww_fraction, gl::ProgramId::ww_advect, gl::ProgramId::ww_emit,
                                             gl::ProgramId::ww_commit, gl::ProgramId::ww_copy};
const gl::ProgramId kViscosityPrograms[] = {gl::ProgramId::visc_setup,       gl::ProgramId::visc_stress_start,
                                            gl::ProgramId::visc_stress,      gl::ProgramId::visc_apply_start,
                                            gl::ProgramId::visc_apply,       gl::ProgramId::visc_update,
                                            gl::ProgramId::visc_couple_update};
const gl::ProgramId kSurfaceTensionPrograms[] = {gl::ProgramId::st_fraction, gl::ProgramId::st_fraction_float,
                                                 gl::ProgramId::st_liquid, gl::ProgramId::st_force};
const gl::ProgramId kSinkPrograms[] = {gl::ProgramId::sink_mark, gl::ProgramId::sink_lists, gl::ProgramId::sink_move,
                                       gl::ProgramId::sink_move_apic};

template <size_t N>
size_t built(const PassRunner& r, const gl::ProgramId (&ids)[N]) {
    size_t n = 0;
    for (gl::ProgramId id : ids) n += r.program(id) != 0;
    return n;
}

TEST_F(EffectsPipeline, OffEffectsBuildNothingAndTurningOneOnBuildsOnlyItsPrograms) {
    pf_sim_desc d = test_desc(12, 10, 8);
    SimPtr handle = create(d);
    ASSERT_TRUE(handle);
    const PassRunner& r = pf::entry(handle)->impl->runner();
    const float lo[3] = {0, 0, 0}, hi[3] = {0.6f, 0.5f, 0.8f};
    ASSERT_EQ(pf_fill_box(handle.get(), lo, hi, nullptr), PF_OK);
    for (int i = 0; i < 2; ++i) ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
    const uint32_t core = r.programs_built();
    EXPECT_EQ(built(r, kForceFieldPrograms), 0u);
    EXPECT_EQ(built(r, kObstaclePrograms), 0u);
    EXPECT_EQ(built(r, kEmitterPrograms), 0u);
    EXPECT_EQ(built(r, kSinkPrograms), 0u);
    EXPECT_EQ(built(r, kDomainPrograms), 0u);
    EXPECT_EQ(built(r, kVorticityPrograms), 0u);
    EXPECT_EQ(built(r, kViscosityPrograms), 0u);
    EXPECT_EQ(built(r, kSurfaceTensionPrograms), 0u);
    // Objects of an effect that is off are kept on the host only.
    pf_obstacle o = pf_default_obstacle();
    o.position[0] = o.position[1] = o.position[2] = 0.4f;
    ASSERT_EQ(pf_add_obstacle(handle.get(), &o, nullptr), PF_OK);
    ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
    EXPECT_EQ(r.programs_built(), core);

    ASSERT_EQ(pf_set_features(handle.get(), PF_FEATURE_FORCE_FIELDS), PF_OK);
    EXPECT_EQ(r.programs_built(), core + std::size(kForceFieldPrograms));
    EXPECT_EQ(built(r, kForceFieldPrograms), std::size(kForceFieldPrograms));
    EXPECT_EQ(built(r, kObstaclePrograms), 0u);
    ASSERT_EQ(pf_set_features(handle.get(), PF_FEATURE_OBSTACLES), PF_OK);
    EXPECT_EQ(r.programs_built(), core + std::size(kForceFieldPrograms) + std::size(kObstaclePrograms));
    EXPECT_EQ(built(r, kObstaclePrograms), std::size(kObstaclePrograms));
    EXPECT_EQ(built(r, kEmitterPrograms) + built(r, kSinkPrograms), 0u);
    ASSERT_EQ(pf_set_features(handle.get(), PF_FEATURE_EMITTERS), PF_OK);
    EXPECT_EQ(built(r, kEmitterPrograms), std::size(kEmitterPrograms));
    EXPECT_EQ(built(r, kSinkPrograms), 0u);
    ASSERT_EQ(pf_set_features(handle.get(), PF_FEATURE_SINKS), PF_OK);
    EXPECT_EQ(built(r, kSinkPrograms), std::size(kSinkPrograms));
    EXPECT_EQ(built(r, kDomainPrograms), 0u);
    ASSERT_EQ(pf_set_features(handle.get(), PF_FEATURE_DOMAIN_MOTION), PF_OK);
    EXPECT_EQ(built(r, kDomainPrograms), std::size(kDomainPrograms));
    EXPECT_EQ(built(r, kVorticityPrograms), 0u);
    ASSERT_EQ(pf_set_features(handle.get(), PF_FEATURE_VORTICITY_CONFINEMENT), PF_OK);
    EXPECT_EQ(built(r, kVorticityPrograms), std::size(kVorticityPrograms));
    EXPECT_EQ(built(r, kWhitewaterPrograms), 0u);
    ASSERT_EQ(pf_set_features(handle.get(), PF_FEATURE_WHITEWATER), PF_OK);
    EXPECT_EQ(built(r, kWhitewaterPrograms), std::size(kWhitewaterPrograms));
    EXPECT_EQ(built(r, kViscosityPrograms), 0u);
    ASSERT_EQ(pf_set_features(handle.get(), PF_FEATURE_VISCOSITY), PF_OK);
    EXPECT_EQ(built(r, kViscosityPrograms), std::size(kViscosityPrograms));
    EXPECT_EQ(built(r, kSurfaceTensionPrograms), 0u);
    ASSERT_EQ(pf_set_features(handle.get(), PF_FEATURE_SURFACE_TENSION), PF_OK);
    EXPECT_EQ(built(r, kSurfaceTensionPrograms), std::size(kSurfaceTensionPrograms));
    const size_t all = core + std::size(kForceFieldPrograms) + std::size(kObstaclePrograms) +
                       std::size(kEmitterPrograms) + std::size(kSinkPrograms) + std::size(kDomainPrograms) +
                       std::size(kVorticityPrograms) + std::size(kWhitewaterPrograms) + std::size(kViscosityPrograms) +
                       std::size(kSurfaceTensionPrograms);
    EXPECT_EQ(r.programs_built(), all);
    // Off and on again: nothing is rebuilt.
    ASSERT_EQ(pf_set_features(handle.get(), 0), PF_OK);
    ASSERT_EQ(pf_set_features(handle.get(), PF_FEATURE_ALL), PF_OK);
    EXPECT_EQ(r.programs_built(), all);
    ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
    EXPECT_EQ(r.binding_errors(), 0u) << last_log();
}

TEST_F(EffectsPipeline, EveryEffectPassBindsEverySlotItsProgramUses) {
    pf_sim_desc d = test_desc(12, 10, 8);
    d.features = PF_FEATURE_ALL;
    SimPtr handle = create(d);
    ASSERT_TRUE(handle);
    pf_obstacle o = pf_default_obstacle();
    o.shape = PF_OBSTACLE_SPHERE;
    o.position[0] = 0.6f, o.position[1] = 0.2f, o.position[2] = 0.4f;
    ASSERT_EQ(pf_add_obstacle(handle.get(), &o, nullptr), PF_OK);
    pf_force_field f = pf_default_force_field();
    f.type = PF_FORCE_FIELD_POINT;
    f.position[0] = 0.5f, f.position[1] = 0.3f, f.position[2] = 0.4f;
    f.strength = 5.0f;
    ASSERT_EQ(pf_add_force_field(handle.get(), &f, nullptr), PF_OK);
    pf_emitter e = pf_default_emitter();
    e.position[0] = 0.3f, e.position[1] = 0.4f, e.position[2] = 0.2f;
    e.radius = 0.05f;
    e.rate = 600.0f;  // 10 particles a frame
    ASSERT_EQ(pf_add_emitter(handle.get(), &e, nullptr), PF_OK);
    pf_sink k = pf_default_sink();
    k.position[0] = 0.05f, k.position[1] = 0.05f, k.position[2] = 0.05f;
    ASSERT_EQ(pf_add_sink(handle.get(), &k, nullptr), PF_OK);
    pf_domain_motion m = pf_default_domain_motion();
    m.angular_velocity[1] = 0.5f;  // a turning domain: its pass runs every substep
    ASSERT_EQ(pf_set_domain_motion(handle.get(), &m), PF_OK);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.5f, 0.5f, 0.8f};
    ASSERT_EQ(pf_fill_box(handle.get(), lo, hi, nullptr), PF_OK);
    // The effect passes bind the same buffers whatever the scheme; six configurations take
    // every solver, transfer, advection and P2G scheme once.
    for (uint32_t i = 0; i < 6; ++i) {
        pf_sim_params p = sized_params();
        ASSERT_EQ(pf_get_params(handle.get(), &p), PF_OK);
        p.pressure_solver = pf_pressure_solver(i % PF_PRESSURE_SOLVER_COUNT);
        p.transfer = pf_transfer(i % PF_TRANSFER_COUNT);
        p.advection = pf_advection(i % PF_ADVECTION_COUNT);
        p.p2g = pf_p2g((i / 2) % PF_P2G_COUNT);
        ASSERT_EQ(pf_set_params(handle.get(), &p), PF_OK) << last_log();
        ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
    }
    EXPECT_EQ(pf::entry(handle)->impl->runner().binding_errors(), 0u) << last_log();
    // Both the emitters and the sinks ran in every configuration.
    uint32_t n = 0;
    ASSERT_EQ(pf_get_pass_count(handle.get(), &n), PF_OK);
    std::vector<std::string> ran;
    for (uint32_t i = 0; i < n; ++i) {
        pf_pass_stats s{};
        ASSERT_EQ(pf_get_pass_stats(handle.get(), i, &s), PF_OK);
        if (s.dispatches > 0) ran.push_back(s.name);
    }
    EXPECT_NE(std::find(ran.begin(), ran.end(), "emit"), ran.end());
    EXPECT_NE(std::find(ran.begin(), ran.end(), "sinks"), ran.end());
    EXPECT_NE(std::find(ran.begin(), ran.end(), "domain_motion"), ran.end());
    EXPECT_NE(std::find(ran.begin(), ran.end(), "vorticity_confinement"), ran.end());
    EXPECT_NE(std::find(ran.begin(), ran.end(), "viscosity"), ran.end());
    EXPECT_NE(std::find(ran.begin(), ran.end(), "surface_tension"), ran.end());
}

}  // namespace
}  // namespace pf::test
