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
const gl::ProgramId kObstaclePrograms[] = {gl::ProgramId::obstacle_cells, gl::ProgramId::obstacle_faces,
                                           gl::ProgramId::obstacle_push};

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
    // Off and on again: nothing is rebuilt.
    ASSERT_EQ(pf_set_features(handle.get(), 0), PF_OK);
    ASSERT_EQ(pf_set_features(handle.get(), PF_FEATURE_ALL), PF_OK);
    EXPECT_EQ(r.programs_built(), core + std::size(kForceFieldPrograms) + std::size(kObstaclePrograms));
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
    const float lo[3] = {0, 0, 0}, hi[3] = {0.5f, 0.5f, 0.8f};
    ASSERT_EQ(pf_fill_box(handle.get(), lo, hi, nullptr), PF_OK);
    // The effect passes bind the same buffers whatever the scheme; six configurations take
    // every solver, transfer, advection and P2G scheme once.
    for (uint32_t i = 0; i < 6; ++i) {
        pf_sim_params p{};
        ASSERT_EQ(pf_get_params(handle.get(), &p), PF_OK);
        p.pressure_solver = pf_pressure_solver(i % PF_PRESSURE_SOLVER_COUNT);
        p.transfer = pf_transfer(i % PF_TRANSFER_COUNT);
        p.advection = pf_advection(i % PF_ADVECTION_COUNT);
        p.p2g = pf_p2g((i / 2) % PF_P2G_COUNT);
        ASSERT_EQ(pf_set_params(handle.get(), &p), PF_OK) << last_log();
        ASSERT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
    }
    EXPECT_EQ(pf::entry(handle)->impl->runner().binding_errors(), 0u) << last_log();
}

}  // namespace
}  // namespace pf::test
