// pf_accuracy — what accuracy costs in time (issue 6).
//
// Sweeps the simulation's knobs over fixed physical test cases and records, for each
// (configuration, case), accuracy metrics measured from the particles (read back after the run)
// and the GPU milliseconds per frame (pf_get_stats timer queries, each measured step once).
// Configurations vary one knob at a time from the original's scheme, plus the
// three presets; scripts/plot_accuracy.py draws metric against time per knob and the Pareto
// front across all of them (docs/accuracy.md).
//
// Cases (grid n per axis, 1 m domain unless said otherwise, frame dt 1/60 s):
//   hydrostatic   tank half full at rest for 2 s: spurious speed / sqrt(g dx), depth change
//   rotation      zero gravity, a ball spinning at 2 rad/s for 1 s: angular momentum lost
//   closed_box    zero gravity, a full closed box with a divergence-free vortex for 1 s:
//                 kinetic energy lost (nothing should dissipate it)
//   standing_wave the first sloshing mode of a tank 3.2 m long and 1.6 m deep (n x 3n/4 cells,
//                 n/8 thick; the issue 17 tank at n = 64), amplitude 0.1 m, for 10 periods:
//                 period error against linear theory w^2 = g k tanh(k h), amplitude lost per
//                 period, and the mechanical energy's largest rise and final drift as shares of
//                 the wave's own energy (samples/common/standing_wave.h)
//   standing_wave_thin  the same tank 2 cells thick
//   dam_break     a 0.4 x 0.6 x 1 m column collapsing for 3 s: particle-density volume drift
// Rotation and closed_box run with separation off (a free ball in zero gravity is held
// together only by the pressure's pull; with p >= 0 it flies apart, which is not what they measure).
//
// --check (CI, llvmpipe, small grids) asserts that the more accurate settings are measurably
// more accurate (never timings) and exits non-zero otherwise; it runs only the configuration and
// case pairs its checks compare.

#include <glad/gl.h>

#include <pf/pf.h>

#include "egl_context.h"
#include "standing_wave.h"
#include "util.h"

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

using pfs::Error;
using ojson = nlohmann::ordered_json;

constexpr double kGravity = 9.81;
constexpr double kPi = 3.14159265358979323846;

struct Config {
    std::string name, knob;
    pf_sim_params params;
};

pf_sim_params preset(pf_quality q) {
    pf_sim_params p{};
    p.struct_size = sizeof p;  // this header's fields, not the v1 layout a zero struct_size means
    pfs::check(pf_quality_params(q, &p), "pf_quality_params");
    return p;
}

// The original's scheme (the fast preset until issue 17): 40 projected Jacobi sweeps and the
// marker-cell free surface.
pf_sim_params original_scheme() {
    pf_sim_params p = preset(PF_QUALITY_BALANCED);
    p.pressure_solver = PF_PRESSURE_SOLVER_JACOBI, p.pressure_tolerance = 1e-4f, p.separation = 1;
    p.free_surface = PF_FREE_SURFACE_MARKER_CELL;
    return p;
}

