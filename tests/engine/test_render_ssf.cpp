// pf_render_ssf seen from an engine: liquid appears exactly where the particles' spheres
// project and the engine's frame is untouched everywhere else; scene depth occludes; thicker
// liquid absorbs more; the output is finite; viewports may change between calls.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "support/render_fixture.h"

namespace pf::test {
namespace {

class RenderSsf : public RenderTest {
protected:
    // Renders into `t` (whose colour and depth were filled before) and checks, pixel by pixel,
    // that liquid (a changed depth) appears exactly where the CPU projects a sphere, and that
    // every other pixel keeps its colour and depth bit for bit. Returns the liquid pixel count.
    int expect_exact_coverage(EngineTarget& t, const TestCamera& c, const std::vector<float>& xyz, double radius,
                              const pf_ssf_params& params, const pf_render_target& target) {
        const std::vector<float> color0 = t.read_color(), depth0 = t.read_depth();
        EXPECT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, &params), PF_OK) << last_log();
        const std::vector<float> color1 = t.read_color(), depth1 = t.read_depth();
        const SphereCoverage cov = project_spheres(c, t.width, t.height, xyz, radius);
        EXPECT_GT(cov.covered, 50) << "the spheres must cover a real area for this test to mean anything";
        int liquid = 0, missing = 0, extra = 0, touched_outside = 0;
        for (int i = 0; i < t.width * t.height; ++i) {
            const bool expected = cov.depth[size_t(i)] > 0.0;
            const bool got = depth1[size_t(i)] != depth0[size_t(i)];
            liquid += got;
            if (cov.ambiguous[size_t(i)]) continue;
            if (expected && !got) ++missing;
            if (!expected && got) ++extra;
            if (!expected && std::memcmp(&color1[size_t(i) * 4], &color0[size_t(i) * 4], 16) != 0) ++touched_outside;
        }
        EXPECT_EQ(missing, 0) << "pixels where a sphere projects but no liquid was written";
        EXPECT_EQ(extra, 0) << "pixels with liquid depth where no sphere projects";
        EXPECT_EQ(touched_outside, 0) << "pixels outside the liquid whose colour changed";
        return liquid;
    }
};

std::vector<float> scattered_spheres() {
    return {0.5f, 0.5f, 0.8f, 1.1f, 0.6f, 0.7f, 0.8f, 1.1f, 0.9f, 0.3f, 1.2f, 0.5f, 1.3f, 1.2f, 1.0f, 0.8f, 0.8f, 0.3f};
}

TEST_F(RenderSsf, LiquidExactlyWhereSpheresProjectAndNothingElseChanges) {
    const std::vector<float> xyz = scattered_spheres();
    add(xyz);
    // Viewport offset inside a larger target; the scene colour is the target's own colour
    // attachment (pflip copies it first, so this is no feedback loop).
    EngineTarget t(160, 112, GL_RGBA8);
    t.write_color(checkerboard(t.width, t.height, 8));
    t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
    const int vp[4] = {16, 8, 128, 96};
    const TestCamera c = camera(vp);
    pf_render_target target{t.fbo, t.color, t.depth, 0};
    for (pf_ssf_path path : {PF_SSF_PATH_COMPUTE, PF_SSF_PATH_RASTER}) {
        for (pf_ssf_filter filter : {PF_SSF_FILTER_BILATERAL, PF_SSF_FILTER_NARROW_RANGE, PF_SSF_FILTER_NONE}) {
            SCOPED_TRACE("path " + std::to_string(path) + " filter " + std::to_string(filter));
            t.write_color(checkerboard(t.width, t.height, 8));
            t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
            pf_ssf_params p = pf_default_ssf_params();
            p.particle_radius = 0.12f;
            p.path = path;
            p.filter = filter;
            EXPECT_GT(expect_exact_coverage(t, c, xyz, 0.12, p, target), 200);
        }
    }
}

