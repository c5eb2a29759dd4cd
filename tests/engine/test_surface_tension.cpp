// Surface tension (PF_FEATURE_SURFACE_TENSION) against what it promises (issue 21). In zero
// gravity: a cube of liquid relaxes toward a sphere with its volume kept, and the kinetic energy
// it gains never exceeds the surface energy its area gave up; a small drop stays round and nearly
// still; a standing capillary wave oscillates at the frequency of linear theory,
// omega^2 = (sigma k^3 / rho) tanh(k h), without gaining energy; a drop on the smallest grid does
// not blow up; the substep count follows Brackbill's capillary limit; bad settings are refused
// with nothing changed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "standing_wave.h"
#include "support/sim_fixture.h"

namespace pf::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The shape of a body of particles: its centroid, and the radius that 99% of them lie within over
// the radius of the sphere of its volume (1 for a sphere, up to the particles' last half cell;
// a cube's corners lie at sqrt(3) (pi / 6)^(1/3) = 1.40, its 99th percentile near 1.2).
struct Shape {
    double centre[3] = {0, 0, 0};
    double roundness = 0;    // r99 / R_equivalent
    double kinetic = 0;      // J, with particle mass m
};

Shape shape_of(const ParticleState& p, double volume, double particle_mass) {
    Shape s;
    const size_t n = p.count();
    for (size_t i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a) s.centre[a] += p.pos[i * 3 + a] / double(n);
    std::vector<double> r(n);
    for (size_t i = 0; i < n; ++i) {
        double d2 = 0, v2 = 0;
        for (int a = 0; a < 3; ++a) {
            const double d = p.pos[i * 3 + a] - s.centre[a];
            d2 += d * d;
            v2 += double(p.vel[i * 3 + a]) * p.vel[i * 3 + a];
        }
        r[i] = std::sqrt(d2);
        s.kinetic += 0.5 * particle_mass * v2;
    }
    std::sort(r.begin(), r.end());
    const double r_eq = std::cbrt(3.0 * volume / (4.0 * kPi));
    s.roundness = n ? r[std::min(n - 1, size_t(0.99 * double(n)))] / r_eq : 0.0;
    return s;
}

class SurfaceTension : public GpuTest {
protected:
    // A closed box of n^3 cells of 1 cm in zero gravity with surface tension `sigma` (0: off).
    SimPtr zero_g(uint32_t n, float sigma, pf_sim_desc* out = nullptr) {
        pf_sim_desc d = test_desc(n, n, n, 0.01f);
        d.params.gravity[1] = 0.0f;
        d.features = sigma > 0.0f ? PF_FEATURE_SURFACE_TENSION : 0u;
        if (out) *out = d;
        SimPtr sim = create(d);
        if (sim && sigma > 0.0f) EXPECT_EQ(set(sim.get(), sigma), PF_OK) << last_log();
        return sim;
    }
    static pf_result set(pf_sim* sim, float sigma) {
        pf_surface_tension t = pf_default_surface_tension();
        t.tension = sigma;
        return pf_set_surface_tension(sim, &t);
    }
    static pf_surface_tension get(const pf_sim* sim) {
        pf_surface_tension t{};
        t.struct_size = sizeof t;
        EXPECT_EQ(pf_get_surface_tension(sim, &t), PF_OK);
        return t;
    }
};

// A cube 8 cells (8 cm) on a side in a 20^3 box, sigma 12.5 N/m (its capillary time
// sqrt(rho R^3 / sigma) is 0.07 s), for 0.5 s. Measured on llvmpipe: roundness 1.204 -> 1.050,
// the most kinetic energy 0.016 J of the 0.093 J the area released, volume 0.6% low.
TEST_F(SurfaceTension, CubeRelaxesTowardASphere) {
    constexpr float kSigma = 12.5f;
    pf_sim_desc d{};
    SimPtr sim = zero_g(20, kSigma, &d);
    ASSERT_TRUE(sim);
    const float lo = 0.06f, hi = 0.14f;
    const std::vector<float> pos = lattice_particles(d, [&](const float* p) {
        return p[0] > lo && p[0] < hi && p[1] > lo && p[1] < hi && p[2] > lo && p[2] < hi;
    });
    const std::vector<float> vel(pos.size(), 0.0f);
    ASSERT_EQ(pf_add_particles(sim.get(), pos.data(), vel.data(), uint32_t(pos.size() / 3)), PF_OK);
    // 8 particles a cell at rest density: the liquid's volume.
    const double volume = double(pos.size() / 3) * 1e-6 / 8.0, mass = 1000.0 * volume / double(pos.size() / 3);
    const double side = std::cbrt(volume), r_eq = std::cbrt(3.0 * volume / (4.0 * kPi));
    const double released = kSigma * (6.0 * side * side - 4.0 * kPi * r_eq * r_eq);  // J, cube to sphere
    const Shape start = shape_of(read_all(sim.get()), volume, mass);
    double most_kinetic = 0;
    Shape now = start;
    for (int f = 1; f <= 30; ++f) {
        ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        now = shape_of(read_all(sim.get()), volume, mass);
        most_kinetic = std::max(most_kinetic, now.kinetic);
    }
    const pf_stats st = settled_stats(sim.get());
    std::printf("roundness %.3f -> %.3f, most kinetic %.4f J of %.4f released, volume %.6f of %.6f m^3, substeps %u, "
                "flags 0x%x\n",
                start.roundness, now.roundness, most_kinetic, released, st.liquid_volume, volume, st.substeps, st.flags);
    EXPECT_GT(start.roundness, 1.15);
    EXPECT_LT(now.roundness, 1.1);
    // Surface energy turns into motion, never more than the area gave up.
    EXPECT_LT(most_kinetic, released);
    EXPECT_NEAR(st.liquid_volume / volume, 1.0, 0.02);
    EXPECT_FALSE(st.flags & (PF_FLAG_NONFINITE | PF_FLAG_SUBSTEPS_CLAMPED)) << st.flags;
}