// One knob at a time from the original's scheme, then the presets themselves, then
// combinations of knobs from the balanced preset (the default) for the Pareto front.
std::vector<Config> sweep_configs() {
    const pf_sim_params base = original_scheme();
    std::vector<Config> out;
    auto add = [&](const std::string& knob, const std::string& name, const std::function<void(pf_sim_params&)>& edit) {
        pf_sim_params p = base;
        edit(p);
        out.push_back({name, knob, p});
    };
    add("solver", "jacobi_40", [](pf_sim_params&) {});
    add("solver", "jacobi_200", [](pf_sim_params& p) { p.pressure_iterations = 200; });
    add("solver", "rbgs_1e-4", [](pf_sim_params& p) {
        p.pressure_solver = PF_PRESSURE_SOLVER_RBGS, p.pressure_tolerance = 1e-4f, p.pressure_iterations = 1000;
    });
    add("solver", "pcg_1e-4", [](pf_sim_params& p) {
        p.pressure_solver = PF_PRESSURE_SOLVER_PCG, p.pressure_tolerance = 1e-4f, p.pressure_iterations = 500;
    });
    for (float tol : {1e-2f, 1e-3f, 1e-4f, 1e-5f}) {
        char name[32];
        std::snprintf(name, sizeof name, "mgpcg_%.0e", double(tol));
        add(tol == 1e-4f ? "solver" : "tolerance", name, [tol](pf_sim_params& p) {
            p.pressure_solver = PF_PRESSURE_SOLVER_MGPCG, p.pressure_tolerance = tol, p.pressure_iterations = 60;
        });
    }
    add("separation", "jacobi_40_sep0", [](pf_sim_params& p) { p.separation = 0; });
    add("separation", "mgpcg_1e-04_sep0", [](pf_sim_params& p) {
        p.pressure_solver = PF_PRESSURE_SOLVER_MGPCG, p.pressure_tolerance = 1e-4f, p.pressure_iterations = 60;
        p.separation = 0;
    });
    add("free_surface", "ghost_fluid", [](pf_sim_params& p) { p.free_surface = PF_FREE_SURFACE_GHOST_FLUID; });
    add("volume", "no_volume_correction", [](pf_sim_params& p) { p.volume_correction = 0.0f; });
    add("volume", "volume_correction_0.3", [](pf_sim_params& p) { p.volume_correction = 0.3f; });
    add("transfer", "pic", [](pf_sim_params& p) { p.flip_ratio = 0.0f; });
    add("transfer", "flip_0.95", [](pf_sim_params&) {});
    add("transfer", "apic", [](pf_sim_params& p) { p.transfer = PF_TRANSFER_APIC; });
    add("p2g", "p2g_tiled", [](pf_sim_params&) {});  // the default since issue 18
    add("p2g", "p2g_fixed", [](pf_sim_params& p) { p.p2g = PF_P2G_FIXED_POINT; });
    add("p2g", "p2g_float", [](pf_sim_params& p) { p.p2g = PF_P2G_FLOAT_ATOMIC; });
    add("p2g", "p2g_gather", [](pf_sim_params& p) { p.p2g = PF_P2G_SORTED_GATHER; });
    add("advection", "euler", [](pf_sim_params&) {});
    add("advection", "rk2", [](pf_sim_params& p) { p.advection = PF_ADVECTION_RK2; });
    add("advection", "rk3", [](pf_sim_params& p) { p.advection = PF_ADVECTION_RK3; });
    add("advection", "leapfrog", [](pf_sim_params& p) { p.advection = PF_ADVECTION_LEAPFROG; });
    add("advection", "rk2_offset", [](pf_sim_params& p) { p.advection = PF_ADVECTION_RK2_OFFSET; });
    add("cfl", "cfl_0.5", [](pf_sim_params& p) { p.cfl = 0.5f, p.max_substeps = 32; });
    add("cfl", "cfl_1", [](pf_sim_params&) {});
    add("cfl", "cfl_2", [](pf_sim_params& p) { p.cfl = 2.0f; });
    for (auto [q, name] : {std::pair{PF_QUALITY_FAST, "preset_fast"}, std::pair{PF_QUALITY_BALANCED, "preset_balanced"},
                           std::pair{PF_QUALITY_ACCURATE, "preset_accurate"}})
        out.push_back({name, "preset", preset(q)});
    auto combine = [&](const std::string& name, const std::function<void(pf_sim_params&)>& edit) {
        pf_sim_params p = preset(PF_QUALITY_BALANCED);
        edit(p);
        out.push_back({name, "combination", p});
    };
    combine("balanced_apic", [](pf_sim_params& p) { p.transfer = PF_TRANSFER_APIC; });
    combine("balanced_apic_rk2", [](pf_sim_params& p) { p.transfer = PF_TRANSFER_APIC, p.advection = PF_ADVECTION_RK2; });
    combine("mgpcg_1e-02_apic", [](pf_sim_params& p) { p.transfer = PF_TRANSFER_APIC, p.pressure_tolerance = 1e-2f; });
    combine("mgpcg_1e-04_apic", [](pf_sim_params& p) { p.transfer = PF_TRANSFER_APIC, p.pressure_tolerance = 1e-4f; });
    combine("balanced_cfl_0.5", [](pf_sim_params& p) { p.cfl = 0.5f, p.max_substeps = 32; });
    combine("balanced_cfl_2", [](pf_sim_params& p) { p.cfl = 2.0f; });  // issue 18: half the substeps
    // Large steps: leapfrog at a projection CFL of 8, its count raised by the strain (docs/design.md §5).
    combine("balanced_leapfrog_cfl_8", [](pf_sim_params& p) { p.advection = PF_ADVECTION_LEAPFROG, p.cfl = 8.0f; });
    combine("balanced_gather", [](pf_sim_params& p) { p.p2g = PF_P2G_SORTED_GATHER; });
    combine("fast_apic", [](pf_sim_params& p) {
        p = preset(PF_QUALITY_FAST);
        p.transfer = PF_TRANSFER_APIC;
    });
    // What each knob does to a standing wave's damping and energy (issue 17), from the default.
    combine("balanced_no_volume_correction", [](pf_sim_params& p) { p.volume_correction = 0.0f; });
    combine("balanced_volume_correction_0.2", [](pf_sim_params& p) { p.volume_correction = 0.2f; });
    // The marker-cell free surface (the default until 2026-11-26) with each preset.
    combine("balanced_marker_cell", [](pf_sim_params& p) { p.free_surface = PF_FREE_SURFACE_MARKER_CELL; });
    combine("balanced_marker_cell_no_volume_correction", [](pf_sim_params& p) {
        p.free_surface = PF_FREE_SURFACE_MARKER_CELL, p.volume_correction = 0.0f;
    });
    combine("fast_marker_cell", [](pf_sim_params& p) {
        p = preset(PF_QUALITY_FAST);
        p.free_surface = PF_FREE_SURFACE_MARKER_CELL;
    });
    combine("accurate_marker_cell", [](pf_sim_params& p) {
        p = preset(PF_QUALITY_ACCURATE);
        p.free_surface = PF_FREE_SURFACE_MARKER_CELL;
    });
    combine("balanced_volume_correction_1", [](pf_sim_params& p) { p.volume_correction = 1.0f; });
    combine("balanced_flip_1", [](pf_sim_params& p) { p.flip_ratio = 1.0f; });
    combine("balanced_flip_0.8", [](pf_sim_params& p) { p.flip_ratio = 0.8f; });
    combine("balanced_mgpcg_1e-02", [](pf_sim_params& p) { p.pressure_tolerance = 1e-2f; });
    combine("balanced_mgpcg_1e-05", [](pf_sim_params& p) { p.pressure_tolerance = 1e-5f; });
    combine("balanced_separation", [](pf_sim_params& p) { p.separation = 1; });
    return out;
}