// A particle with hardly any liquid around it is drawn as spray: at spray_radius_scale of the
// radius (default 0.5) once a step has counted the particles per cell, whole before that; a dense
// block keeps the full radius. Liquid appears exactly where those spheres project, on both paths.
TEST_F(RenderSsf, IsolatedParticlesAreDrawnAsSpray) {
    std::vector<float> xyz;  // a 2 x 2 x 2-cell block at 8 a cell, then one particle alone
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i)
                xyz.insert(xyz.end(), {0.325f + 0.05f * float(i), 0.625f + 0.05f * float(j), 0.725f + 0.05f * float(k)});
    xyz.insert(xyz.end(), {1.25f, 1.05f, 0.85f});
    add(xyz);
    EngineTarget t(320, 240, GL_RGBA8);
    const int vp[4] = {0, 0, 320, 240};
    const TestCamera c = camera(vp);
    const pf_render_target target{t.fbo, t.color, t.depth, 0};
    const double r = 0.05;  // the default radius, half of a 0.1 m cell
    // Liquid pixels where `block` (radius r) and `lone` (radius lone_r) project, and the count of
    // pixels that disagree with that.
    auto mismatches = [&](pf_ssf_path path, float scale, const std::vector<float>& block, const std::vector<float>& lone,
                          double lone_r, int* lone_pixels) {
        t.write_color(checkerboard(t.width, t.height, 8));
        t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
        const std::vector<float> depth0 = t.read_depth();
        pf_ssf_params p = pf_default_ssf_params();
        p.path = path;
        p.spray_radius_scale = scale;
        EXPECT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, &p), PF_OK) << last_log();
        const std::vector<float> depth1 = t.read_depth();
        const SphereCoverage a = project_spheres(c, t.width, t.height, block, r);
        const SphereCoverage b = project_spheres(c, t.width, t.height, lone, lone_r);
        *lone_pixels = b.covered;
        int wrong = 0;
        for (size_t i = 0; i < depth1.size(); ++i) {
            if (a.ambiguous[i] || b.ambiguous[i]) continue;
            wrong += (depth1[i] != depth0[i]) != (a.depth[i] > 0.0 || b.depth[i] > 0.0);
        }
        return wrong;
    };
    const std::vector<float> block0(xyz.begin(), xyz.end() - 3), lone0(xyz.end() - 3, xyz.end());
    int lone_pixels = 0;
    for (pf_ssf_path path : {PF_SSF_PATH_COMPUTE, PF_SSF_PATH_RASTER}) {
        SCOPED_TRACE("path " + std::to_string(path));
        // Before any step the counts say nothing: every particle whole.
        EXPECT_EQ(mismatches(path, 0.0f, block0, lone0, r, &lone_pixels), 0);
    }
    ASSERT_EQ(pf_step(sim_.get(), 1.0f / 240.0f), PF_OK) << last_log();
    ParticleState now = read_all(sim_.get());
    const std::vector<float> block(now.pos.begin(), now.pos.end() - 3), lone(now.pos.end() - 3, now.pos.end());
    for (pf_ssf_path path : {PF_SSF_PATH_COMPUTE, PF_SSF_PATH_RASTER}) {
        SCOPED_TRACE("path " + std::to_string(path));
        int whole = 0, spray = 0, quarter = 0;
        EXPECT_EQ(mismatches(path, 1.0f, block, lone, r, &whole), 0) << "spray_radius_scale 1: all whole";
        EXPECT_EQ(mismatches(path, 0.0f, block, lone, 0.5 * r, &spray), 0) << "default: spray at half the radius";
        EXPECT_EQ(mismatches(path, 0.25f, block, lone, 0.25 * r, &quarter), 0) << "a quarter of the radius";
        EXPECT_GT(whole, 100);
        EXPECT_LT(spray, whole / 3);
        EXPECT_GT(quarter, 0);
    }
}