// A drop 4 cells in radius in a 16^3 box at sigma 12.5 N/m, for 1 s: the jump around it is
// uniform, so only the curvature's errors move it (parasitic currents). Measured on llvmpipe:
// roundness at most 1.069, the most kinetic energy 4.5e-4 of the drop's surface energy (in the
// first frames, as the lattice's steps round off), after 0.5 s 2.6e-6 of it. With the substep at the
// whole of Brackbill's limit instead of half, this drop grew unstable after 0.5 s (docs/notes/2026-11-27-surface-tension-choices.md).
TEST_F(SurfaceTension, SmallDropStaysRoundAndStill) {
    constexpr float kSigma = 12.5f;
    pf_sim_desc d{};
    SimPtr sim = zero_g(16, kSigma, &d);
    ASSERT_TRUE(sim);
    const std::vector<float> pos = ball_particles(d, 0.08f, 0.04f);
    const std::vector<float> vel(pos.size(), 0.0f);
    ASSERT_EQ(pf_add_particles(sim.get(), pos.data(), vel.data(), uint32_t(pos.size() / 3)), PF_OK);
    const double volume = double(pos.size() / 3) * 1e-6 / 8.0, mass = 1e-3 / 8.0;
    const double r_eq = std::cbrt(3.0 * volume / (4.0 * kPi)), surface_energy = kSigma * 4.0 * kPi * r_eq * r_eq;
    const Shape start = shape_of(read_all(sim.get()), volume, mass);
    double most_kinetic = 0, least_round = 0, late_kinetic = 0;
    for (int f = 1; f <= 60; ++f) {
        ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        const Shape s = shape_of(read_all(sim.get()), volume, mass);
        most_kinetic = std::max(most_kinetic, s.kinetic);
        least_round = std::max(least_round, s.roundness);
        if (f > 30) late_kinetic = std::max(late_kinetic, s.kinetic);
    }
    std::printf("roundness %.3f, at most %.3f; most kinetic %.3g of the surface energy %.4f J, after 0.5 s %.3g\n",
                start.roundness, least_round, most_kinetic / surface_energy, surface_energy, late_kinetic / surface_energy);
    EXPECT_LT(least_round, 1.1);
    EXPECT_LT(most_kinetic, 1e-3 * surface_energy);
    EXPECT_LT(late_kinetic, 1e-5 * surface_energy);
}