using pfs::SimPtr;

struct Particles {
    std::vector<float> pos, vel;
    size_t count() const { return pos.size() / 3; }
};

Particles read_particles(pf_sim* sim) {
    pf_stats st{};
    pfs::check(pf_get_stats(sim, &st), "pf_get_stats");
    Particles p;
    p.pos.resize(size_t(st.particle_count) * 3);
    p.vel.resize(size_t(st.particle_count) * 3);
    pfs::check(pf_read_particles(sim, 0, st.particle_count, p.pos.data(), p.vel.data()), "pf_read_particles");
    return p;
}

// What one run measured.
struct Run {
    std::map<std::string, double> metrics;
    double gpu_ms_per_frame = 0, wall_ms_per_frame = 0, substeps = 0, residual = 0, iterations = 0;
    uint32_t flags = 0;
};

// One physical test case: its grid, how it is filled, what it measures.
struct Case {
    std::string name;
    glm::uvec3 grid;                 // cells
    uint32_t frames;                 // at 1/60 s
    bool zero_gravity = false, separation_off = false;
    double length = 1.0;             // domain extent along x, m: the cell size is length / n
    std::function<void(pf_sim*, double dx)> fill{};
    // Called after every frame (tracking), then once at the end with the first and last particles.
    std::function<void(pf_sim*, uint32_t frame, double dx)> each_frame{};
    std::function<void(const Particles& start, const Particles& end, double dx, Run&)> measure{};
};