// pf_stats.gpu_memory_bytes counts the renderer's screen-sized textures once a render call has
// made them: 48 bytes a texel over the ten that do not copy the engine's depth (two RGBA16F,
// eight 32-bit), at the viewport's size; the particle part stays as it was.
TEST_F(RenderSsf, RenderTargetsCountInTheGpuMemory) {
    add(scattered_spheres());
    pf_stats before{};
    before.struct_size = sizeof before;
    ASSERT_EQ(pf_get_stats(sim_.get(), &before), PF_OK);
    EngineTarget t(64, 48, GL_RGBA8);
    const int vp[4] = {0, 0, 64, 48};
    const TestCamera c = camera(vp);
    pf_render_target target{t.fbo, t.color, t.depth, 0};
    ASSERT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, nullptr), PF_OK) << last_log();
    pf_stats after{};
    after.struct_size = sizeof after;
    ASSERT_EQ(pf_get_stats(sim_.get(), &after), PF_OK);
    const uint64_t texels = 64 * 48, grown = after.gpu_memory_bytes - before.gpu_memory_bytes;
    // 44 bytes a pixel at full resolution (ssf_targets.h) and 8 a texel of the half-resolution
    // thickness: 46 a pixel, and the renderer's buffers.
    EXPECT_GE(grown, 46 * texels);
    EXPECT_LE(grown, 46 * texels + (1u << 20));
    EXPECT_EQ(after.gpu_particle_bytes, before.gpu_particle_bytes);
}

// No particles at all (the API fuzzer found a division by zero here): both paths render
// nothing and leave the engine's frame exactly as it was.
TEST_F(RenderSsf, EmptySimulationChangesNothing) {
    EngineTarget t(64, 48, GL_RGBA8);
    const int vp[4] = {0, 0, 64, 48};
    const TestCamera c = camera(vp);
    pf_render_target target{t.fbo, t.color, t.depth, 0};
    for (pf_ssf_path path : {PF_SSF_PATH_COMPUTE, PF_SSF_PATH_RASTER}) {
        SCOPED_TRACE("path " + std::to_string(path));
        t.write_color(checkerboard(t.width, t.height, 8));
        t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
        const std::vector<float> color0 = t.read_color(), depth0 = t.read_depth();
        pf_ssf_params p = pf_default_ssf_params();
        p.path = path;
        ASSERT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, &p), PF_OK) << last_log();
        EXPECT_EQ(t.read_color(), color0);
        EXPECT_EQ(t.read_depth(), depth0);
    }
    const pf_particle_params pp = pf_default_particle_params();
    EXPECT_EQ(pf_render_particles(sim_.get(), &c.cam, &target, &pp), PF_OK) << last_log();
}

// A slab of spheres facing the camera: `layers` deep along z, jittered by `jitter` metres.
std::vector<float> slab(int layers, float jitter, float spacing = 0.05f) {
    std::vector<float> xyz;
    uint32_t n = 0;
    for (int k = 0; k < layers; ++k) {
        for (int j = 0; j < 12; ++j) {
            for (int i = 0; i < 16; ++i, ++n) {
                xyz.push_back(0.4f + spacing * i + jitter * hash_jitter(3 * n));
                xyz.push_back(0.5f + spacing * j + jitter * hash_jitter(3 * n + 1));
                xyz.push_back(1.0f - spacing * k + jitter * hash_jitter(3 * n + 2));
            }
        }
    }
    return xyz;
}

// Mean RGB over the target pixels inside [x0, x1) x [y0, y1).
std::array<double, 3> mean_rgb(const std::vector<float>& rgba, int w, int x0, int x1, int y0, int y1) {
    std::array<double, 3> m{};
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            for (int ch = 0; ch < 3; ++ch) m[ch] += rgba[(size_t(y) * w + x) * 4 + ch];
        }
    }
    for (double& v : m) v /= double((x1 - x0) * (y1 - y0));
    return m;
}

std::vector<float> uniform_color(int w, int h, float r, float g, float b) {
    std::vector<float> out(size_t(w) * h * 4);
    for (size_t i = 0; i < out.size(); i += 4) out[i] = r, out[i + 1] = g, out[i + 2] = b, out[i + 3] = 1.0f;
    return out;
}

