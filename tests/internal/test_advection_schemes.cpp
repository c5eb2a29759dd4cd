// The advection schemes on a rigidly rotating grid velocity, set directly on the faces (no
// P2G or pressure solve): u = w z x (x - c). The field is linear, so the §3 interpolant
// reproduces it exactly away from the clamped border, and every scheme becomes a linear map
// per substep: Euler x' - c = (I + hA)(x - c), and any explicit Runge-Kutta scheme of order
// p = stages (midpoint, Ralston's third order) the Taylor polynomial of exp(hA) to degree p.
// For a rotation by theta = w dt per substep the radius is multiplied by |P(i theta)|:
// sqrt(1 + theta^2) for Euler (the outward spiral), sqrt(1 + theta^4 / 4) for RK2 and
// sqrt((1 - theta^2/2)^2 + (theta - theta^3/6)^2) for RK3. The GPU must follow these
// factors to float rounding, and the exact path (radius R) best with RK3.
#include <cmath>
#include <complex>
#include <cstdio>

#include "api/handle.h"
#include "reference/cpu_reference.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

struct Orbit {
    double worst_radius_error;     // max over particles of |r_N - R| / R
    double worst_model_error;      // max over particles of |r_N - R |P|^N| / R
};

class AdvectionSchemes : public GpuTest {
protected:
    static constexpr double kOmega = 2.0;   // rad/s about z
    static constexpr double kDt = 0.05;     // theta = 0.1 rad per substep
    static constexpr int kSteps = 63;       // ~ one turn (2 pi / 0.1)
    static constexpr double kRadius = 0.4;  // m: 4 cells, inside the unclamped interior

    // |P(i theta)| of the scheme's stability polynomial.
    static double radius_factor(pf_advection scheme, double theta) {
        const std::complex<double> z(0.0, theta);
        std::complex<double> p = 1.0 + z;
        if (scheme >= PF_ADVECTION_RK2) p += z * z / 2.0;
        if (scheme >= PF_ADVECTION_RK3) p += z * z * z / 6.0;
        return std::abs(p);
    }

    Orbit orbit(pf_advection scheme) {
        // 16 x 16 x 4 cells of 0.1 m centred on the world origin, so positions stay small.
        pf_sim_desc d = test_desc(16, 16, 4, 0.1f);
        d.origin[0] = d.origin[1] = -0.8f;
        d.origin[2] = -0.2f;
        d.params.gravity[1] = 0.0f;
        d.params.flip_ratio = 0.0f;  // Euler moves with the G2P (PIC) velocity: the same field
        d.params.advection = scheme;
        SimPtr handle = create(d);
        EXPECT_TRUE(handle);
        if (!handle) return {NAN, NAN};
        Simulation& sim = *pf::entry(handle)->impl;

        // Face velocities of the rotation about the origin: u = -w y on u faces, v = w x on v faces.
        const ref::Grid grid{16, 16, 4, d.cell_size, glm::dvec3(d.origin[0], d.origin[1], d.origin[2])};
        const std::vector<uint32_t> words = floats_as_words(ref::sample_faces(grid, [&](int axis, const glm::dvec3& g) {
            const glm::dvec3 x = grid.to_world(g);
            return axis == 0 ? -kOmega * x.y : axis == 1 ? kOmega * x.x : 0.0;
        }));
        sim.write_grid_for_test(GridBuffer::face_vel, words);

        // 12 particles on the circle of radius R in the plane z = 0, at different phases.
        std::vector<float> pos;
        for (int p = 0; p < 12; ++p) {
            const double a = 2.0 * M_PI * p / 12.0 + 0.1;
            pos.insert(pos.end(), {float(kRadius * std::cos(a)), float(kRadius * std::sin(a)), 0.0f});
        }
        EXPECT_EQ(pf_add_particles(handle.get(), pos.data(), nullptr, 12), PF_OK) << last_log();
        for (int s = 0; s < kSteps; ++s) EXPECT_EQ(sim.run_g2p_and_advect_for_test(float(kDt)), PF_OK);

        const ParticleState end = read_all(handle.get());
        const double model = std::pow(radius_factor(scheme, kOmega * kDt), kSteps);
        Orbit o{0.0, 0.0};
        for (size_t p = 0; p < end.count(); ++p) {
            const double r0 = std::hypot(double(pos[p * 3]), double(pos[p * 3 + 1]));
            const double r = std::hypot(double(end.pos[p * 3]), double(end.pos[p * 3 + 1]));
            o.worst_radius_error = std::max(o.worst_radius_error, std::abs(r - r0) / r0);
            o.worst_model_error = std::max(o.worst_model_error, std::abs(r - r0 * model) / r0);
        }
        return o;
    }
};

TEST_F(AdvectionSchemes, RungeKuttaFollowsARotationFarBetterThanEuler) {
    const Orbit euler = orbit(PF_ADVECTION_EULER), rk2 = orbit(PF_ADVECTION_RK2), rk3 = orbit(PF_ADVECTION_RK3);
    std::printf("radius error after %d substeps of %.2f rad: Euler %.3e, RK2 %.3e, RK3 %.3e "
                "(vs |P|^N: %.1e, %.1e, %.1e)\n",
                kSteps, kOmega * kDt, euler.worst_radius_error, rk2.worst_radius_error, rk3.worst_radius_error,
                euler.worst_model_error, rk2.worst_model_error, rk3.worst_model_error);
    // Each scheme is the one it claims: its radius follows |P(i theta)|^N to float rounding.
    // Bound: per substep a few roundings (8 eps) of coordinates up to 1.4 R (Euler's final
    // radius), accumulated over N substeps, relative to R.
    const double rounding = kSteps * 8.0 * std::ldexp(1.0, -24) * 1.4;
    EXPECT_LE(euler.worst_model_error, rounding);
    EXPECT_LE(rk2.worst_model_error, rounding);
    EXPECT_LE(rk3.worst_model_error, rounding);
    // Against the exact circle (theory: Euler 1.01^31.5 - 1 = 37%, RK2 N theta^4 / 8 = 7.9e-4,
    // RK3 N theta^4 / 24 = 2.6e-4): RK3 is three orders of magnitude closer than Euler, RK2 in
    // between. Bounds are the measured ratios (1400 and 3) with margin.
    EXPECT_GT(euler.worst_radius_error, 0.3);
    EXPECT_LT(rk3.worst_radius_error, euler.worst_radius_error / 500.0);
    EXPECT_LT(rk2.worst_radius_error, euler.worst_radius_error / 100.0);
    EXPECT_LT(rk3.worst_radius_error, rk2.worst_radius_error / 2.0);
}

}  // namespace
}  // namespace pf::test
