// Divergence after projection: with enough Jacobi iterations the GPU's projected face
// velocities are discretely divergence free on every FLUID cell; with the original's 40
// iterations they are not (measured here, so the cost of accuracy is visible).
#include <cmath>
#include <cstring>
#include <random>

#include "api/handle.h"
#include "reference/cpu_reference.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class Projection : public GpuTest {
protected:
    // Max |div| over FLUID cells before (from the right-hand side) and after projection.
    std::pair<double, double> project(uint32_t iterations) {
        pf_sim_desc d = test_desc(16, 16, 16, 0.05f);
        d.params.pressure_iterations = iterations;
        SimPtr handle = create(d);
        EXPECT_TRUE(handle);
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> u(0.0f, 1.0f), uv(-1.0f, 1.0f);
        std::vector<float> pos, vel;
        for (int i = 0; i < 12000; ++i) {
            pos.insert(pos.end(), {0.8f * u(rng), 0.5f * u(rng), 0.8f * u(rng)});
            vel.insert(vel.end(), {uv(rng), uv(rng), uv(rng)});
        }
        EXPECT_EQ(pf_add_particles(handle.get(), pos.data(), vel.data(), 12000), PF_OK);
        Simulation& sim = *handle->impl;
        const double dt = 0.01;
        EXPECT_EQ(sim.run_substep_for_test(float(dt)), PF_OK);

        const ref::Grid g{16, 16, 16, d.cell_size, glm::dvec3(0.0)};
        const std::vector<uint32_t> type_words = sim.read_grid(GridBuffer::cell_type);
        const std::vector<uint32_t> rhs_words = sim.read_grid(GridBuffer::rhs);
        const std::vector<uint32_t> vel_words = sim.read_grid(GridBuffer::face_vel);
        std::vector<uint8_t> type(type_words.begin(), type_words.end());
        std::vector<double> face(vel_words.size());
        double before = 0;
        for (size_t c = 0; c < rhs_words.size(); ++c) {
            float b;
            std::memcpy(&b, &rhs_words[c], 4);
            before = std::max(before, std::abs(double(b)) * dt / (d.density * d.cell_size));  // b = -div rho dx / dt
        }
        for (size_t f = 0; f < face.size(); ++f) {
            float v;
            std::memcpy(&v, &vel_words[f], 4);
            face[f] = v;
        }
        double after = 0;
        for (double div : ref::divergence(g, type, face)) after = std::max(after, std::abs(div));
        return {before, after};
    }
};

TEST_F(Projection, ConvergedJacobiRemovesDivergence) {
    const auto [before, after] = project(3000);
    ASSERT_GT(before, 0.5);  // random velocities: strongly divergent input (m/s per cell)
    // Float pressure (~1e3 Pa) rounds at ~1e-4 Pa, i.e. ~1e-7 m/s of face velocity.
    EXPECT_LT(after, 1e-4 * before);
}

TEST_F(Projection, FortyIterationsLeaveMeasurableDivergence) {
    const auto [before40, after40] = project(40);
    const auto [before400, after400] = project(400);
    EXPECT_DOUBLE_EQ(before40, before400);  // the same input
    EXPECT_LT(after40, before40);            // Jacobi reduces divergence...
    EXPECT_LT(after400, 0.5 * after40);      // ...and ten times the iterations reduce it further
    RecordProperty("div_after_40", std::to_string(after40 / before40));
    RecordProperty("div_after_400", std::to_string(after400 / before400));
}

}  // namespace
}  // namespace pf::test