// Opaque scene in front of the liquid hides it (the frame stays the engine's there); a scene
// surface behind the liquid does not.
TEST_F(RenderSsf, SceneDepthInFrontOccludesLiquid) {
    const std::vector<float> xyz = slab(2, 0.0f);
    add(xyz);
    EngineTarget t(128, 96, GL_RGBA16F);
    const int vp[4] = {0, 0, 128, 96};
    for (pf_depth_convention conv : {PF_DEPTH_STANDARD, PF_DEPTH_REVERSED_Z}) {
        SCOPED_TRACE("convention " + std::to_string(conv));
        const TestCamera c = camera(vp, conv);
        // Left half: a wall 1.5 m away (the liquid is 2.2 m away); right half: a wall at 3 m.
        std::vector<float> depth(size_t(t.width) * t.height);
        for (int y = 0; y < t.height; ++y) {
            for (int x = 0; x < t.width; ++x) depth[size_t(y) * t.width + x] = float(window_depth_at(c, x, y, x < 64 ? 1.5 : 3.0));
        }
        t.write_depth(depth);
        t.write_color(checkerboard(t.width, t.height, 8));
        const std::vector<float> before = t.read_color();
        const pf_render_target target{t.fbo, t.color, t.depth, 0};
        ASSERT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, nullptr), PF_OK) << last_log();
        const std::vector<float> after = t.read_color();
        const SphereCoverage cov = project_spheres(c, t.width, t.height, xyz, 0.05);
        int left_expected = 0, left_changed = 0, right_expected = 0, right_changed = 0;
        for (int y = 0; y < t.height; ++y) {
            for (int x = 0; x < t.width; ++x) {
                const size_t i = size_t(y) * t.width + x;
                const bool changed = std::memcmp(&after[i * 4], &before[i * 4], 16) != 0;
                const bool expected = cov.depth[i] > 0.0 && !cov.ambiguous[i];
                (x < 64 ? left_expected : right_expected) += expected;
                (x < 64 ? left_changed : right_changed) += changed;
            }
        }
        EXPECT_GT(left_expected, 300) << "the liquid must reach behind the near wall for the test to mean anything";
        EXPECT_EQ(left_changed, 0) << "liquid drawn over the scene in front of it";
        EXPECT_GE(right_changed, right_expected * 9 / 10) << "liquid in front of the far wall is missing";
    }
}

// Beer-Lambert: the same absorption over more liquid leaves less light, and less of the most
// absorbed channel relative to the least absorbed one.
TEST_F(RenderSsf, ThickerLiquidAbsorbsMore) {
    EngineTarget t(96, 96, GL_RGBA16F);
    const int vp[4] = {0, 0, 96, 96};
    const TestCamera c = camera(vp);
    pf_ssf_params p = pf_default_ssf_params();
    p.absorption[0] = 4.0f, p.absorption[1] = 1.5f, p.absorption[2] = 0.5f;
    p.fresnel_f0 = 0.0f;
    p.specular = 0.0f;
    p.refraction = 0.0f;
    std::array<double, 3> mean[2];
    for (int thick = 0; thick < 2; ++thick) {
        ASSERT_EQ(pf_clear_particles(sim_.get()), PF_OK);
        add(slab(thick ? 8 : 1, 0.0f));
        t.write_color(uniform_color(t.width, t.height, 1.0f, 1.0f, 1.0f));
        t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
        const pf_render_target target{t.fbo, t.color, t.depth, 0};
        ASSERT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, &p), PF_OK) << last_log();
        mean[thick] = mean_rgb(t.read_color(), t.width, 40, 56, 44, 56);  // inside the slab's image
    }
    const auto& thin = mean[0];
    const auto& thick = mean[1];
    EXPECT_LT(thin[0], 0.95) << "one layer must already absorb some red";
    EXPECT_LT(thick[0], 0.6 * thin[0]) << "red: thin " << thin[0] << ", thick " << thick[0];
    EXPECT_LT(thick[1], thin[1]) << "green: thin " << thin[1] << ", thick " << thick[1];
    EXPECT_LT(thick[2], thin[2]) << "blue: thin " << thin[2] << ", thick " << thick[2];
    EXPECT_GT(thick[2] / thick[0], 1.5 * thin[2] / thin[0]) << "thicker liquid must be more tinted";
}

