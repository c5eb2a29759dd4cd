// Shared pieces of the GPU tests: a fixture that skips nothing — it fails if no GL 4.3
// context can be made — and helpers to create simulations and read particles back.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "pf/pf.h"
#include "support/test_context.h"

namespace pf::test {

// PF_STABILITY_LONG is set: the long physics runs go at their full size and length (by hand;
// CI runs the fast mode, which keeps every case but shrinks the costliest ones, as each file says).
inline bool long_mode() { return std::getenv("PF_STABILITY_LONG") != nullptr; }

struct SimDeleter {
    void operator()(pf_sim* s) const { pf_destroy(s); }
};
using SimPtr = std::unique_ptr<pf_sim, SimDeleter>;

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(ensure_context()) << "no OpenGL 4.3 context through EGL"; }

    SimPtr create(const pf_sim_desc& desc) {
        pf_sim* s = nullptr;
        const pf_result r = pf_create(&desc, &s);
        EXPECT_EQ(r, PF_OK) << last_log();
        return SimPtr(s);
    }
};

struct ParticleState {
    std::vector<float> pos, vel;  // 3 floats per particle
    size_t count() const { return pos.size() / 3; }
};

// An output pf_sim_params of this header's layout: pf_get_params and pf_quality_params fill every
// field (a zero struct_size means the first layout, which ends before free_surface).
inline pf_sim_params sized_params() {
    pf_sim_params p{};
    p.struct_size = sizeof p;
    return p;
}

// Largest particle speed, m/s.
inline double max_speed_of(const ParticleState& p) {
    double m = 0;
    for (size_t i = 0; i < p.count(); ++i)
        m = std::max(m, std::sqrt(double(p.vel[i * 3]) * p.vel[i * 3] + double(p.vel[i * 3 + 1]) * p.vel[i * 3 + 1] +
                                  double(p.vel[i * 3 + 2]) * p.vel[i * 3 + 2]));
    return m;
}

// Particles per cell, counted as P2G counts them: the cell clamp(floor((x - origin) / dx), 0, n-1).
inline std::vector<uint32_t> cell_counts_of(const ParticleState& p, const pf_sim_desc& d) {
    const uint32_t* n = d.grid_size;
    std::vector<uint32_t> count(size_t(n[0]) * n[1] * n[2], 0u);
    for (size_t i = 0; i < p.count(); ++i) {
        size_t index = 0, stride = 1;
        for (int a = 0; a < 3; ++a) {
            const int c = int(std::floor((p.pos[i * 3 + a] - d.origin[a]) / d.cell_size));
            index += size_t(std::clamp(c, 0, int(n[a]) - 1)) * stride;
            stride *= n[a];
        }
        ++count[index];
    }
    return count;
}

// Particle-density volume (pf_stats.particle_volume): dx^3 * sum over cells of
// min(count / fill_particles_per_cell, 1), in m^3. Falls where particles clump.
inline double particle_volume_of(const std::vector<uint32_t>& count, const pf_sim_desc& d) {
    const double rest = double(d.fill_particles_per_cell);
    double cells = 0;
    for (uint32_t c : count) cells += std::min(double(c) / rest, 1.0);
    return cells * double(d.cell_size) * d.cell_size * d.cell_size;
}

// The interior cells (pf_stats.interior_density, without obstacles): those holding a particle
// whose face neighbours all hold one or are domain walls, and their mean count /
// fill_particles_per_cell (0 when there are none).
struct Interior {
    size_t cells = 0;
    double density = 0;
};
inline Interior interior_of(const std::vector<uint32_t>& count, const pf_sim_desc& d) {
    const int n[3] = {int(d.grid_size[0]), int(d.grid_size[1]), int(d.grid_size[2])};
    auto at = [&](int x, int y, int z) { return count[size_t(x) + size_t(n[0]) * (size_t(y) + size_t(n[1]) * size_t(z))]; };
    double sum = 0;
    Interior out;
    for (int z = 0; z < n[2]; ++z)
        for (int y = 0; y < n[1]; ++y)
            for (int x = 0; x < n[0]; ++x) {
                const uint32_t c = at(x, y, z);
                if (c == 0) continue;
                const int nb[6][3] = {{x - 1, y, z}, {x + 1, y, z}, {x, y - 1, z}, {x, y + 1, z}, {x, y, z - 1}, {x, y, z + 1}};
                bool inner = true;
                for (const auto& q : nb) {
                    const bool wall = q[0] < 0 || q[1] < 0 || q[2] < 0 || q[0] >= n[0] || q[1] >= n[1] || q[2] >= n[2];
                    if (!wall && at(q[0], q[1], q[2]) == 0) inner = false;
                }
                if (!inner) continue;
                sum += c;
                ++out.cells;
            }
    if (out.cells) out.density = sum / double(out.cells) / double(d.fill_particles_per_cell);
    return out;
}

