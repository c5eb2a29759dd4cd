// A small golden image of the composite: a jittered block of liquid over a checkerboard scene
// with a post in the scene depth in front of part of it, default look (narrow-range filter one
// cell wide, compute path, built-in sky). Compared with tolerance (drivers round differently); with
// PF_UPDATE_GOLDEN=1 in the environment the image is rewritten instead (then inspect and commit
// it) and the test fails so an update is never mistaken for a pass.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "support/render_fixture.h"

namespace pf::test {
namespace {

class RenderGolden : public RenderTest {};

constexpr int kPost0 = 80, kPost1 = 86;  // target columns of the post

std::vector<float> liquid_block() {
    std::vector<float> xyz;
    uint32_t n = 0;
    for (int k = 0; k < 8; ++k) {
        for (int j = 0; j < 8; ++j) {
            for (int i = 0; i < 12; ++i, ++n) {
                xyz.push_back(0.5f + 0.05f * i + 0.01f * hash_jitter(3 * n));
                xyz.push_back(0.4f + 0.05f * j + 0.01f * hash_jitter(3 * n + 1));
                xyz.push_back(0.6f + 0.05f * k + 0.01f * hash_jitter(3 * n + 2));
            }
        }
    }
    return xyz;
}

std::vector<uint8_t> to_rgba8(const std::vector<float>& rgba, int w, int h) {
    std::vector<uint8_t> out(size_t(w) * h * 4);
    for (int y = 0; y < h; ++y) {  // GL rows start at the bottom, PNG rows at the top
        for (int x = 0; x < w * 4; ++x) {
            const float v = rgba[size_t(h - 1 - y) * w * 4 + x];
            out[size_t(y) * w * 4 + x] = uint8_t(std::lround(std::fmin(std::fmax(v, 0.0f), 1.0f) * 255.0f));
        }
    }
    return out;
}

TEST_F(RenderGolden, CompositeMatchesGoldenImage) {
    add(liquid_block());
    EngineTarget t(128, 96, GL_RGBA8);
    t.write_color(checkerboard(t.width, t.height, 8));
    const int vp[4] = {0, 0, 128, 96};
    const TestCamera c = make_camera({0.8, 0.6, 2.2}, {0.8, 0.6, 0.8}, 45.0, vp, 0.1, 10.0, PF_DEPTH_STANDARD);
    // A post 0.9 m from the camera, in front of the right part of the liquid (which starts at 1.2 m).
    std::vector<float> scene_depth(size_t(t.width) * t.height, 1.0f);
    for (int y = 0; y < t.height; ++y) {
        for (int x = kPost0; x < kPost1; ++x) scene_depth[size_t(y) * t.width + x] = float(window_depth_at(c, x, y, 0.9));
    }
    t.write_depth(scene_depth);
    // The scene colour is a separate texture here (the post is dark in it).
    EngineTarget scene(128, 96, GL_RGBA8, false);
    std::vector<float> scene_color = checkerboard(t.width, t.height, 8);
    for (int y = 0; y < t.height; ++y) {
        for (int x = kPost0; x < kPost1; ++x) {
            float* p = &scene_color[(size_t(y) * t.width + x) * 4];
            p[0] = p[1] = p[2] = 0.1f;
        }
    }
    scene.write_color(scene_color);
    t.write_color(scene_color);
    // A depth texture apart from the target's, as engines with a depth pre-pass have.
    EngineTarget depth(128, 96, GL_RGBA8, true);
    depth.write_depth(scene_depth);
    const pf_render_target target{t.fbo, scene.color, depth.depth, 0};
    ASSERT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, nullptr), PF_OK) << last_log();
    const std::vector<uint8_t> got = to_rgba8(t.read_color(), t.width, t.height);

    const std::string path = std::string(PF_GOLDEN_DIR) + "/ssf_composite.png";
    if (const char* update = std::getenv("PF_UPDATE_GOLDEN"); update && std::string(update) == "1") {
        ASSERT_TRUE(stbi_write_png(path.c_str(), t.width, t.height, 4, got.data(), t.width * 4));
        FAIL() << "wrote " << path << "; inspect it, commit it and run again without PF_UPDATE_GOLDEN";
    }
    int w = 0, h = 0, channels = 0;
    stbi_uc* golden = stbi_load(path.c_str(), &w, &h, &channels, 4);
    ASSERT_NE(golden, nullptr) << "cannot read " << path;
    ASSERT_EQ(w, t.width);
    ASSERT_EQ(h, t.height);
    // Tolerance: 4/255 per channel on 99% of the pixels, mean error below 1/255.
    const std::vector<uint8_t> behind = to_rgba8(scene_color, w, h);
    int off = 0, liquid = 0;
    double total = 0.0;
    for (int i = 0; i < w * h; ++i) {
        int worst = 0;
        for (int ch = 0; ch < 4; ++ch) {
            const int d = std::abs(int(got[size_t(i) * 4 + ch]) - int(golden[size_t(i) * 4 + ch]));
            worst = std::max(worst, d);
            total += d;
        }
        off += worst > 4;
        liquid += std::memcmp(&golden[size_t(i) * 4], &behind[size_t(i) * 4], 4) != 0;
    }
    stbi_image_free(golden);
    EXPECT_GT(liquid, 1000) << "the golden image shows too little liquid to be a meaningful reference";
    EXPECT_LE(off, w * h / 100) << off << " pixels differ by more than 4/255 from " << path;
    EXPECT_LT(total / (w * h * 4), 1.0) << "mean difference from " << path;
}

}  // namespace
}  // namespace pf::test