// The thickness that absorbs is the depth of liquid, not the summed chords of the overlapping
// spheres: a slab of 8 layers at the fill's spacing (8 particles a cell of 0.1 m: 0.05 m apart)
// holds 0.4 m of liquid along the view. With only absorption acting (no Fresnel, highlight or
// refraction) the light through it is exp(-a T), so T = -ln(red) / a inside the slab's image.
// Measured: 0.395 m (0.989 of the depth). Before the sum was scaled by a particle's volume over
// its sphere's, it read 1.63 m (4.08 times; the volumes' ratio is 4.19), which this test
// failed on. Bound: 10%.
TEST_F(RenderSsf, ThicknessIsTheDepthOfLiquid) {
    add(slab(8, 0.0f));
    // Spheres about 3 px across, whose thickness the compute splat adds texel by texel; 6 px, summed
    // per workgroup in shared memory first (PF_SPLAT_SHARED); 24 px, too many texels for that, so
    // added texel by texel again (ssf_splat.comp).
    for (int size : {64, 128, 480}) {
        SCOPED_TRACE("viewport " + std::to_string(size));
        EngineTarget t(size, size, GL_RGBA16F);
        const int vp[4] = {0, 0, size, size};
        const TestCamera c = camera(vp);
        pf_ssf_params p = pf_default_ssf_params();
        const float a = 2.0f;
        p.absorption[0] = p.absorption[1] = p.absorption[2] = a;
        p.fresnel_f0 = 0.0f;
        p.specular = 0.0f;
        p.refraction = 0.0f;
        t.write_color(uniform_color(t.width, t.height, 1.0f, 1.0f, 1.0f));
        t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
        const pf_render_target target{t.fbo, t.color, t.depth, 0};
        ASSERT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, &p), PF_OK) << last_log();
        // Inside the slab's image.
        const std::array<double, 3> mean =
            mean_rgb(t.read_color(), t.width, size * 40 / 96, size * 56 / 96, size * 44 / 96, size * 56 / 96);
        const double depth = 8 * 0.05;
        const double thickness = -std::log(mean[0]) / a;
        RecordProperty("thickness_over_depth_" + std::to_string(size), std::to_string(thickness / depth));
        EXPECT_NEAR(thickness / depth, 1.0, 0.10) << "thickness " << thickness << " m, liquid " << depth << " m";
    }
}

// Float targets show every NaN/Inf: none for spheres crossing the near plane, behind the
// camera, around the camera, far away, tiny or large, with every filter, path and a cube map.
TEST_F(RenderSsf, OutputIsFiniteEverywhere) {
    std::vector<float> xyz = slab(3, 0.02f);
    const float awkward[] = {0.8f, 0.8f, 3.15f,  // around the camera (z 3.2)
                             0.8f, 0.8f, 3.5f,   // behind it -- outside the domain: kept out below
                             0.82f, 0.8f, 3.12f, 0.8f, 0.79f, 0.01f, 1.59f, 1.59f, 1.59f};
    for (size_t i = 0; i < sizeof awkward / sizeof awkward[0]; i += 3) {
        if (awkward[i + 2] <= 1.6f) xyz.insert(xyz.end(), awkward + i, awkward + i + 3);
    }
    add(xyz);
    EngineTarget t(80, 64, GL_RGBA32F);
    GLuint cube = 0;
    glGenTextures(1, &cube);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_RGBA16F, 4, 4);
    const std::vector<float> sky = uniform_color(4, 4, 0.4f, 0.6f, 2.0f);
    for (int f = 0; f < 6; ++f)
        glTexSubImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, 0, 0, 4, 4, GL_RGBA, GL_FLOAT, sky.data());
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    const int vp[4] = {0, 0, 80, 64};
    // A camera inside the domain, so spheres lie around, behind and across the near plane.
    const TestCamera inside = make_camera({0.8, 0.8, 1.3}, {0.8, 0.8, 0.0}, 70.0, vp, 0.05, 5.0, PF_DEPTH_REVERSED_Z);
    const TestCamera outside = camera(vp, PF_DEPTH_ZERO_TO_ONE);
    for (const TestCamera* c : {&inside, &outside}) {
        for (float radius : {0.002f, 0.05f, 0.4f}) {
            for (pf_ssf_filter filter : {PF_SSF_FILTER_BILATERAL, PF_SSF_FILTER_NARROW_RANGE, PF_SSF_FILTER_NONE}) {
                for (pf_ssf_path path : {PF_SSF_PATH_COMPUTE, PF_SSF_PATH_RASTER}) {
                    SCOPED_TRACE("radius " + std::to_string(radius) + " filter " + std::to_string(filter) + " path " +
                                 std::to_string(path));
                    t.write_color(checkerboard(t.width, t.height, 4));
                    t.write_depth(std::vector<float>(size_t(t.width) * t.height, float(far_window_depth(c->cam.depth_convention))));
                    pf_ssf_params p = pf_default_ssf_params();
                    p.particle_radius = radius;
                    p.filter = filter;
                    p.path = path;
                    const pf_render_target target{t.fbo, t.color, t.depth, path == PF_SSF_PATH_RASTER ? cube : 0u};
                    ASSERT_EQ(pf_render_ssf(sim_.get(), &c->cam, &target, &p), PF_OK) << last_log();
                    const std::vector<float> color = t.read_color(), depth = t.read_depth();
                    int bad = 0;
                    for (float v : color) bad += !std::isfinite(v);
                    for (float v : depth) bad += !std::isfinite(v) || v < 0.0f || v > 1.0f;
                    EXPECT_EQ(bad, 0);
                }
            }
        }
    }
    glDeleteTextures(1, &cube);
}