// Liquid volume (pf_stats.liquid_volume, without obstacles): the particles' rest volume
// (count * dx^3 / fill_particles_per_cell) over their interior density; the rest volume when no
// cell is interior.
inline double liquid_volume_of(const std::vector<uint32_t>& count, const pf_sim_desc& d) {
    double particles = 0;
    for (uint32_t c : count) particles += c;
    const double rest_volume = particles / d.fill_particles_per_cell * double(d.cell_size) * d.cell_size * d.cell_size;
    const Interior interior = interior_of(count, d);
    return interior.cells ? rest_volume / interior.density : rest_volume;
}

// Depth of a liquid at rest: the mean over occupied cell columns (x, z) of the highest particle's
// height above the grid's floor, in metres.
inline double surface_depth_of(const ParticleState& p, const pf_sim_desc& d) {
    const uint32_t nx = d.grid_size[0], nz = d.grid_size[2];
    std::vector<double> top(size_t(nx) * nz, -1.0);
    for (size_t i = 0; i < p.count(); ++i) {
        const int cx = std::clamp(int(std::floor((p.pos[i * 3] - d.origin[0]) / d.cell_size)), 0, int(nx) - 1);
        const int cz = std::clamp(int(std::floor((p.pos[i * 3 + 2] - d.origin[2]) / d.cell_size)), 0, int(nz) - 1);
        double& t = top[size_t(cz) * nx + size_t(cx)];
        t = std::max(t, double(p.pos[i * 3 + 1]) - d.origin[1]);
    }
    double sum = 0;
    size_t columns = 0;
    for (double t : top) {
        if (t < 0) continue;
        sum += t;
        ++columns;
    }
    return columns ? sum / double(columns) : 0.0;
}

// Raw 32-bit words of a GPU buffer read as floats (widened to double for comparisons).
inline std::vector<double> words_as_floats(const std::vector<uint32_t>& words) {
    std::vector<double> out(words.size());
    for (size_t i = 0; i < words.size(); ++i) {
        float f;
        std::memcpy(&f, &words[i], 4);
        out[i] = f;
    }
    return out;
}

// Values as the raw 32-bit words of a GPU float buffer (narrowed to float).
inline std::vector<uint32_t> floats_as_words(const std::vector<double>& values) {
    std::vector<uint32_t> words(values.size());
    for (size_t i = 0; i < values.size(); ++i) {
        const float f = float(values[i]);
        std::memcpy(&words[i], &f, 4);
    }
    return words;
}

// Exact live count (waits for the GPU while emitters or sinks are on).
inline uint32_t live_count(pf_sim* sim) {
    uint32_t n = 0;
    EXPECT_EQ(pf_get_particle_count(sim, &n), PF_OK);
    return n;
}

// The per-pass statistics list, in its order (names valid until the simulation is destroyed).
inline std::vector<pf_pass_stats> pass_list(const pf_sim* sim) {
    uint32_t n = 0;
    EXPECT_EQ(pf_get_pass_count(sim, &n), PF_OK);
    std::vector<pf_pass_stats> out(n);
    for (uint32_t i = 0; i < n; ++i) EXPECT_EQ(pf_get_pass_stats(sim, i, &out[i]), PF_OK);
    return out;
}

inline ParticleState read_all(pf_sim* sim) {
    const uint32_t n = live_count(sim);
    ParticleState p;
    p.pos.resize(size_t(n) * 3);
    p.vel.resize(size_t(n) * 3);
    EXPECT_EQ(pf_read_particles(sim, 0, n, p.pos.data(), p.vel.data()), PF_OK);
    return p;
}

// Particles on a 2 x 2 x 2 lattice per cell (jitter-free; the grid's origin at 0): every site
// for which inside(site) holds (xyz triples).
template <typename Inside> std::vector<float> lattice_particles(const pf_sim_desc& d, Inside inside) {
    std::vector<float> pos;
    const float s = d.cell_size / 2;
    for (uint32_t z = 0; z < 2 * d.grid_size[2]; ++z)
        for (uint32_t y = 0; y < 2 * d.grid_size[1]; ++y)
            for (uint32_t x = 0; x < 2 * d.grid_size[0]; ++x) {
                const float p[3] = {(x + 0.5f) * s, (y + 0.5f) * s, (z + 0.5f) * s};
                if (inside(p)) pos.insert(pos.end(), {p[0], p[1], p[2]});
            }
    return pos;
}

// The lattice's sites inside a ball of `radius` around (c, c, c).
inline std::vector<float> ball_particles(const pf_sim_desc& d, float c, float radius) {
    return lattice_particles(d, [&](const float* p) {
        return (p[0] - c) * (p[0] - c) + (p[1] - c) * (p[1] - c) + (p[2] - c) * (p[2] - c) < radius * radius;
    });
}

// The stats once the GPU has finished every step so far (reading the particles back waits for it).
inline pf_stats settled_stats(pf_sim* sim) {
    (void)read_all(sim);
    pf_stats st{};
    st.struct_size = sizeof st;
    EXPECT_EQ(pf_get_stats(sim, &st), PF_OK);
    return st;
}

}  // namespace pf::test