// The first standing mode of a thin tank 16 cells (16 cm) long, liquid 8 cells deep, amplitude 1
// cell, zero gravity, sigma 35 N/m: omega^2 = (sigma k^3 / rho) tanh(k h), a period of 0.403 s
// (23 substeps a frame at half Brackbill's limit). Its energy is the particles' kinetic energy
// plus the mode's surface energy; the reference is taken a quarter period in, once the lattice's
// half-cell steps (area the mode's amplitude does not count) have rounded off. One jittered lattice
// decides little (docs/effects.md, "Surface tension"): single lattices of one library ranged from
// 17.7% short to 2.3% long and from 0 to 0.89 of the wave's energy gained (llvmpipe, 2026-12-06,
// docs/notes/2026-12-06-lone-particle-flip.md). So the wave is the mean over eight lattices: their
// mean amplitude is fitted and their mean energy checked. Bounds: period within 8%, under a quarter
// of the amplitude lost a period, energy at most 0.1 of the wave's above its reference.
TEST_F(SurfaceTension, CapillaryWaveHasTheTheoreticalFrequency) {
    pfs::StandingWave wave;
    wave.length = 0.16;
    wave.depth = 0.08;
    wave.amplitude = 0.01;
    wave.dx = 0.01;
    wave.thickness = 0.01;
    wave.gravity = 0.0;
    wave.tension = 35.0;
    pf_sim_desc d = test_desc(16, 16, 1, float(wave.dx));
    d.params.gravity[1] = 0.0f;
    d.params.max_substeps = 64;
    d.features = PF_FEATURE_SURFACE_TENSION;
    const auto energy = [&](const ParticleState& p) {
        return pfs::mechanical_energy_per_mass(wave, p.pos.data(), p.vel.data(), p.count()) +
               wave.surface_energy_per_mass(pfs::mode_amplitude(wave, p.pos.data(), p.count()));
    };
    const double e_wave = wave.wave_energy_per_mass();
    const int frames = int(std::ceil(3.0 * wave.period() * 60.0)), reference_frame = int(std::ceil(wave.period() * 15.0));
    constexpr int kLattices = 8;
    std::vector<double> t(size_t(frames) + 1), a(size_t(frames) + 1, 0.0), e(size_t(frames) + 1, 0.0);
    for (int f = 0; f <= frames; ++f) t[size_t(f)] = f / 60.0;
    for (uint32_t lattice = 1; lattice <= kLattices; ++lattice) {
        SimPtr sim = create(d);
        ASSERT_TRUE(sim);
        ASSERT_EQ(set(sim.get(), float(wave.tension)), PF_OK);
        const std::vector<float> pos = wave.lattice(lattice);
        const std::vector<float> vel(pos.size(), 0.0f);
        ASSERT_EQ(pf_add_particles(sim.get(), pos.data(), vel.data(), uint32_t(pos.size() / 3)), PF_OK);
        for (int f = 0; f <= frames; ++f) {
            if (f > 0) ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
            const ParticleState p = read_all(sim.get());
            a[size_t(f)] += pfs::mode_amplitude(wave, p.pos.data(), p.count()) / kLattices;
            e[size_t(f)] += energy(p) / kLattices;
        }
        const pf_stats st = settled_stats(sim.get());
        EXPECT_FALSE(st.flags & PF_FLAG_SUBSTEPS_CLAMPED) << "lattice " << lattice;
    }
    double gain = 0;
    for (int f = reference_frame + 1; f <= frames; ++f)
        gain = std::max(gain, (e[size_t(f)] - e[size_t(reference_frame)]) / e_wave);
    const pfs::WaveFit fit = pfs::fit_wave(t, a);
    std::printf("capillary wave, mean of %d lattices: a0 %.4f m, period %.4f s (theory %.4f, %+.2f%%), loss/period %.1f%% "
                "(%u extrema), energy gain max %.3f of the wave's\n",
                kLattices, a[0], fit.period, wave.period(), 100.0 * (fit.period / wave.period() - 1.0),
                100.0 * fit.loss_per_period, fit.extrema, gain);
    EXPECT_GE(fit.extrema, 5u);
    EXPECT_NEAR(fit.period / wave.period(), 1.0, 0.08);
    EXPECT_LT(fit.loss_per_period, 0.25);
    EXPECT_LT(gain, 0.1);
}