// The renderer reallocates its textures when the viewport changes size; every size is exact.
TEST_F(RenderSsf, ViewportSizeMayChangeBetweenCalls) {
    const std::vector<float> xyz = scattered_spheres();
    add(xyz);
    EngineTarget t(256, 160, GL_RGBA8);
    const pf_render_target target{t.fbo, t.color, t.depth, 0};
    const int viewports[][4] = {{0, 0, 64, 64}, {20, 10, 200, 120}, {0, 0, 256, 160}, {100, 50, 64, 64}, {3, 5, 203, 117}};
    for (const auto& vp : viewports) {
        SCOPED_TRACE("viewport " + std::to_string(vp[2]) + "x" + std::to_string(vp[3]));
        t.write_color(checkerboard(t.width, t.height, 8));
        t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
        pf_ssf_params p = pf_default_ssf_params();
        p.particle_radius = 0.12f;
        EXPECT_GT(expect_exact_coverage(t, camera(vp), xyz, 0.12, p, target), 50);
    }
}

// The compute and raster paths run the same filter and shading code: same image.
TEST_F(RenderSsf, ComputeAndRasterPathsAgree) {
    add(slab(3, 0.02f));
    EngineTarget t(96, 80, GL_RGBA32F);
    const int vp[4] = {0, 0, 96, 80};
    const TestCamera c = camera(vp);
    for (pf_ssf_filter filter : {PF_SSF_FILTER_BILATERAL, PF_SSF_FILTER_NARROW_RANGE, PF_SSF_FILTER_NONE}) {
        SCOPED_TRACE("filter " + std::to_string(filter));
        std::vector<float> color[2], depth[2];
        for (int path = 0; path < 2; ++path) {
            t.write_color(checkerboard(t.width, t.height, 6));
            t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
            pf_ssf_params p = pf_default_ssf_params();
            p.filter = filter;
            p.filter_iterations = 2;
            p.path = path ? PF_SSF_PATH_RASTER : PF_SSF_PATH_COMPUTE;
            const pf_render_target target{t.fbo, t.color, t.depth, 0};
            ASSERT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, &p), PF_OK) << last_log();
            color[path] = t.read_color();
            depth[path] = t.read_depth();
        }
        double worst_color = 0, worst_depth = 0;
        int liquid = 0;
        for (size_t i = 0; i < depth[0].size(); ++i) {
            liquid += depth[0][i] != 1.0f;
            worst_depth = std::max(worst_depth, double(std::fabs(depth[0][i] - depth[1][i])));
            for (int ch = 0; ch < 4; ++ch) worst_color = std::max(worst_color, double(std::fabs(color[0][i * 4 + ch] - color[1][i * 4 + ch])));
        }
        EXPECT_GT(liquid, 500);
        EXPECT_LT(worst_color, 2e-3);
        EXPECT_LT(worst_depth, 1e-6);
    }
}

