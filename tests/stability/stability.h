// The stability suite's shared rules (issue 7, docs/stability.md): every case runs with each
// quality preset, and after every checked frame the simulation must be sound — every particle
// finite and inside the domain, every grid face velocity and pressure finite, the particle
// count what the case put in, the mechanical energy not above what the case put in, and
// pf_step still returning PF_OK. What each case adds (volume drift, rest, symmetry) it asserts
// itself, with the bound and the measurement next to it.
#pragma once
#include <string>
#include <vector>

#include "support/sim_fixture.h"

namespace pf::test {

// Every message one simulation logged, by level (the suite checks that a degraded step says so).
struct LogRecord {
    std::vector<std::string> warnings, errors;
    // Number of warnings containing `text`.
    size_t warnings_with(const std::string& text) const;
};

// Mechanical energy of the particles, J: kinetic 0.5 m |v|^2 and potential m (-g . x), the
// potential measured from the domain corner lowest along g (so it is >= 0).
struct Energy {
    double kinetic = 0, potential = 0;
    double total() const { return kinetic + potential; }
};
Energy energy_of(const ParticleState& p, const pf_sim_desc& d);
// Particle mass of the simulation, kg (pf_stats.kinetic_energy's m).
double particle_mass(const pf_sim_desc& d);

// What one soundness check found (all zero when sound).
struct Soundness {
    size_t nonfinite_particles = 0;  // a position or velocity component NaN/Inf
    size_t outside = 0;              // a particle outside [origin, origin + extent]
    size_t nonfinite_grid = 0;       // a face velocity or pressure NaN/Inf
    size_t count = 0;                // live particles
    Energy energy;
    double volume = 0;               // particle-density volume (particle_volume_of), m^3
    double liquid = 0;               // liquid volume, mass over density (liquid_volume_of), m^3
    double max_speed = 0;            // m/s
};

class Stability : public GpuTest, public ::testing::WithParamInterface<pf_quality> {
protected:
    // test_desc() with the preset's parameters (gravity default) and a logger into log_.
    pf_sim_desc desc(uint32_t nx, uint32_t ny, uint32_t nz, float cell_size);
    // Reads particles and grid back and checks the universal rules (EXPECTs, with `when` in
    // the message); returns what it measured.
    Soundness check(pf_sim* sim, const pf_sim_desc& d, size_t expected_count, const std::string& when);
    // Steps `frames` frames of `dt`, each of which must return PF_OK.
    void run(pf_sim* sim, float dt, int frames);
    // pf_stats of the simulation after glFinish (so the last step's readback has landed).
    static pf_stats settled_stats(pf_sim* sim);
    // Records a measurement in the test's XML output and on stderr (docs/stability.md tables).
    void record(const std::string& key, double value);
    // The simulation still works: a box of particles is added, one step runs, all is sound
    // (emitters and sinks must be off or away from the domain's middle cell for that step).
    void expect_usable(pf_sim* sim, const pf_sim_desc& d, const std::string& when);

    LogRecord log_;
};

// Name of a preset for test names: fast, balanced, accurate.
std::string preset_name(const ::testing::TestParamInfo<pf_quality>& info);

}  // namespace pf::test

// Instantiates a Stability-derived suite once per quality preset.
#define PF_STABILITY_PRESETS(Suite)                                                                         \
    INSTANTIATE_TEST_SUITE_P(Presets, Suite,                                                                \
                             ::testing::Values(PF_QUALITY_FAST, PF_QUALITY_BALANCED, PF_QUALITY_ACCURATE), \
                             ::pf::test::preset_name)
