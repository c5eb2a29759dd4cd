// The decaying-vortex setup the vorticity confinement and viscosity tests share: a closed 1 m box
// of 16^3 cells, full, turning as one cellular vortex u = 0.5 sin(pi x) cos(pi y),
// v = -0.5 cos(pi x) sin(pi y) (divergence-free, zero normal velocity at the walls), 8 particles
// a cell on a regular lattice; and the particles' kinetic energy per unit mass.
#pragma once
#include <cmath>
#include <vector>

#include "support/sim_fixture.h"

namespace pf::test {

// Positions and velocities (xyz each) of the vortex's particles in a box of d's cell size.
inline void cellular_vortex_particles(const pf_sim_desc& d, std::vector<float>& pos, std::vector<float>& vel) {
    constexpr double kPi = 3.14159265358979323846;
    const double s = d.cell_size / 2.0;
    for (int k = 0; k < 32; ++k)
        for (int j = 0; j < 32; ++j)
            for (int i = 0; i < 32; ++i) {
                const double x = (i + 0.5) * s, y = (j + 0.5) * s, z = (k + 0.5) * s;
                pos.insert(pos.end(), {float(x), float(y), float(z)});
                vel.insert(vel.end(), {float(0.5 * std::sin(kPi * x) * std::cos(kPi * y)),
                                       float(-0.5 * std::cos(kPi * x) * std::sin(kPi * y)), 0.0f});
            }
}

// Mean of |v|^2 / 2 over the particles (J/kg).
inline double kinetic_energy_per_mass(const ParticleState& p) {
    double e = 0;
    for (float v : p.vel) e += 0.5 * double(v) * v;
    return p.count() ? e / double(p.count()) : 0.0;
}

}  // namespace pf::test