// The three depth conventions describe the same frame: the same colours, and depth written in
// each convention exactly where the CPU puts the sphere surface.
TEST_F(RenderSsf, DepthConventionsGiveTheSameImageAndTheirOwnDepth) {
    const std::vector<float> xyz = slab(2, 0.01f);
    add(xyz);
    EngineTarget t(96, 80, GL_RGBA32F);
    const int vp[4] = {0, 0, 96, 80};
    std::vector<float> colors[3];
    for (pf_depth_convention conv : {PF_DEPTH_STANDARD, PF_DEPTH_ZERO_TO_ONE, PF_DEPTH_REVERSED_Z}) {
        SCOPED_TRACE("convention " + std::to_string(conv));
        const TestCamera c = camera(vp, conv);
        // Scene depth: a wall at 2.25 m across the lower third (cuts into the liquid).
        std::vector<float> depth(size_t(t.width) * t.height);
        for (int y = 0; y < t.height; ++y) {
            for (int x = 0; x < t.width; ++x)
                depth[size_t(y) * t.width + x] = y < 26 ? float(window_depth_at(c, x, y, 2.25)) : float(far_window_depth(conv));
        }
        t.write_depth(depth);
        t.write_color(checkerboard(t.width, t.height, 6));
        pf_ssf_params p = pf_default_ssf_params();
        p.filter = PF_SSF_FILTER_NONE;  // raw sphere depth: comparable with the CPU
        const pf_render_target target{t.fbo, t.color, t.depth, 0};
        ASSERT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, &p), PF_OK) << last_log();
        colors[conv] = t.read_color();
        const std::vector<float> got = t.read_depth();
        const SphereCoverage cov = project_spheres(c, t.width, t.height, xyz, 0.05);
        int checked = 0;
        double worst = 0;
        for (int y = 0; y < t.height; ++y) {
            for (int x = 0; x < t.width; ++x) {
                const size_t i = size_t(y) * t.width + x;
                if (cov.depth[i] == 0.0 || cov.ambiguous[i] || (y < 26 && cov.depth[i] >= 2.25)) continue;
                // Compare in eye depth: window depth resolution differs between conventions.
                const double eye = eye_depth_of(c, x + 0.5, y + 0.5, got[i]);
                worst = std::max(worst, std::fabs(eye - cov.depth[i]));
                ++checked;
            }
        }
        EXPECT_GT(checked, 500);
        EXPECT_LT(worst, 2e-3) << "metres between the written depth and the CPU's sphere surface";
    }
    for (int conv = 1; conv < 3; ++conv) {
        double worst = 0;
        for (size_t i = 0; i < colors[0].size(); ++i) worst = std::max(worst, double(std::fabs(colors[conv][i] - colors[0][i])));
        EXPECT_LT(worst, 5e-3) << "convention " << conv << " changes the colour image";
    }
}

// The smoothing filters flatten a bumpy sheet of spheres: less curvature noise than raw depth.
TEST_F(RenderSsf, FiltersReduceDepthNoise) {
    add(slab(1, 0.02f, 0.04f));
    EngineTarget t(128, 96, GL_RGBA16F);
    const int vp[4] = {0, 0, 128, 96};
    const TestCamera c = camera(vp);
    double roughness[3] = {};
    for (pf_ssf_filter filter : {PF_SSF_FILTER_NONE, PF_SSF_FILTER_BILATERAL, PF_SSF_FILTER_NARROW_RANGE}) {
        t.write_color(checkerboard(t.width, t.height, 8));
        t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
        pf_ssf_params p = pf_default_ssf_params();
        p.filter = filter;
        const pf_render_target target{t.fbo, t.color, t.depth, 0};
        ASSERT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, &p), PF_OK) << last_log();
        const std::vector<float> d = t.read_depth();
        std::vector<double> eye(d.size(), 0.0);
        for (int y = 0; y < t.height; ++y) {
            for (int x = 0; x < t.width; ++x) {
                const size_t i = size_t(y) * t.width + x;
                if (d[i] != 1.0f) eye[i] = eye_depth_of(c, x + 0.5, y + 0.5, d[i]);
            }
        }
        // Mean |discrete Laplacian| over pixels whose 9x9 neighbourhood is all liquid.
        double sum = 0;
        int n = 0;
        for (int y = 4; y < t.height - 4; ++y) {
            for (int x = 4; x < t.width - 4; ++x) {
                bool inside = true;
                for (int dy = -4; dy <= 4 && inside; ++dy)
                    for (int dx = -4; dx <= 4 && inside; ++dx) inside = eye[size_t(y + dy) * t.width + x + dx] > 0.0;
                if (!inside) continue;
                auto e = [&](int dx, int dy) { return eye[size_t(y + dy) * t.width + x + dx]; };
                sum += std::fabs(e(1, 0) + e(-1, 0) + e(0, 1) + e(0, -1) - 4.0 * e(0, 0));
                ++n;
            }
        }
        ASSERT_GT(n, 500) << "filter " << filter;
        roughness[filter] = sum / n;
    }
    const double raw = roughness[PF_SSF_FILTER_NONE];
    EXPECT_LT(roughness[PF_SSF_FILTER_BILATERAL], 0.5 * raw) << "raw " << raw;
    EXPECT_LT(roughness[PF_SSF_FILTER_NARROW_RANGE], 0.5 * raw) << "raw " << raw;
}

}  // namespace
}  // namespace pf::test

