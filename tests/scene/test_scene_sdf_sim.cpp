// The SDF obstacle of samples/scenes/effects_sdf.json in a simulation (GL, llvmpipe in CI), put
// there as the samples do (pfs::create_scene_sim): its texture holds the file's grid exactly,
// in the texel order the library samples, and is deleted with the ids that own it; the block of
// liquid poured into the tilted bowl never ends inside the bowl's wall (sampled here on the CPU
// from the file's grid, as pf.h documents the texture: linear between texel centres that tile
// the box, the box surface's value plus the way to it outside) and stays in the bowl. The same
// run with the obstacle removed finds liquid inside the wall and none held up, so the checks
// would fail were the texture wrong or ignored. A floating SDF obstacle is moved with its texture.
#include <glad/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "floating.h"
#include "scene.h"
#include "sdf_file.h"
#include "support/sim_fixture.h"
#include "util.h"

namespace {

using pf::test::ParticleState;

// Distance (m) of obstacle o, whose texture holds grid g, at world point x.
double sdf_distance(const pfs::SdfGrid& g, const pf_obstacle& o, const double x[3]) {
    double q[4] = {o.rotation[0], o.rotation[1], o.rotation[2], o.rotation[3]};
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& c : q) c /= n;
    // Local point: p rotated by the conjugate quaternion, v + w t + u x t with u = -q.xyz.
    const double v[3] = {x[0] - o.position[0], x[1] - o.position[1], x[2] - o.position[2]};
    const double u[3] = {-q[0], -q[1], -q[2]}, w = q[3];
    const double t[3] = {2 * (u[1] * v[2] - u[2] * v[1]), 2 * (u[2] * v[0] - u[0] * v[2]), 2 * (u[0] * v[1] - u[1] * v[0])};
    const double p[3] = {v[0] + w * t[0] + (u[1] * t[2] - u[2] * t[1]), v[1] + w * t[1] + (u[2] * t[0] - u[0] * t[2]),
                         v[2] + w * t[2] + (u[0] * t[1] - u[1] * t[0])};
    double outside = 0;
    int i0[3];
    double f[3];
    for (int a = 0; a < 3; ++a) {
        const double h = o.half_extents[a], c = std::clamp(p[a], -h, h);
        outside += (p[a] - c) * (p[a] - c);
        const double texel = (c / (2 * h) + 0.5) * g.size[a] - 0.5;  // texel centres at integers
        i0[a] = int(std::floor(texel));
        f[a] = texel - i0[a];
    }
    auto at = [&](int di, int dj, int dk) {
        const int idx[3] = {i0[0] + di, i0[1] + dj, i0[2] + dk};
        uint32_t c[3];
        for (int a = 0; a < 3; ++a) c[a] = uint32_t(std::clamp(idx[a], 0, int(g.size[a]) - 1));  // clamp to edge
        return double(g.at(c[0], c[1], c[2]));
    };
    double value = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const int d[3] = {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
        double weight = 1;
        for (int a = 0; a < 3; ++a) weight *= d[a] ? f[a] : 1 - f[a];
        value += weight * at(d[0], d[1], d[2]);
    }
    return value * o.sdf_scale + std::sqrt(outside);
}

struct PourResult {
    size_t most_inside = 0;  // most particles found inside the wall at one check
    double deepest = 0;      // deepest particle inside the wall, m (negative)
    double held = 0;         // fraction of the liquid above the floor's puddle at the end
    size_t particles = 0;
};

class SceneSdfObstacle : public pf::test::GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(pf::test::get_proc))) << "the samples' GL loader";
        scene_ = pfs::load_scene(std::string(PF_TEST_SCENES_DIR) + "/effects_sdf.json");
        ASSERT_EQ(scene_.obstacles.size(), 1u);
        ASSERT_TRUE(scene_.obstacle_sdf[0]);
    }

    // The scene for `frames` frames, the wall checked every 2nd; with_obstacle false removes it
    // before the first step.
    PourResult pour(bool with_obstacle, int frames) {
        PourResult r;
        pfs::SceneEffectIds ids;
        pfs::SimPtr sim(
            pfs::create_scene_sim(scene_, pf::test::get_proc, pfs::stderr_logger(false), &ids));
        if (!with_obstacle) EXPECT_EQ(pf_remove_obstacle(sim.get(), ids.obstacles[0]), PF_OK);
        const pfs::SdfGrid& grid = *scene_.obstacle_sdf[0];
        const pf_obstacle& bowl = scene_.obstacles[0];
        ParticleState p;
        for (int f = 0; f < frames; ++f) {
            EXPECT_EQ(pf_step(sim.get(), scene_.frame_dt), PF_OK);
            if (f % 2 != 1) continue;
            p = pf::test::read_all(sim.get());
            size_t inside = 0;
            for (size_t i = 0; i < p.count(); ++i) {
                const double x[3] = {p.pos[i * 3], p.pos[i * 3 + 1], p.pos[i * 3 + 2]};
                const double d = sdf_distance(grid, bowl, x);
                r.deepest = std::min(r.deepest, d);
                // Deeper than the library's float sampling can differ from ours (as the SDF
                // tests of tests/engine/test_obstacles.cpp: 2 mm).
                inside += d < -0.002;
            }
            r.most_inside = std::max(r.most_inside, inside);
        }
        r.particles = p.count();
        size_t held = 0;
        for (size_t i = 0; i < p.count(); ++i) held += p.pos[i * 3 + 1] > 0.15f;  // the bowl's inside is above 0.18 m
        r.held = p.count() ? double(held) / double(p.count()) : 0.0;
        return r;
    }

    pfs::Scene scene_;
};