// Particles on a 2x2x2 sub-lattice of every cell whose sub-position passes `inside`.
void add_lattice(pf_sim* sim, glm::uvec3 n, double dx, const std::function<bool(double, double, double)>& inside,
                 const std::function<void(double, double, double, float*)>& velocity) {
    std::vector<float> pos, vel;
    for (uint32_t k = 0; k < 2 * n.z; ++k)
        for (uint32_t j = 0; j < 2 * n.y; ++j)
            for (uint32_t i = 0; i < 2 * n.x; ++i) {
                const double x = (i + 0.5) * dx / 2, y = (j + 0.5) * dx / 2, z = (k + 0.5) * dx / 2;
                if (!inside(x, y, z)) continue;
                float v[3] = {0, 0, 0};
                if (velocity) velocity(x, y, z, v);
                pos.insert(pos.end(), {float(x), float(y), float(z)});
                vel.insert(vel.end(), {v[0], v[1], v[2]});
            }
    pfs::check(pf_add_particles(sim, pos.data(), vel.data(), uint32_t(pos.size() / 3)), "pf_add_particles");
}

double mean_axis(const Particles& p, int axis) {
    double s = 0;
    for (size_t i = 0; i < p.count(); ++i) s += p.pos[i * 3 + axis];
    return p.count() ? s / double(p.count()) : 0.0;
}

double kinetic(const Particles& p) {
    double e = 0;
    for (size_t i = 0; i < p.count(); ++i)
        for (int a = 0; a < 3; ++a) e += 0.5 * double(p.vel[i * 3 + a]) * p.vel[i * 3 + a];
    return e;
}

// Angular momentum about the centre of mass along y (unit masses).
double angular_momentum_y(const Particles& p) {
    const double cx = mean_axis(p, 0), cz = mean_axis(p, 2);
    double l = 0;
    for (size_t i = 0; i < p.count(); ++i) {
        const double rx = p.pos[i * 3] - cx, rz = p.pos[i * 3 + 2] - cz;
        l += rz * p.vel[i * 3] - rx * p.vel[i * 3 + 2];
    }
    return l;
}

// Particles per cell (8 per cell at rest: the lattice fill).
std::vector<uint32_t> cell_counts(const Particles& p, glm::uvec3 n, double dx) {
    std::vector<uint32_t> count(size_t(n.x) * n.y * n.z, 0);
    for (size_t i = 0; i < p.count(); ++i) {
        glm::ivec3 c;
        for (int a = 0; a < 3; ++a) c[a] = std::clamp(int(std::floor(p.pos[i * 3 + a] / dx)), 0, int(n[a]) - 1);
        ++count[size_t(c.x) + n.x * (size_t(c.y) + n.y * size_t(c.z))];
    }
    return count;
}

// Volume of the cells the particles fill, each cell counting min(count / 8, 1) of itself
// (pf_stats.particle_volume).
double particle_volume(const Particles& p, glm::uvec3 n, double dx) {
    double v = 0;
    for (uint32_t c : cell_counts(p, n, dx)) v += std::min(double(c) / 8.0, 1.0);
    return v * dx * dx * dx;
}

// Mass over density (pf_stats.liquid_volume): the particles' rest volume over their mean count
// in interior cells (every face neighbour holds particles or is a wall), rest 8.
double liquid_volume(const Particles& p, glm::uvec3 n, double dx) {
    const std::vector<uint32_t> count = cell_counts(p, n, dx);
    auto at = [&](glm::ivec3 c) { return count[size_t(c.x) + n.x * (size_t(c.y) + n.y * size_t(c.z))]; };
    double sum = 0;
    size_t interior = 0;
    for (int z = 0; z < int(n.z); ++z)
        for (int y = 0; y < int(n.y); ++y)
            for (int x = 0; x < int(n.x); ++x) {
                const glm::ivec3 c{x, y, z};
                if (at(c) == 0) continue;
                bool inner = true;
                for (int a = 0; a < 3; ++a)
                    for (int s : {-1, 1}) {
                        glm::ivec3 q = c;
                        q[a] += s;
                        if (q[a] >= 0 && q[a] < int(n[a]) && at(q) == 0) inner = false;
                    }
                if (!inner) continue;
                sum += at(c);
                ++interior;
            }
    const double rest_volume = double(p.count()) / 8.0 * dx * dx * dx;
    return interior ? rest_volume / (sum / double(interior) / 8.0) : rest_volume;
}

