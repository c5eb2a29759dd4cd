// Surface tension's pressure jump against Laplace's law: a drop of radius R at rest in zero
// gravity holds a pressure 2 sigma / R above the air's. The drops below (radius 4 and 6 cells of
// 1 cm, sigma 12.5 N/m) settle for a quarter second; the mean solved pressure of the cells whose
// centres lie more than two cells inside the surface is compared with 2 sigma / R, R the radius of
// the sphere of the particles' rest volume.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "api/handle.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

class SurfaceTensionPressure : public GpuTest {
protected:
    // Mean interior pressure over 2 sigma / R for a drop of `radius_cells` in an n^3 box.
    double laplace_ratio(uint32_t n, float radius_cells) {
        constexpr float kSigma = 12.5f, kDx = 0.01f;
        pf_sim_desc d = test_desc(n, n, n, kDx);
        d.params.gravity[1] = 0.0f;
        d.features = PF_FEATURE_SURFACE_TENSION;
        SimPtr handle = create(d);
        if (!handle) return NAN;
        pf_surface_tension t = pf_default_surface_tension();
        t.tension = kSigma;
        EXPECT_EQ(pf_set_surface_tension(handle.get(), &t), PF_OK);
        const float c = 0.5f * float(n) * kDx;
        const std::vector<float> pos = ball_particles(d, c, radius_cells * kDx);
        const std::vector<float> vel(pos.size(), 0.0f);
        EXPECT_EQ(pf_add_particles(handle.get(), pos.data(), vel.data(), uint32_t(pos.size() / 3)), PF_OK);
        for (int f = 0; f < 15; ++f) EXPECT_EQ(pf_step(handle.get(), 1.0f / 60.0f), PF_OK);
        const Simulation& sim = *pf::entry(handle)->impl;
        const std::vector<uint32_t> words = sim.read_grid(GridBuffer::pressure);
        const double volume = double(pos.size() / 3) * double(kDx) * kDx * kDx / 8.0;
        const double r_eq = std::cbrt(3.0 * volume / (4.0 * kPi));
        double sum = 0;
        int cells = 0;
        for (uint32_t k = 0; k < n; ++k)
            for (uint32_t j = 0; j < n; ++j)
                for (uint32_t i = 0; i < n; ++i) {
                    const double x = (i + 0.5) * kDx - c, y = (j + 0.5) * kDx - c, z = (k + 0.5) * kDx - c;
                    if (std::sqrt(x * x + y * y + z * z) > r_eq - 2.0 * kDx) continue;
                    float p = 0;
                    std::memcpy(&p, &words[i + n * (j + n * k)], sizeof p);
                    sum += p;
                    ++cells;
                }
        const double expected = 2.0 * kSigma / r_eq;
        std::printf("drop of %.1f cells: interior pressure %.1f Pa over %d cells, 2 sigma / R = %.1f Pa (ratio %.3f)\n",
                    radius_cells, cells ? sum / cells : 0.0, cells, expected, cells ? sum / cells / expected : 0.0);
        return cells ? sum / cells / expected : NAN;
    }
};

// The curvature's error is first order in the cell over the radius: the bound is 0.5 / R in
// cells. Measured on llvmpipe: 9.1% low at 4 cells, 2.6% at 6. Without moving the curvature
// from the AIR centres to the surface (st_force.comp) it was 17% and 9% low.
TEST_F(SurfaceTensionPressure, DropHoldsTheLaplacePressure) {
    EXPECT_NEAR(laplace_ratio(16, 4.0f), 1.0, 0.5 / 4.0);
    EXPECT_NEAR(laplace_ratio(20, 6.0f), 1.0, 0.5 / 6.0);
}

}  // namespace
}  // namespace pf::test