TEST_F(SceneSdfObstacle, TextureHoldsTheFileGridAndIsDeletedWithItsOwner) {
    GLuint name = 0;
    {
        pfs::SceneEffectIds ids;
        pf_sim* sim = pfs::create_scene_sim(scene_, pf::test::get_proc, pfs::stderr_logger(false), &ids);
        ASSERT_NE(sim, nullptr);
        ASSERT_EQ(ids.obstacle_textures.size(), 1u);
        name = ids.obstacle_textures[0];
        ASSERT_TRUE(glIsTexture(name));
        EXPECT_EQ(ids.sdf_textures.size(), 1u);
        const pfs::SdfGrid& g = *scene_.obstacle_sdf[0];
        GLint previous = 0, size[3] = {}, format = 0;
        glGetIntegerv(GL_TEXTURE_BINDING_3D, &previous);
        glBindTexture(GL_TEXTURE_3D, name);
        glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &size[0]);
        glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_HEIGHT, &size[1]);
        glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &size[2]);
        glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
        std::vector<float> texels(g.values.size(), -1e9f);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glGetTexImage(GL_TEXTURE_3D, 0, GL_RED, GL_FLOAT, texels.data());
        glBindTexture(GL_TEXTURE_3D, GLuint(previous));
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        for (int a = 0; a < 3; ++a) EXPECT_EQ(uint32_t(size[a]), g.size[a]) << "axis " << a;
        EXPECT_EQ(format, GL_R16F) << "a float16 file keeps its precision";
        size_t differing = 0;
        for (size_t i = 0; i < texels.size(); ++i) differing += texels[i] != g.values[i];
        EXPECT_EQ(differing, 0u) << "texels that differ from the file's grid (x fastest)";
        pf_destroy(sim);
        EXPECT_TRUE(glIsTexture(name)) << "pf never deletes the engine's texture";
    }
    EXPECT_FALSE(glIsTexture(name)) << "the ids' owner deletes it";
}

TEST_F(SceneSdfObstacle, LiquidPouredIntoTheBowlStaysOutOfItsWall) {
    const PourResult r = pour(true, 60);
    EXPECT_EQ(r.most_inside, 0u) << "deepest " << r.deepest << " m";
    EXPECT_GT(r.held, 0.6) << "of " << r.particles << " particles above the floor";
    RecordProperty("deepest_inside_m", std::to_string(r.deepest));
    RecordProperty("held_fraction", std::to_string(r.held));
}

// The control: the same checks see the liquid fall through where the wall would be.
TEST_F(SceneSdfObstacle, WithoutTheObstacleTheChecksFail) {
    const PourResult r = pour(false, 60);
    EXPECT_GT(r.most_inside, 100u) << "deepest " << r.deepest << " m";
    EXPECT_LT(r.held, 0.05);
    RecordProperty("most_inside", std::to_string(r.most_inside));
    RecordProperty("held_fraction", std::to_string(r.held));
}

// float_density on an SDF obstacle: the samples' rigid body sets it every frame through
// pf_set_obstacle, which refuses an SDF obstacle without its texture (sdf_texture 0).
TEST_F(SceneSdfObstacle, FloatingSdfObstacleMovesWithItsTexture) {
    scene_.obstacle_float_density[0] = 300.0f;
    pfs::SceneEffectIds ids;
    pf_sim* sim = pfs::create_scene_sim(scene_, pf::test::get_proc, pfs::stderr_logger(false), &ids);
    ASSERT_NE(sim, nullptr);
    pfs::FloatingBodies floating;
    pfs::float_scene_obstacles(scene_, ids, floating);
    EXPECT_FALSE(floating.empty());
    for (int f = 0; f < 10; ++f) {
        ASSERT_EQ(floating.step(sim, scene_.frame_dt, scene_.params.gravity), PF_OK) << "frame " << f;
        ASSERT_EQ(pf_step(sim, scene_.frame_dt), PF_OK);
    }
    pf_destroy(sim);
}

} // namespace
