// The first sloshing mode of a rectangular tank, measured from particles (issue 17): the
// scene (a jittered lattice under eta = A cos(k x)), the mode's amplitude, the mechanical
// energy, and the period and damping of a recorded amplitude history. Pure C++ (no GL): the
// engine tests and pf_accuracy share it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pfs {

struct StandingWave {
    double length = 3.2;      // tank length along x, m (the mode's half wavelength)
    double depth = 1.6;       // still-water depth, m
    double amplitude = 0.1;   // surface displacement at the end walls at t = 0, m
    double thickness = 0.1;   // tank extent along z, m
    double dx = 0.05;         // cell size, m (the lattice puts 2 x 2 x 2 particles in a cell)
    double gravity = 9.81;    // m/s^2, along -y
    double tension = 0.0;     // surface tension sigma, N/m (0: a pure gravity wave)
    double density = 1000.0;  // kg/m^3

    double wavenumber() const;           // k = pi / length
    double omega() const;                // linear theory: omega^2 = (g k + sigma k^3 / rho) tanh(k h)
    double period() const;               // 2 pi / omega, s
    // Particles of a 2x2x2 sub-lattice per cell, each jittered by up to `jitter` of the
    // sub-cell spacing (seeded), kept where y < depth + amplitude * cos(k x) (xyz triples).
    std::vector<float> lattice(uint32_t seed, double jitter = 0.25, double amplitude_override = -1.0) const;
    // Mechanical energy of the wave above the flat tank holding the same particles, per unit
    // mass, from linear theory's (g + sigma k^2 / rho) A^2 / (4 h): the scale energy drift is
    // measured in.
    double wave_energy_per_mass() const;
    // Surface energy of the mode at amplitude a above the flat surface's, per unit mass: sigma
    // times the extra area (k a)^2 L / 4 per unit width, over the liquid's mass (linear theory).
    double surface_energy_per_mass(double a) const;
};

// The mode's amplitude from particle positions: each column's height is its particle count at
// the rest density (8 per cell), so a splash or a noisy top particle cannot move it; the
// heights are projected onto cos(k x). m.
double mode_amplitude(const StandingWave& wave, const float* pos, size_t count);

// Kinetic plus potential energy per unit mass (potential from y = 0 along -y), J/kg.
double mechanical_energy_per_mass(const StandingWave& wave, const float* pos, const float* vel, size_t count);

// Period and damping of an amplitude history a(t) sampled at times t (seconds).
struct WaveFit {
    double period = 0;              // s, from downward and upward zero crossings (0: fewer than 3)
    double loss_per_period = 0;     // 1 - (amplitude after one period / before), from a
                                    // least-squares line through log |a| at the extrema
    uint32_t crossings = 0;         // zero crossings found
    uint32_t extrema = 0;           // extrema fitted
};
WaveFit fit_wave(const std::vector<double>& t, const std::vector<double>& a);

}  // namespace pfs
