// pf_render_particles: each sprite's colour is its value mapped from range onto color_low ..
// color_high (clamped), shaded by n.v; its depth is the sphere's, in the engine's convention,
// tested LESS (GREATER for reversed-Z) against the target's depth.
#include <cmath>
#include <string>
#include <vector>

#include "support/render_fixture.h"

namespace pf::test {
namespace {

class RenderParticles : public RenderTest {
protected:
    // Target pixel nearest the projection of world point p.
    static std::pair<int, int> pixel_of(const TestCamera& c, const float p[3]) {
        const glm::dvec4 clip = c.proj * c.view * glm::dvec4(p[0], p[1], p[2], 1.0);
        const int* vp = c.cam.viewport;
        return {int(std::floor(vp[0] + (clip.x / clip.w * 0.5 + 0.5) * vp[2])),
                int(std::floor(vp[1] + (clip.y / clip.w * 0.5 + 0.5) * vp[3]))};
    }
};

TEST_F(RenderParticles, ColoursMapAsSpecified) {
    // Four well separated particles with known velocities and heights.
    const std::vector<float> xyz = {0.4f, 0.4f, 0.8f, 1.2f, 0.4f, 0.8f, 0.4f, 1.2f, 0.8f, 1.2f, 1.2f, 0.8f};
    const std::vector<float> vel = {1.5f, 0.0f, 0.0f, 0.0f, -3.0f, 0.0f, 0.0f, 0.0f, 9.0f, 0.0f, 0.0f, 0.0f};
    add(xyz, vel);
    EngineTarget t(128, 96, GL_RGBA32F);
    const int vp[4] = {0, 0, 128, 96};
    const TestCamera c = camera(vp);
    struct Case {
        pf_particle_color by;
        float range[2];
        float value[4];  // expected value per particle
    };
    const Case cases[] = {
        {PF_PARTICLE_COLOR_SPEED, {0.0f, 3.0f}, {1.5f, 3.0f, 9.0f, 0.0f}},
        {PF_PARTICLE_COLOR_VELOCITY_X, {-3.0f, 3.0f}, {1.5f, 0.0f, 0.0f, 0.0f}},
        {PF_PARTICLE_COLOR_VELOCITY_Y, {-3.0f, 3.0f}, {0.0f, -3.0f, 0.0f, 0.0f}},
        {PF_PARTICLE_COLOR_VELOCITY_Z, {3.0f, -3.0f}, {0.0f, 0.0f, 9.0f, 0.0f}},  // reversed range
        {PF_PARTICLE_COLOR_HEIGHT, {0.0f, 1.6f}, {0.4f, 0.4f, 1.2f, 1.2f}},
        {PF_PARTICLE_COLOR_UNIFORM, {0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 0.0f}},
    };
    for (const Case& k : cases) {
        SCOPED_TRACE("color_by " + std::to_string(k.by));
        t.write_color(std::vector<float>(size_t(t.width) * t.height * 4, 0.0f));
        t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
        pf_particle_params p = pf_default_particle_params();
        p.particle_radius = 0.1f;
        p.color_by = k.by;
        p.range[0] = k.range[0];
        p.range[1] = k.range[1];
        const float low[3] = {0.1f, 0.2f, 0.9f}, high[3] = {0.9f, 0.6f, 0.1f};
        for (int ch = 0; ch < 3; ++ch) p.color_low[ch] = low[ch], p.color_high[ch] = high[ch];
        const pf_render_target target{t.fbo, 0, 0, 0};
        ASSERT_EQ(pf_render_particles(sim_.get(), &c.cam, &target, &p), PF_OK) << last_log();
        const std::vector<float> color = t.read_color();
        for (int i = 0; i < 4; ++i) {
            const auto [x, y] = pixel_of(c, &xyz[size_t(i) * 3]);
            double f = (k.value[i] - k.range[0]) / (k.range[1] - k.range[0]);
            f = k.by == PF_PARTICLE_COLOR_UNIFORM ? 0.0 : std::fmin(std::fmax(f, 0.0), 1.0);
            for (int ch = 0; ch < 3; ++ch) {
                const double want = low[ch] + f * (high[ch] - low[ch]);  // n.v is ~1 at the centre
                EXPECT_NEAR(color[(size_t(y) * t.width + x) * 4 + ch], want, 0.01)
                    << "particle " << i << " channel " << ch;
            }
        }
    }
}

// Depth: the sprites write the sphere's depth in the engine's convention and are hidden by
// nearer engine depth (LESS; GREATER for reversed-Z) -- left half: a wall in front.
TEST_F(RenderParticles, DepthTestedAndWrittenInEngineConvention) {
    const std::vector<float> xyz = {0.5f, 0.8f, 0.8f, 1.1f, 0.8f, 0.8f};
    add(xyz);
    EngineTarget t(128, 96, GL_RGBA8);
    const int vp[4] = {0, 0, 128, 96};
    for (pf_depth_convention conv : {PF_DEPTH_STANDARD, PF_DEPTH_ZERO_TO_ONE, PF_DEPTH_REVERSED_Z}) {
        SCOPED_TRACE("convention " + std::to_string(conv));
        const TestCamera c = camera(vp, conv);
        std::vector<float> depth(size_t(t.width) * t.height);
        for (int y = 0; y < t.height; ++y) {
            for (int x = 0; x < t.width; ++x)
                depth[size_t(y) * t.width + x] = x < 64 ? float(window_depth_at(c, x, y, 1.0)) : float(far_window_depth(conv));
        }
        t.write_depth(depth);
        t.write_color(std::vector<float>(size_t(t.width) * t.height * 4, 0.0f));
        pf_particle_params p = pf_default_particle_params();
        p.particle_radius = 0.12f;
        const pf_render_target target{t.fbo, 0, 0, 0};
        ASSERT_EQ(pf_render_particles(sim_.get(), &c.cam, &target, &p), PF_OK) << last_log();
        const std::vector<float> color = t.read_color(), got = t.read_depth();
        const SphereCoverage cov = project_spheres(c, t.width, t.height, xyz, 0.12);
        int left_drawn = 0, right_checked = 0;
        double worst = 0;
        for (int y = 0; y < t.height; ++y) {
            for (int x = 0; x < t.width; ++x) {
                const size_t i = size_t(y) * t.width + x;
                const bool drawn = color[i * 4 + 3] != 0.0f;
                if (x < 64) left_drawn += drawn;
                if (x < 64 || cov.depth[i] == 0.0 || cov.ambiguous[i]) continue;
                ++right_checked;
                EXPECT_TRUE(drawn) << "pixel " << x << ", " << y;
                worst = std::max(worst, std::fabs(eye_depth_of(c, x + 0.5, y + 0.5, got[i]) - cov.depth[i]));
            }
        }
        EXPECT_EQ(left_drawn, 0) << "a sprite behind the engine's wall was drawn";
        EXPECT_GT(right_checked, 60);
        EXPECT_LT(worst, 2e-3) << "metres between the written depth and the sphere surface";
    }
}

}  // namespace
}  // namespace pf::test