// The substeps follow the capillary limit: a tension whose half limit is shorter than the CFL
// substep raises the count to ceil(frame_dt / (0.5 sqrt(rho dx^3 / (4 pi sigma)))); with
// max_substeps below that the step is flagged, and the drop on a 4^3 grid at the largest tension
// accepted (1000 N/m: 119 substeps wanted, 16 allowed) stays finite, inside and calm: the step
// uses the tension its substeps are stable at.
TEST_F(SurfaceTension, SubstepsFollowTheCapillaryLimitAndTheSmallestGridStaysStable) {
    pf_sim_desc d{};
    SimPtr sim = zero_g(16, 12.5f, &d);
    ASSERT_TRUE(sim);
    const float lo[3] = {0.04f, 0.04f, 0.04f}, hi[3] = {0.12f, 0.12f, 0.12f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    const double limit = 0.5 * std::sqrt(1000.0 * 1e-6 / (4.0 * kPi * 12.5));
    EXPECT_EQ(settled_stats(sim.get()).substeps, uint32_t(std::ceil((1.0 / 60.0) / limit)));
    ASSERT_EQ(pf_set_features(sim.get(), 0), PF_OK);
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    EXPECT_LT(settled_stats(sim.get()).substeps, 3u);  // at rest, without it: the CFL's one or two

    SimPtr tiny = zero_g(4, 1000.0f, &d);
    ASSERT_TRUE(tiny);
    const std::vector<float> pos = ball_particles(d, 0.02f, 0.015f);
    ASSERT_GT(pos.size(), 0u);
    const std::vector<float> vel(pos.size(), 0.0f);
    ASSERT_EQ(pf_add_particles(tiny.get(), pos.data(), vel.data(), uint32_t(pos.size() / 3)), PF_OK);
    const double mass = 1e-3 / 8.0, surface_energy = 1000.0 * 4.0 * kPi * 0.015 * 0.015;
    for (int f = 0; f < 60; ++f) ASSERT_EQ(pf_step(tiny.get(), 1.0f / 60.0f), PF_OK);
    const ParticleState p = read_all(tiny.get());
    ASSERT_EQ(p.count(), pos.size() / 3);
    for (float x : p.pos) ASSERT_TRUE(std::isfinite(x) && x >= 0.0f && x <= 0.04f) << x;
    const Shape s = shape_of(p, double(p.count()) * 1e-6 / 8.0, mass);
    const pf_stats st = settled_stats(tiny.get());
    std::printf("tiny drop: kinetic %.3g J (%.3g of its surface energy), substeps %u, flags 0x%x\n", s.kinetic,
                s.kinetic / surface_energy, st.substeps, st.flags);
    EXPECT_LT(s.kinetic, 0.01 * surface_energy);
    EXPECT_TRUE(st.flags & PF_FLAG_SUBSTEPS_CLAMPED);
    EXPECT_FALSE(st.flags & PF_FLAG_NONFINITE);
}

TEST_F(SurfaceTension, RerunsAreBitIdenticalAndSnapshotsKeepTheSettings) {
    std::vector<float> runs[2];
    for (auto& out : runs) {
        SimPtr sim = zero_g(12, 20.0f);
        ASSERT_TRUE(sim);
        const float lo[3] = {0.02f, 0.02f, 0.03f}, hi[3] = {0.09f, 0.06f, 0.08f};
        ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
        for (int f = 0; f < 10; ++f) ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
        const ParticleState p = read_all(sim.get());
        out = p.pos;
        out.insert(out.end(), p.vel.begin(), p.vel.end());
    }
    ASSERT_FALSE(runs[0].empty());
    EXPECT_TRUE(runs[0] == runs[1]);

    SimPtr sim = zero_g(8, 3.5f);
    ASSERT_TRUE(sim);
    size_t size = 0;
    ASSERT_EQ(pf_snapshot_size(sim.get(), &size), PF_OK);
    std::vector<uint8_t> snapshot(size);
    ASSERT_EQ(pf_save_snapshot(sim.get(), snapshot.data(), size), PF_OK);
    ASSERT_EQ(set(sim.get(), 0.5f), PF_OK);
    ASSERT_EQ(pf_restore_snapshot(sim.get(), snapshot.data(), size), PF_OK) << last_log();
    EXPECT_EQ(get(sim.get()).tension, 3.5f);
}

// Bad settings: refused with a logged reason; the settings stay what they were.
TEST_F(SurfaceTension, BadSettingsAreRefusedAndChangeNothing) {
    SimPtr sim = create(test_desc(8, 8, 8, 0.1f));
    ASSERT_TRUE(sim);
    pf_surface_tension good = pf_default_surface_tension();
    EXPECT_EQ(good.tension, 0.072f);
    good.tension = 7.0f;
    ASSERT_EQ(pf_set_surface_tension(sim.get(), &good), PF_OK);
    for (float sigma : {std::nanf(""), INFINITY, -INFINITY, -0.001f, 1000.5f}) {
        pf_surface_tension bad = good;
        bad.tension = sigma;
        clear_log();
        EXPECT_EQ(pf_set_surface_tension(sim.get(), &bad), PF_ERROR_INVALID_ARGUMENT) << sigma;
        EXPECT_NE(std::string(last_log()).find("tension"), std::string::npos) << last_log();
        EXPECT_EQ(get(sim.get()).tension, 7.0f) << sigma;
    }
    EXPECT_EQ(pf_set_surface_tension(sim.get(), nullptr), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_get_surface_tension(sim.get(), nullptr), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_init_surface_tension(&good, 3), PF_ERROR_INVALID_ARGUMENT);
    // A zero-initialised struct takes the defaults; zero tension is accepted (no force).
    pf_surface_tension zero{};
    ASSERT_EQ(pf_set_surface_tension(sim.get(), &zero), PF_OK) << last_log();
    EXPECT_EQ(get(sim.get()).tension, 0.072f);
    good.tension = 0.0f;
    EXPECT_EQ(pf_set_surface_tension(sim.get(), &good), PF_OK);
}

}  // namespace
}  // namespace pf::test