std::vector<Case> make_cases(uint32_t n) {
    std::vector<Case> cases;
    {
        Case c{"hydrostatic", {n, n, n}, 120};
        c.fill = [n](pf_sim* sim, double dx) {
            add_lattice(sim, {n, n, n}, dx, [](double, double y, double) { return y < 0.5; }, nullptr);
        };
        c.measure = [](const Particles& a, const Particles& b, double dx, Run& r) {
            double vmax = 0;
            for (size_t i = 0; i < b.count(); ++i)
                vmax = std::max(vmax, std::sqrt(double(b.vel[i * 3]) * b.vel[i * 3] + double(b.vel[i * 3 + 1]) * b.vel[i * 3 + 1] +
                                                double(b.vel[i * 3 + 2]) * b.vel[i * 3 + 2]));
            r.metrics["spurious_speed"] = vmax / std::sqrt(kGravity * dx);
            r.metrics["depth_change_pct"] = 100.0 * (mean_axis(b, 1) / mean_axis(a, 1) - 1.0);
        };
        cases.push_back(c);
    }
    {
        Case c{"rotation", {n, n, n}, 60, true, true};
        c.fill = [n](pf_sim* sim, double dx) {
            add_lattice(
                sim, {n, n, n}, dx,
                [](double x, double y, double z) {
                    return (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) + (z - 0.5) * (z - 0.5) < 0.25 * 0.25;
                },
                [](double x, double, double z, float* v) { v[0] = float(2.0 * (z - 0.5)), v[2] = float(-2.0 * (x - 0.5)); });
        };
        c.measure = [](const Particles& a, const Particles& b, double, Run& r) {
            r.metrics["angular_momentum_loss_pct"] = 100.0 * (1.0 - angular_momentum_y(b) / angular_momentum_y(a));
        };
        cases.push_back(c);
    }
    {
        Case c{"closed_box", {n, n, n}, 60, true, true};
        c.fill = [n](pf_sim* sim, double dx) {
            add_lattice(
                sim, {n, n, n}, dx, [](double, double, double) { return true; },
                [](double x, double y, double, float* v) {
                    v[0] = float(0.5 * std::sin(kPi * x) * std::cos(kPi * y));
                    v[1] = float(-0.5 * std::cos(kPi * x) * std::sin(kPi * y));
                });
        };
        c.measure = [](const Particles& a, const Particles& b, double, Run& r) {
            r.metrics["kinetic_energy_loss_pct"] = 100.0 * (1.0 - kinetic(b) / kinetic(a));
        };
        cases.push_back(c);
    }
    for (const bool thin : {false, true}) {
        pfs::StandingWave wave;
        wave.dx = wave.length / n;
        const glm::uvec3 g{n, 3 * n / 4, thin ? 2u : std::max(2u, n / 8)};
        wave.thickness = g.z * wave.dx;
        struct Track {
            std::vector<double> t, a;
            double e0 = 0, gain = 0, end = 0;
        };
        auto track = std::make_shared<Track>();
        Case c{thin ? "standing_wave_thin" : "standing_wave", g, uint32_t(std::ceil(10.0 * wave.period() * 60.0))};
        c.length = wave.length;
        c.fill = [wave, track](pf_sim* sim, double) {
            const std::vector<float> pos = wave.lattice(17);
            const std::vector<float> vel(pos.size(), 0.0f);
            pfs::check(pf_add_particles(sim, pos.data(), vel.data(), uint32_t(pos.size() / 3)), "pf_add_particles");
            *track = Track{};
            track->e0 = pfs::mechanical_energy_per_mass(wave, pos.data(), vel.data(), pos.size() / 3);
            track->t.push_back(0.0);
            track->a.push_back(pfs::mode_amplitude(wave, pos.data(), pos.size() / 3));
        };
        c.each_frame = [wave, track](pf_sim* sim, uint32_t frame, double) {
            const Particles p = read_particles(sim);
            const double e = (pfs::mechanical_energy_per_mass(wave, p.pos.data(), p.vel.data(), p.count()) - track->e0) /
                             wave.wave_energy_per_mass();
            track->t.push_back((frame + 1) / 60.0);
            track->a.push_back(pfs::mode_amplitude(wave, p.pos.data(), p.count()));
            track->gain = std::max(track->gain, e);
            track->end = e;
        };
        c.measure = [wave, track](const Particles&, const Particles&, double, Run& r) {
            const pfs::WaveFit fit = pfs::fit_wave(track->t, track->a);
            // Too few crossings (a smothered wave) leaves the period unmeasured: NaN, reported.
            r.metrics["period_error_pct"] = fit.period > 0 ? 100.0 * (fit.period / wave.period() - 1.0) : std::nan("");
            r.metrics["period_theory_s"] = wave.period();
            r.metrics["amplitude_loss_per_period_pct"] = fit.period > 0 ? 100.0 * fit.loss_per_period : std::nan("");
            r.metrics["energy_gain_max_pct"] = 100.0 * track->gain;
            r.metrics["energy_drift_end_pct"] = 100.0 * track->end;
        };
        cases.push_back(c);
    }
    {
        const glm::uvec3 g{n, n / 2, n / 4};
        Case c{"dam_break", g, 180};
        c.fill = [g](pf_sim* sim, double dx) {
            add_lattice(sim, g, dx, [](double x, double y, double) { return x < 0.4 && y < 0.4; }, nullptr);
        };
        c.measure = [g](const Particles& a, const Particles& b, double dx, Run& r) {
            r.metrics["volume_drift_pct"] = 100.0 * (particle_volume(b, g, dx) / particle_volume(a, g, dx) - 1.0);
            r.metrics["liquid_volume_drift_pct"] = 100.0 * (liquid_volume(b, g, dx) / liquid_volume(a, g, dx) - 1.0);
        };
        cases.push_back(c);
    }
    return cases;
}

