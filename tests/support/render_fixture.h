// Fixture of the rendering tests: a GL context with the app's GLAD loaded, one simulation
// whose domain is [0, 1.6]^3 (16^3 cells of 0.1 m) holding exactly the particles a test adds,
// and a camera looking at the domain's centre from +z.
#pragma once
#include <glad/gl.h>

#include <vector>

#include "support/engine_state.h"
#include "support/render_scene.h"
#include "support/sim_fixture.h"

namespace pf::test {

class RenderTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc)));
        drain_gl_errors();
        pf_sim_desc d = test_desc(16, 16, 16, 0.1f);
        d.max_particles = 1u << 16;
        sim_ = create(d);
        ASSERT_TRUE(sim_);
    }

    void add(const std::vector<float>& xyz, const std::vector<float>& vel = {}) {
        ASSERT_EQ(pf_add_particles(sim_.get(), xyz.data(), vel.empty() ? nullptr : vel.data(), uint32_t(xyz.size() / 3)),
                  PF_OK)
            << last_log();
    }

    // Camera at (0.8, 0.8, 3.2) looking at (0.8, 0.8, 0.8), 45 degree vertical field of view.
    static TestCamera camera(const int viewport[4], pf_depth_convention conv = PF_DEPTH_STANDARD) {
        return make_camera({0.8, 0.8, 3.2}, {0.8, 0.8, 0.8}, 45.0, viewport, 0.1, 10.0, conv);
    }

    SimPtr sim_;
};

// Deterministic jitter in [-1, 1] (the same on every platform, unlike <random> distributions).
inline float hash_jitter(uint32_t i) {
    i ^= i >> 16;
    i *= 0x7feb352du;
    i ^= i >> 15;
    i *= 0x846ca68bu;
    i ^= i >> 16;
    return float(i & 0xffffffu) / float(0x800000u) - 1.0f;
}

}  // namespace pf::test