namespace pf::test {
namespace {

// PF_FEATURE_DOMAIN_MOTION: the renderer draws the particles where the engine holds the domain.
// A domain turned 30 degrees about y and moved, seen by camera C, must give the depth image of
// an unmoved domain seen by C's view times the domain's pose (the same eye-space geometry), and
// a different one from the unmoved domain seen by C (so the pose is applied at all).
TEST_F(RenderSsf, DomainPosePlacesTheLiquid) {
    add(slab(3, 0.02f));
    EngineTarget t(96, 80, GL_RGBA32F);
    const int vp[4] = {0, 0, 96, 80};
    const TestCamera c = camera(vp);
    const double angle = 30.0 * 3.14159265358979 / 180.0;
    pf_domain_motion m = pf_default_domain_motion();
    m.rotation[1] = float(std::sin(angle / 2)), m.rotation[3] = float(std::cos(angle / 2));
    m.position[0] = 0.2f, m.position[1] = -0.1f, m.position[2] = 0.3f;
    ASSERT_EQ(pf_set_domain_motion(sim_.get(), &m), PF_OK);
    auto depth_image = [&](const pf_camera& cam) {
        t.write_color(std::vector<float>(size_t(t.width) * t.height * 4, 0.0f));
        t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
        const pf_render_target target{t.fbo, t.color, t.depth, 0};
        EXPECT_EQ(pf_render_ssf(sim_.get(), &cam, &target, nullptr), PF_OK) << last_log();
        return t.read_depth();
    };
    const std::vector<float> unmoved = depth_image(c.cam);
    ASSERT_EQ(pf_set_features(sim_.get(), PF_FEATURE_DOMAIN_MOTION), PF_OK);
    const std::vector<float> moved = depth_image(c.cam);
    ASSERT_EQ(pf_set_features(sim_.get(), 0), PF_OK);
    const glm::dmat4 pose = glm::translate(glm::dmat4(1.0), glm::dvec3(0.2, -0.1, 0.3)) *
                            glm::rotate(glm::dmat4(1.0), angle, glm::dvec3(0.0, 1.0, 0.0));
    pf_camera moved_camera = c.cam;
    const glm::dmat4 view = c.view * pose;
    for (int i = 0; i < 16; ++i) moved_camera.view[i] = float(glm::value_ptr(view)[i]);
    const std::vector<float> expected = depth_image(moved_camera);
    double worst = 0;
    int liquid = 0, changed = 0;
    for (size_t i = 0; i < moved.size(); ++i) {
        liquid += moved[i] != 1.0f;
        changed += moved[i] != unmoved[i];
        worst = std::max(worst, double(std::fabs(moved[i] - expected[i])));
    }
    EXPECT_GT(liquid, 500);
    EXPECT_GT(changed, 500);
    EXPECT_LT(worst, 1e-6);
}

}  // namespace
}  // namespace pf::test