Run run_case(const Case& c, const Config& config, uint32_t n, bool verbose) {
    const double dx = c.length / n;
    pf_sim_desc desc = pf_default_sim_desc();
    for (int a = 0; a < 3; ++a) desc.grid_size[a] = c.grid[a];
    desc.cell_size = float(dx);
    desc.max_particles = c.grid.x * c.grid.y * c.grid.z * 8 + 64;
    desc.gl_get_proc_address = pfs::get_proc;
    desc.logger = pfs::stderr_logger(verbose);
    desc.params = config.params;
    if (c.zero_gravity) desc.params.gravity[1] = 0.0f;
    if (c.separation_off) desc.params.separation = 0;
    pf_sim* raw = nullptr;
    pfs::check(pf_create(&desc, &raw), "pf_create");
    SimPtr sim(raw);
    c.fill(sim.get(), dx);
    const Particles start = read_particles(sim.get());

    Run r;
    std::map<uint64_t, double> gpu;  // measured step -> GPU ms
    std::vector<double> wall, residual, iterations, substeps;
    pf_stats st{};
    for (uint32_t f = 0; f < c.frames; ++f) {
        glFinish();
        const double t0 = pfs::now_ms();
        pfs::check(pf_step(sim.get(), 1.0f / 60.0f), "pf_step");
        glFinish();
        wall.push_back(pfs::now_ms() - t0);
        pfs::check(pf_get_stats(sim.get(), &st), "pf_get_stats");
        if (st.gpu_step > 0 && !gpu.count(st.gpu_step)) gpu[st.gpu_step] = st.gpu_total_ms;
        residual.push_back(st.solver_residual);
        iterations.push_back(st.solver_iterations);
        substeps.push_back(st.substeps);
        if (c.each_frame) c.each_frame(sim.get(), f, dx);
    }
    const Particles end = read_particles(sim.get());
    c.measure(start, end, dx, r);
    std::vector<double> g;
    for (const auto& [step, ms] : gpu) g.push_back(ms);
    r.gpu_ms_per_frame = pfs::summarize(g).mean;
    r.wall_ms_per_frame = pfs::summarize(wall).mean;
    r.residual = pfs::summarize(residual).mean;
    r.iterations = pfs::summarize(iterations).mean;
    r.substeps = pfs::summarize(substeps).mean;
    r.flags = st.flags;
    for (const auto& [name, value] : r.metrics)
        if (!std::isfinite(value) && name != "period_error_pct" && name != "amplitude_loss_per_period_pct") throw Error(c.name + ": " + name + " is not finite");
    return r;
}

