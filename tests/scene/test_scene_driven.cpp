// A scene's driven obstacle (samples/common/driven.h, "oscillation" in a scene file) in a
// simulation: each frame the samples set its pose at the frame's start and the velocity that
// carries it to the next frame's pose, and a sphere bobbing at the surface of a tank at rest
// sets the liquid moving, where the same sphere held still leaves it at rest (the control).
#include <glad/gl.h>

#include <cmath>
#include <string>
#include <vector>

#include "driven.h"
#include "scene.h"
#include "support/sim_fixture.h"
#include "util.h"

namespace {

// A tank of 0.8 x 0.6 x 0.8 m half full, a sphere of 0.1 m at the surface bobbing 5 cm every 0.5 s.
const char* kScene = R"({
  "grid": {"size": [16, 12, 16], "cell_size": 0.05},
  "max_particles": 40000,
  "fill": [{"lo": [0, 0, 0], "hi": [0.8, 0.3, 0.8]}],
  "features": ["obstacles"],
  "obstacles": [{"shape": "sphere", "position": [0.4, 0.3, 0.4], "radius": 0.1,
                 "oscillation": {"amplitude": [0, 0.05, 0], "period": 0.5}}]
})";

class SceneDrivenObstacle : public pf::test::GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(pf::test::get_proc))) << "the samples' GL loader";
        scene_ = pfs::parse_scene(kScene, "driven.json");
    }

    // RMS particle speed (m/s) after `frames` frames, the obstacle driven or held at rest.
    double rms_speed_after(int frames, bool driven_on) {
        pfs::Scene scene = scene_;
        if (!driven_on) scene.obstacle_oscillation[0].period = 0.0f;
        pfs::SceneEffectIds ids;
        pfs::SimPtr sim(pfs::create_scene_sim(scene, pf::test::get_proc, pfs::stderr_logger(false), &ids));
        EXPECT_TRUE(sim);
        if (!sim) return -1.0;
        pfs::DrivenObstacles driven;
        pfs::drive_scene_obstacles(scene, ids, driven);
        EXPECT_EQ(driven.empty(), !driven_on);
        for (int f = 0; f < frames; ++f) {
            EXPECT_EQ(driven.step(sim.get(), scene.frame_dt), PF_OK) << "frame " << f;
            EXPECT_EQ(pf_step(sim.get(), scene.frame_dt), PF_OK) << "frame " << f;
        }
        const pf::test::ParticleState p = pf::test::read_all(sim.get());
        double sum = 0;
        for (float v : p.vel) sum += double(v) * v;
        return p.count() ? std::sqrt(sum / double(p.count())) : -1.0;
    }

    pfs::Scene scene_;
};

TEST_F(SceneDrivenObstacle, SceneCarriesItsOscillation) {
    ASSERT_EQ(scene_.obstacle_oscillation.size(), 1u);
    EXPECT_FLOAT_EQ(scene_.obstacle_oscillation[0].period, 0.5f);
    EXPECT_FLOAT_EQ(scene_.obstacle_oscillation[0].amplitude[1], 0.05f);
    EXPECT_FLOAT_EQ(scene_.obstacle_float_density[0], 0.0f);
}

// The pose set for a frame is the path's at the frame's start, and its velocity moves it onto
// the next frame's pose in one frame.
TEST_F(SceneDrivenObstacle, PoseFollowsThePathAndVelocityReachesTheNextPose) {
    pfs::SceneEffectIds ids;
    pfs::SimPtr sim(pfs::create_scene_sim(scene_, pf::test::get_proc, pfs::stderr_logger(false), &ids));
    ASSERT_TRUE(sim);
    pfs::DrivenObstacles driven;
    pfs::drive_scene_obstacles(scene_, ids, driven);
    const float dt = scene_.frame_dt;
    for (int f = 0; f < 40; ++f) {
        const double t = driven.time();
        ASSERT_EQ(driven.step(sim.get(), dt), PF_OK);
        const pf_obstacle now = driven.poses(scene_.obstacles, ids.obstacles)[0];
        float expected[3], next[3];
        pfs::DrivenObstacles::position_at(scene_.obstacles[0], scene_.obstacle_oscillation[0], t, expected);
        pfs::DrivenObstacles::position_at(scene_.obstacles[0], scene_.obstacle_oscillation[0], t + dt, next);
        for (int a = 0; a < 3; ++a) {
            EXPECT_FLOAT_EQ(now.position[a], expected[a]) << "frame " << f << " axis " << a;
            EXPECT_NEAR(now.position[a] + now.velocity[a] * dt, next[a], 1e-6f) << "frame " << f << " axis " << a;
        }
        ASSERT_EQ(pf_step(sim.get(), dt), PF_OK);
    }
    // Within its amplitude of its rest position, and it did move.
    EXPECT_NEAR(driven.poses(scene_.obstacles, ids.obstacles)[0].position[1], 0.3f, 0.05f + 1e-6f);
}

TEST_F(SceneDrivenObstacle, BobbingSphereSetsTheLiquidMovingAndAStillOneDoesNot) {
    const double driven = rms_speed_after(40, true), still = rms_speed_after(40, false);
    RecordProperty("rms_speed_driven", std::to_string(driven));
    RecordProperty("rms_speed_still", std::to_string(still));
    // The sphere's own speed peaks at 2 pi 0.05 / 0.5 = 0.63 m/s.
    EXPECT_GT(driven, 0.02);
    EXPECT_GT(driven, 5.0 * still);
}

} // namespace