// The items named in `names`, in that order (all of them when names is empty).
template <typename T>
std::vector<T> select_by_name(std::vector<T> all, const std::vector<std::string>& names, const char* what) {
    if (names.empty()) return all;
    std::vector<T> chosen;
    for (const std::string& name : names) {
        auto it = std::find_if(all.begin(), all.end(), [&](const T& item) { return item.name == name; });
        if (it == all.end()) throw Error(std::string("unknown ") + what + " '" + name + "'");
        chosen.push_back(*it);
    }
    return chosen;
}

struct Options {
    uint32_t n = 32;
    std::vector<std::string> cases, configs;
    std::string json_path, csv_path;
    bool check = false, verbose = false;
};

// CI: the more accurate settings are measurably more accurate (metrics only, never timings).
int run_checks(const std::map<std::string, std::map<std::string, Run>>& results) {
    int failures = 0;
    auto metric = [&](const char* config, const char* c, const char* m) { return results.at(config).at(c).metrics.at(m); };
    auto expect = [&](bool ok, const std::string& what) {
        std::printf("%s  %s\n", ok ? "ok  " : "FAIL", what.c_str());
        failures += ok ? 0 : 1;
    };
    const double pic = metric("pic", "rotation", "angular_momentum_loss_pct"),
                 apic = metric("apic", "rotation", "angular_momentum_loss_pct");
    expect(apic < 0.5 * pic, "APIC keeps angular momentum: loss " + std::to_string(apic) + "% vs PIC " + std::to_string(pic) + "%");
    const double ke_pic = metric("pic", "closed_box", "kinetic_energy_loss_pct"),
                 ke_flip = metric("flip_0.95", "closed_box", "kinetic_energy_loss_pct");
    expect(ke_flip < ke_pic, "FLIP dissipates less energy than PIC: " + std::to_string(ke_flip) + "% vs " + std::to_string(ke_pic) + "%");
    // The closed box keeps moving (the resting tank starts in exact equilibrium: residual 0).
    const double r_mg = results.at("mgpcg_1e-04").at("closed_box").residual,
                 r_jac = results.at("jacobi_40").at("closed_box").residual;
    expect(r_mg <= 2e-4 && r_jac > 10 * r_mg,
           "MGPCG reaches its tolerance where 40 Jacobi sweeps do not: residual " + std::to_string(r_mg) + " vs " + std::to_string(r_jac));
    for (const auto& [config, by_case] : results)
        for (const auto& [c, r] : by_case) expect(!(r.flags & PF_FLAG_NONFINITE), config + "/" + c + ": no non-finite velocity");
    return failures;
}

int run(int argc, char** argv) {
    Options opt;
    CLI::App app{"pf_accuracy: accuracy metrics against GPU time for every knob (docs/accuracy.md)"};
    app.add_option("-n,--cells", opt.n, "cells per axis of the 1 m cases (16..256)")->check(CLI::Range(16u, 256u));
    app.add_option("--case", opt.cases, "run only these cases (hydrostatic, rotation, closed_box, standing_wave, standing_wave_thin, dam_break)");
    app.add_option("--config", opt.configs, "run only these configurations (names as printed)");
    app.add_option("--json", opt.json_path, "write every result as JSON");
    app.add_option("--csv", opt.csv_path, "write every result as CSV");
    app.add_flag("--check", opt.check, "CI: the configurations and cases the checks need; fail unless they hold");
    app.add_flag("--verbose", opt.verbose, "pflip's info messages");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    // The configurations each case runs under for run_checks (each run is also checked for
    // non-finite velocities).
    const std::map<std::string, std::vector<std::string>> check_pairs = {
        {"rotation", {"pic", "apic"}}, {"closed_box", {"jacobi_40", "mgpcg_1e-04", "pic", "flip_0.95"}}};
    if (opt.check) {
        opt.configs.clear();
        opt.cases.clear();
        for (const auto& [c, configs] : check_pairs) {
            opt.cases.push_back(c);
            for (const std::string& config : configs)
                if (std::find(opt.configs.begin(), opt.configs.end(), config) == opt.configs.end()) opt.configs.push_back(config);
        }
    }

    pfs::EglContext ctx(pfs::EglContext::Options{});
    if (!gladLoadGL(pfs::get_proc)) throw Error("gladLoadGL failed");
    std::printf("pf_accuracy %s, %s\n%s\n", pfs::pf_version_string().c_str(), pfs::utc_timestamp().c_str(),
                ctx.describe().c_str());

    const std::vector<Config> configs = select_by_name(sweep_configs(), opt.configs, "configuration");
    const std::vector<Case> cases = select_by_name(make_cases(opt.n), opt.cases, "case");

    std::map<std::string, std::map<std::string, Run>> results;
    ojson rows = ojson::array();
    std::printf("%-16s %-10s %-14s %10s %9s %10s  metrics\n", "config", "knob", "case", "gpu ms/fr", "substeps", "residual");
    for (const Config& config : configs) {
        for (const Case& c : cases) {
            if (opt.check) {
                const std::vector<std::string>& wanted = check_pairs.at(c.name);
                if (std::find(wanted.begin(), wanted.end(), config.name) == wanted.end()) continue;
            }
            const Run r = run_case(c, config, opt.n, opt.verbose);
            results[config.name][c.name] = r;
            std::string m;
            for (const auto& [name, value] : r.metrics) m += " " + name + "=" + std::to_string(value);
            std::printf("%-16s %-10s %-14s %10.3f %9.2f %10.2e %s\n", config.name.c_str(), config.knob.c_str(), c.name.c_str(),
                        r.gpu_ms_per_frame, r.substeps, r.residual, m.c_str());
            std::fflush(stdout);
            ojson row;
            row["config"] = config.name;
            row["knob"] = config.knob;
            row["case"] = c.name;
            row["cells"] = {c.grid.x, c.grid.y, c.grid.z};
            row["frames"] = c.frames;
            row["gpu_ms_per_frame"] = r.gpu_ms_per_frame;
            row["wall_ms_per_frame"] = r.wall_ms_per_frame;
            row["substeps"] = r.substeps;
            row["solver_residual"] = r.residual;
            row["solver_iterations"] = r.iterations;
            row["flags"] = r.flags;
            row["metrics"] = r.metrics;
            row["params"] = {{"pressure_solver", pfs::solver_name(config.params.pressure_solver)},
                             {"pressure_tolerance", config.params.pressure_tolerance},
                             {"pressure_iterations", config.params.pressure_iterations},
                             {"flip_ratio", config.params.flip_ratio},
                             {"transfer", int(config.params.transfer)},
                             {"advection", int(config.params.advection)},
                             {"cfl", config.params.cfl},
                             {"separation", config.params.separation},
                             {"p2g", pfs::p2g_name(config.params.p2g)},
                             {"free_surface", pfs::free_surface_name(config.params.free_surface)}};
            rows.push_back(row);
        }
    }
    if (!opt.json_path.empty()) {
        ojson j;
        j["tool"] = "pf_accuracy";
        j["date"] = pfs::utc_timestamp();
        j["gl_renderer"] = ctx.gl_renderer();
        j["cells"] = opt.n;
        j["results"] = rows;
        std::ofstream f(opt.json_path);
        f << j.dump(2) << "\n";
        if (!f) throw Error("cannot write " + opt.json_path);
    }
    if (!opt.csv_path.empty()) {
        std::ofstream f(opt.csv_path);
        f << "config,knob,case,gpu_ms_per_frame,substeps,solver_residual,metric,value\n";
        for (const ojson& row : rows)
            for (const auto& [name, value] : row["metrics"].items())
                f << row["config"].get<std::string>() << "," << row["knob"].get<std::string>() << ","
                  << row["case"].get<std::string>() << "," << row["gpu_ms_per_frame"].get<double>() << ","
                  << row["substeps"].get<double>() << "," << row["solver_residual"].get<double>() << "," << name << ","
                  << value.get<double>() << "\n";
        if (!f) throw Error("cannot write " + opt.csv_path);
    }
    return opt.check ? (run_checks(results) == 0 ? 0 : 1) : 0;
}

}  // namespace

int main(int argc, char** argv) { return pfs::run_tool("pf_accuracy", run, argc, argv); }
