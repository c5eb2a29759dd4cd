// pf_validation — pflip against published dam-break experiments.
//
// Rebuilds laboratory experiments at their own size (gravity 9.81 m/s^2, frame dt 1/60 s, pflip's
// CFL substeps inside pf_step), measures after every frame what the experimenters measured, from
// the particles read back, and compares it with their data (docs/validation_data.json, every
// series with its source) at the data's times:
//   martin_moyce_2  Martin & Moyce (1952): a column a = 2.25 in wide and n^2 a = 2a high collapses
//                   on a dry floor. Surge front Z = z/a against T = n t sqrt(g/a) = t sqrt(2g/a);
//                   residual column height at the back wall H = h/(n^2 a) against tau = t sqrt(g/a)
//   martin_moyce_1  the same with a square column (n^2 = 1: T = tau)
//   marin_obstacle  MARIN (Kleefsman et al. 2005, SPHERIC test 2): a reservoir 0.55 m deep released
//                   into a 3.22 x 1 x 1 m tank with a box obstacle; water heights at gauges H1..H4
// The Martin & Moyce tanks are 4 cells thick with free-slip walls (their experiment is 2D) and long
// enough that the far wall is not reached within the data; the MARIN tank is fully 3D.
//
// Per data series: RMS, largest and mean difference (simulation - data) at the data's times, and
// the time shift that aligns the two best (sim_lead > 0: the simulation runs that far ahead of the
// experiment, whose gate took time to open while the simulation starts from an instant release).
// --scale S builds every experiment S times larger: the runs use neither viscosity nor surface
// tension (both off by default), so by Froude similarity only the number of 1/60 s frames per unit
// of dimensionless time changes.
// --perturb SEED... repeats every run from a lattice whose particles are each moved by up to a
// thousandth of their spacing (seeded): a FLIP flow amplifies differences of that size, so one
// run's RMS is one sample, and the mean and spread over seeds compare two schemes fairly.

#include <glad/gl.h>

#include <pf/pf.h>

#include "cli.h"
#include "egl_context.h"
#include "util.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#ifndef PF_VALIDATION_DATA
#define PF_VALIDATION_DATA "docs/validation_data.json"
#endif

namespace {

using pfs::Error;
using ojson = nlohmann::ordered_json;

constexpr double kGravity = 9.81;
constexpr double kFrameDt = 1.0 / 60.0;
constexpr uint32_t kSlabCells = 4;  // thickness of the 2D (Martin & Moyce) tanks

// ---- the data ----------------------------------------------------------------------------------

struct Series {
    std::string id, label, quantity;  // quantity: front | column_height | water_height
    std::string time, value;          // the data's variables: T | tau | t_s, Z | H | h_m
    glm::dvec2 gauge{0.0};            // water_height: gauge (x, z), m
    std::vector<glm::dvec2> points;   // (time, value)
};

struct Case {
    std::string name, title, type;  // type: column | tank_obstacle
    double a = 0, n2 = 0;           // column: width (m) and height over width
    glm::dvec3 tank{0.0}, water_lo{0.0}, water_hi{0.0}, obstacle_lo{0.0}, obstacle_hi{0.0};
    double reference_length = 0;    // tank_obstacle: the length --cells divides
    std::vector<Series> series;
};

glm::dvec3 vec3(const ojson& j) { return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()}; }

std::vector<Case> load_cases(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw Error("cannot read " + path + " (see --data)");
    const ojson doc = ojson::parse(f);
    std::vector<Case> cases;
    for (const auto& [name, jc] : doc.at("cases").items()) {
        Case c;
        c.name = name;
        c.title = jc.value("title", name);
        const ojson& setup = jc.at("setup");
        c.type = setup.at("type").get<std::string>();
        if (c.type == "column") {
            c.a = setup.at("a_m").get<double>();
            c.n2 = setup.at("n2").get<double>();
        } else if (c.type == "tank_obstacle") {
            c.tank = vec3(setup.at("tank_m"));
            c.water_lo = vec3(setup.at("water_m").at("min"));
            c.water_hi = vec3(setup.at("water_m").at("max"));
            c.obstacle_lo = vec3(setup.at("obstacle_m").at("min"));
            c.obstacle_hi = vec3(setup.at("obstacle_m").at("max"));
            c.reference_length = setup.at("reference_length_m").get<double>();
        } else {
            throw Error(path + ": case " + name + ": unknown setup type '" + c.type + "'");
        }
        for (const ojson& js : jc.at("series")) {
            Series s;
            s.id = js.at("id").get<std::string>();
            s.label = js.value("label", s.id);
            s.quantity = js.at("quantity").get<std::string>();
            s.time = js.at("time").get<std::string>();
            s.value = js.at("value").get<std::string>();
            if (s.quantity == "water_height") s.gauge = {js.at("gauge_m").at(0).get<double>(), js.at("gauge_m").at(1).get<double>()};
            for (const ojson& p : js.at("points")) s.points.push_back({p.at(0).get<double>(), p.at(1).get<double>()});
            c.series.push_back(s);
        }
        cases.push_back(c);
    }
    return cases;
}

// ---- the simulation ----------------------------------------------------------------------------

using pfs::SimPtr;

std::vector<float> read_positions(pf_sim* sim) {
    uint32_t n = 0;
    pfs::check(pf_get_particle_count(sim, &n), "pf_get_particle_count");
    std::vector<float> pos(size_t(n) * 3);
    if (n) pfs::check(pf_read_particles(sim, 0, n, pos.data(), nullptr), "pf_read_particles");
    return pos;
}

// Particles on a 2x2x2 sub-lattice of every cell, those inside [lo, hi): the rest count of 8 per
// cell with no jitter, so a resolution's initial state is exactly reproducible. perturb_seed > 0
// moves each particle by up to kPerturbation of the spacing along each axis, seeded (so also
// reproducible); 0 keeps the exact lattice.
constexpr double kPerturbation = 1e-3;
void add_lattice(pf_sim* sim, glm::uvec3 n, double dx, glm::dvec3 lo, glm::dvec3 hi, uint32_t perturb_seed) {
    std::mt19937 rng(perturb_seed);
    std::uniform_real_distribution<double> offset(-kPerturbation * dx / 2, kPerturbation * dx / 2);
    std::vector<float> pos;
    for (uint32_t k = 0; k < 2 * n.z; ++k)
        for (uint32_t j = 0; j < 2 * n.y; ++j)
            for (uint32_t i = 0; i < 2 * n.x; ++i) {
                glm::dvec3 p = (glm::dvec3(i, j, k) + 0.5) * (dx / 2);
                if (!glm::all(glm::greaterThanEqual(p, lo)) || !glm::all(glm::lessThan(p, hi))) continue;
                if (perturb_seed > 0) p += glm::dvec3(offset(rng), offset(rng), offset(rng));
                pos.insert(pos.end(), {float(p.x), float(p.y), float(p.z)});
            }
    pfs::check(pf_add_particles(sim, pos.data(), nullptr, uint32_t(pos.size() / 3)), "pf_add_particles");
}

// The particle centres of a resting lattice sit dx/4 inside the liquid's surface: added back so that
// the initial column measures exactly a wide and n^2 a high.
double surface_offset(double dx) { return dx / 4; }

// Surge front and residual column of a Martin & Moyce tank (back wall x = 0, floor y = 0).
// The front is where the liquid film that is connected to the column ends, not the largest x of
// any particle: FLIP throws single particles ahead of the tip, and a percentile of x would measure
// the volume of the thin wedge (which depends on resolution) rather than where its tip is. So the
// columns of cells along x are walked from the back wall while each holds at least half a particle
// layer over its floor (2 per cell face at rest: 2 n.z for the tank's thickness); the front is the
// largest x among the particles of the last such column. The residual height is the same walk up
// the rows of cells touching the back wall (x < dx). The raw extremes are kept as well.
struct ColumnShape {
    double front = 0, front_max = 0, height = 0, height_max = 0;  // m
};

ColumnShape measure_column(const std::vector<float>& pos, glm::uvec3 n, double dx) {
    std::vector<uint32_t> col(n.x, 0), row(n.y, 0);
    std::vector<double> col_end(n.x, 0.0), row_top(n.y, 0.0);
    ColumnShape s;
    for (size_t p = 0; p + 2 < pos.size(); p += 3) {
        const double x = pos[p], y = pos[p + 1];
        const int i = std::clamp(int(std::floor(x / dx)), 0, int(n.x) - 1);
        ++col[i];
        col_end[i] = std::max(col_end[i], x);
        s.front_max = std::max(s.front_max, x);
        if (x < dx) {
            const int j = std::clamp(int(std::floor(y / dx)), 0, int(n.y) - 1);
            ++row[j];
            row_top[j] = std::max(row_top[j], y);
            s.height_max = std::max(s.height_max, y);
        }
    }
    const uint32_t film = 2 * n.z;
    for (uint32_t i = 0; i < n.x && col[i] >= film; ++i) s.front = col_end[i];
    for (uint32_t j = 0; j < n.y && row[j] >= film; ++j) s.height = row_top[j];
    const double off = surface_offset(dx);
    s.front += off, s.front_max += off, s.height += off, s.height_max += off;
    return s;
}

// Water height at a gauge: the liquid volume above a 2dx x 2dx patch of floor centred on it
// (particles x rest volume dx^3/8) over the patch's area. Volume rather than the highest particle:
// the breaking bores of the MARIN tank carry spray, which a wave gauge reads as little water while
// a highest-particle rule reads it as a tall column; the patch smooths the count over 4 x 4
// particle columns.
double gauge_height(const std::vector<float>& pos, glm::dvec2 gauge, double dx) {
    size_t count = 0;
    for (size_t p = 0; p + 2 < pos.size(); p += 3)
        if (std::abs(pos[p] - gauge.x) < dx && std::abs(pos[p + 2] - gauge.y) < dx) ++count;
    return double(count) * (dx * dx * dx / 8.0) / (4.0 * dx * dx);
}

// One quantity's simulated history: time in the series' variable, value in its variable.
struct Track {
    std::vector<double> time, value;
};

// Linear interpolation in a sorted table, held at its ends.
double interp(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
    if (x <= xs.front()) return ys.front();
    if (x >= xs.back()) return ys.back();
    const size_t i = size_t(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin());
    const double f = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
    return ys[i - 1] + f * (ys[i] - ys[i - 1]);
}

struct Comparison {
    size_t n = 0;
    double rms = 0, max_abs = 0, bias = 0, sim_lead = 0, rms_aligned = 0;
    bool lead_at_bound = false;  // the best shift is the largest searched: the data disagree in shape
    std::vector<std::array<double, 3>> points;  // time, data, simulation
};

// Simulation against data at the data's times. Points at time <= 0 are the initial state (no
// measurement) and are skipped. sim_lead is the shift s in [-max_shift, max_shift] minimising the
// RMS of sim(time - s) - data: the simulation reaches each measured state s earlier.
Comparison compare(const Track& sim, const Series& s, double max_shift) {
    Comparison c;
    std::vector<glm::dvec2> pts;
    for (const glm::dvec2& p : s.points)
        if (p.x > 0 && p.x <= sim.time.back()) pts.push_back(p);
    c.n = pts.size();
    if (pts.empty()) return c;
    auto rms_at = [&](double shift) {
        double e = 0;
        for (const glm::dvec2& p : pts) {
            const double d = interp(sim.time, sim.value, p.x - shift) - p.y;
            e += d * d;
        }
        return std::sqrt(e / double(pts.size()));
    };
    for (const glm::dvec2& p : pts) {
        const double v = interp(sim.time, sim.value, p.x), d = v - p.y;
        c.points.push_back({p.x, p.y, v});
        c.max_abs = std::max(c.max_abs, std::abs(d));
        c.bias += d / double(pts.size());
    }
    c.rms = rms_at(0.0);
    c.rms_aligned = c.rms;
    constexpr int kSteps = 200;
    for (int k = -kSteps; k <= kSteps; ++k) {
        const double shift = max_shift * k / kSteps, e = rms_at(shift);
        if (e < c.rms_aligned - 1e-12) c.rms_aligned = e, c.sim_lead = shift;
    }
    c.lead_at_bound = std::abs(c.sim_lead) >= max_shift * (1.0 - 1e-9);
    return c;
}

struct Run {
    glm::uvec3 grid{0};
    double dx = 0;
    uint32_t frames = 0, particles = 0, flags = 0;
    double wall_s = 0, substeps = 0;
    pf_advection advection = PF_ADVECTION_EULER;  // the integrator the run used
    float flip_ratio = 0.95f;                      // and its PIC/FLIP blend
    float cfl = 1.0f;                              // and its projection CFL
    float tolerance = 0.0f;                        // and its pressure tolerance
    std::vector<double> t;                  // s, one per measurement (frame 0 is the initial state)
    std::map<std::string, std::vector<double>> measured;  // per quantity, m
    std::vector<Comparison> comparisons;    // one per series
};

// Seconds -> the series' time variable, and metres -> its value variable.
double time_in(const Case& c, const std::string& var, double t, double scale) {
    const double a = c.a * scale;
    if (var == "T") return t * std::sqrt(c.n2 * kGravity / a);
    if (var == "tau") return t * std::sqrt(kGravity / a);
    if (var == "t_s") return t / std::sqrt(scale);  // back to the experiment's own size
    throw Error(c.name + ": unknown time variable '" + var + "'");
}
double value_in(const Case& c, const std::string& var, double v, double scale) {
    if (var == "Z") return v / (c.a * scale);
    if (var == "H") return v / (c.n2 * c.a * scale);
    if (var == "h_m") return v / scale;
    throw Error(c.name + ": unknown value variable '" + var + "'");
}
// Largest alignment shift searched, in the series' time variable: a gate opening is a fraction of
// the first dimensionless time unit (Martin & Moyce) or of a tenth of a second (MARIN).
double max_shift_in(const std::string& var) { return var == "t_s" ? 0.25 : 1.0; }

// Parameters the command line sets over the preset's (unset: the preset's own).
struct Overrides {
    std::optional<float> cfl, flip_ratio, tolerance;
    std::optional<pf_advection> advection;
};

Run run_case(const Case& c, pf_quality quality, uint32_t cells, double scale, const Overrides& over,
             uint32_t perturb_seed, bool verbose) {
    Run r;
    pf_sim_desc desc = pf_default_sim_desc();
    desc.gl_get_proc_address = pfs::get_proc;
    desc.logger = pfs::stderr_logger(verbose);
    pfs::check(pf_quality_params(quality, &desc.params), "pf_quality_params");
    // A substep budget, not a quality choice: let the CFL condition hold at any resolution.
    desc.params.max_substeps = 64;
    if (over.cfl) desc.params.cfl = *over.cfl;
    if (over.advection) desc.params.advection = *over.advection;
    if (over.flip_ratio) desc.params.flip_ratio = *over.flip_ratio;
    if (over.tolerance) desc.params.pressure_tolerance = *over.tolerance;
    r.advection = desc.params.advection;
    r.flip_ratio = desc.params.flip_ratio;
    r.cfl = desc.params.cfl;
    r.tolerance = desc.params.pressure_tolerance;

    // The experiment's last data time (s, at this scale) and the frames to cover it, plus room for
    // the alignment shift.
    double t_end = 0;
    auto seconds = [&](const Series& s, double x) { return x / time_in(c, s.time, 1.0, scale); };
    for (const Series& s : c.series)
        for (const glm::dvec2& p : s.points) t_end = std::max(t_end, seconds(s, p.x + max_shift_in(s.time)));
    r.frames = uint32_t(std::ceil(t_end / kFrameDt)) + 1;

    glm::dvec3 water_lo{0.0}, water_hi{0.0};
    if (c.type == "column") {
        const double a = c.a * scale;
        r.dx = a / cells;
        // Long enough that the front, which may run ahead of the data, stays clear of the far wall
        // up to the last measured Z; a head room of a/2 above the column keeps the lid away.
        double z_last = 1.0;
        for (const Series& s : c.series)
            if (s.quantity == "front")
                for (const glm::dvec2& p : s.points) z_last = std::max(z_last, p.y);
        r.grid = {uint32_t(std::ceil((1.25 * z_last + 1.0) * cells)), uint32_t(std::ceil((c.n2 + 0.5) * cells)), kSlabCells};
        water_hi = {a, c.n2 * a, kSlabCells * r.dx};
    } else {
        const glm::dvec3 tank = c.tank * scale;
        // The tank length in whole cells, so the far wall is where the experiment's was.
        const uint32_t nx = std::max(1u, uint32_t(std::lround(tank.x / (c.reference_length * scale / cells))));
        r.dx = tank.x / nx;
        r.grid = {nx, uint32_t(std::lround(tank.y / r.dx)), uint32_t(std::lround(tank.z / r.dx))};
        // Water reaching a tank wall reaches the grid's wall (the grid may differ from the tank by
        // dx/2 across and in height).
        const glm::dvec3 extent = glm::dvec3(r.grid) * r.dx;
        water_lo = c.water_lo * scale;
        water_hi = c.water_hi * scale;
        for (int k = 0; k < 3; ++k)
            if (c.water_hi[k] >= c.tank[k]) water_hi[k] = extent[k];
        desc.features = PF_FEATURE_OBSTACLES;
    }
    for (int k = 0; k < 3; ++k) desc.grid_size[k] = r.grid[k];
    desc.cell_size = float(r.dx);
    desc.max_particles = r.grid.x * r.grid.y * r.grid.z * 8 + 64;

    pf_sim* raw = nullptr;
    pfs::check(pf_create(&desc, &raw), "pf_create");
    SimPtr sim(raw);
    if (c.type == "tank_obstacle") {
        pf_obstacle box = pf_default_obstacle();
        box.shape = PF_OBSTACLE_BOX;
        const glm::dvec3 lo = c.obstacle_lo * scale, hi = c.obstacle_hi * scale;
        for (int k = 0; k < 3; ++k) box.position[k] = float(0.5 * (lo[k] + hi[k])), box.half_extents[k] = float(0.5 * (hi[k] - lo[k]));
        pfs::check(pf_add_obstacle(sim.get(), &box, nullptr), "pf_add_obstacle");
    }
    add_lattice(sim.get(), r.grid, r.dx, water_lo, water_hi, perturb_seed);

    auto measure = [&](double t) {
        const std::vector<float> pos = read_positions(sim.get());
        r.particles = uint32_t(pos.size() / 3);
        r.t.push_back(t);
        if (c.type == "column") {
            const ColumnShape s = measure_column(pos, r.grid, r.dx);
            r.measured["front"].push_back(s.front);
            r.measured["front_max"].push_back(s.front_max);
            r.measured["column_height"].push_back(s.height);
            r.measured["column_height_max"].push_back(s.height_max);
        } else {
            for (const Series& s : c.series)
                if (s.quantity == "water_height") r.measured[s.id].push_back(gauge_height(pos, s.gauge * scale, r.dx));
        }
    };
    measure(0.0);
    const double t0 = pfs::now_ms();
    pf_stats st{};
    st.struct_size = sizeof st;
    for (uint32_t f = 1; f <= r.frames; ++f) {
        pfs::check(pf_step(sim.get(), float(kFrameDt)), "pf_step");
        pfs::check(pf_get_stats(sim.get(), &st), "pf_get_stats");
        r.substeps += double(st.substeps) / r.frames;
        measure(f * kFrameDt);
    }
    glFinish();
    r.wall_s = (pfs::now_ms() - t0) / 1000.0;
    r.flags = st.flags;

    for (const Series& s : c.series) {
        const std::string key = s.quantity == "water_height" ? s.id : s.quantity;
        const auto it = r.measured.find(key);
        if (it == r.measured.end()) throw Error(c.name + "/" + s.id + ": nothing measures '" + s.quantity + "'");
        Track tr;
        for (size_t k = 0; k < r.t.size(); ++k) {
            tr.time.push_back(time_in(c, s.time, r.t[k], scale));
            tr.value.push_back(value_in(c, s.value, it->second[k], scale));
        }
        r.comparisons.push_back(compare(tr, s, max_shift_in(s.time)));
    }
    return r;
}

// Prints one run's comparisons and returns its JSON row (the time series and the comparisons).
ojson report_run(const Case& c, const std::string& pname, const Run& r, uint32_t cells, double scale, uint32_t seed) {
    std::printf("\n%s / %s%s: grid %ux%ux%u, dx %.4g m, %u particles, %u frames, %.2f substeps/frame, %.1f s, flags 0x%x\n",
                c.name.c_str(), pname.c_str(), seed ? (", perturb " + std::to_string(seed)).c_str() : "", r.grid.x,
                r.grid.y, r.grid.z, r.dx, r.particles, r.frames, r.substeps, r.wall_s, r.flags);
    std::printf("  %-22s %-9s %4s %9s %9s %9s %9s %11s\n", "series", "value(t)", "n", "rms", "max", "bias", "sim_lead",
                "rms_aligned");
    ojson row;
    row["case"] = c.name;
    row["preset"] = pname;
    row["cells"] = cells;
    row["scale"] = scale;
    row["cfl"] = r.cfl;
    row["pressure_tolerance"] = r.tolerance;
    row["perturb_seed"] = seed;
    row["advection"] = pfs::advection_name(r.advection);
    row["flip_ratio"] = r.flip_ratio;
    row["grid"] = {r.grid.x, r.grid.y, r.grid.z};
    row["cell_size_m"] = r.dx;
    row["particles"] = r.particles;
    row["frames"] = r.frames;
    row["substeps_per_frame"] = r.substeps;
    row["flags"] = r.flags;
    row["wall_s"] = r.wall_s;
    ojson series = ojson::array();
    for (size_t k = 0; k < c.series.size(); ++k) {
        const Series& s = c.series[k];
        const Comparison& cmp = r.comparisons[k];
        const std::string vars = s.value + "(" + s.time + ")";
        std::printf("  %-22s %-9s %4zu %9.4f %9.4f %+9.4f %+9.3f%s %10.4f\n", s.id.c_str(), vars.c_str(), cmp.n, cmp.rms,
                    cmp.max_abs, cmp.bias, cmp.sim_lead, cmp.lead_at_bound ? "*" : " ", cmp.rms_aligned);
        ojson js;
        js["id"] = s.id;
        js["label"] = s.label;
        js["time"] = s.time;
        js["value"] = s.value;
        js["n"] = cmp.n;
        js["rms"] = cmp.rms;
        js["max_abs"] = cmp.max_abs;
        js["bias"] = cmp.bias;
        js["sim_lead"] = cmp.sim_lead;
        js["sim_lead_at_bound"] = cmp.lead_at_bound;
        js["rms_aligned"] = cmp.rms_aligned;
        js["points"] = cmp.points;  // [time, data, simulation]
        series.push_back(js);
    }
    row["series"] = series;
    // The raw histories in seconds and metres at the experiment's size, for plotting.
    ojson history;
    std::vector<double> t;
    for (double v : r.t) t.push_back(v / std::sqrt(scale));
    history["t_s"] = t;
    for (const auto& [name, values] : r.measured) {
        std::vector<double> v;
        for (double x : values) v.push_back(x / scale);
        history[name + "_m"] = v;
    }
    row["history"] = history;
    return row;
}

// Each series' RMS over the perturbed runs: mean, sample standard deviation, range.
void print_spread(const Case& c, const std::string& preset, const std::vector<std::vector<double>>& rms) {
    std::printf("\n%s / %s over %zu perturbed lattices:\n  %-22s %9s %9s %9s %9s\n", c.name.c_str(), preset.c_str(),
                rms.empty() ? size_t(0) : rms[0].size(), "series", "rms mean", "sd", "min", "max");
    for (size_t k = 0; k < c.series.size(); ++k) {
        const pfs::Summary v = pfs::summarize(rms[k]);
        std::printf("  %-22s %9.4f %9.4f %9.4f %9.4f\n", c.series[k].id.c_str(), v.mean, v.stddev, v.min, v.max);
    }
}

int run(int argc, char** argv) {
    uint32_t cells = 16;
    double scale = 1.0;
    Overrides over;
    std::vector<pf_quality> presets;
    std::vector<std::string> case_names;
    std::vector<uint32_t> perturb_seeds;
    std::string json_path, data_path = PF_VALIDATION_DATA;
    bool verbose = false;
    CLI::App app{"pf_validation: pflip against published dam-break experiments (docs/validation_data.json)"};
    app.add_option("--cells", cells,
                   "cells across the column width a (Martin & Moyce) or the water depth (MARIN); default 16")
        ->check(CLI::Range(4u, 256u));
    app.add_option("--preset", presets, "quality presets to run (repeatable; default all three)")
        ->transform(pfs::NameMap(pfs::preset_choices(), "preset"))
        ->type_name("NAME");
    app.add_option("--case", case_names, "martin_moyce_2, martin_moyce_1 or marin_obstacle (repeatable; default all)");
    app.add_option("--json", json_path, "write the time series and the comparisons as JSON");
    app.add_option("--data", data_path, "the published data (docs/validation_data.json)");
    app.add_option("--scale", scale, "build the experiments this many times larger (Froude similarity); default 1")
        ->check(CLI::Range(0.1, 100.0));
    app.add_option("--cfl", over.cfl, "override the presets' cfl (cells a particle may cross per substep)")
        ->check(CLI::Range(0.05f, 16.0f));
    app.add_option("--advection", over.advection, "override the presets' particle integrator")
        ->transform(pfs::NameMap(pfs::enum_choices(pfs::advection_name, PF_ADVECTION_COUNT), "advection"))
        ->type_name("NAME");
    app.add_option("--flip-ratio", over.flip_ratio, "override the presets' PIC/FLIP blend (0 = PIC, 1 = FLIP)")
        ->check(CLI::Range(0.0f, 1.0f));
    app.add_option("--tolerance", over.tolerance, "override the presets' pressure tolerance (relative residual)")
        ->check(CLI::Range(1e-7f, 0.5f));
    app.add_option("--perturb", perturb_seeds,
                   "run each case from the lattice moved by up to 1e-3 of its spacing, once per seed (repeatable; "
                   "1 and up), and print each series' RMS mean and spread over the seeds")
        ->check(CLI::Range(1u, 1000000u))
        ->type_name("SEED");
    app.add_flag("--verbose", verbose, "pflip's info messages");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    if (presets.empty())
        for (const auto& [name, quality] : pfs::preset_choices()) presets.push_back(quality);
    if (perturb_seeds.empty()) perturb_seeds.push_back(0);  // the exact lattice

    const std::vector<Case> all = load_cases(data_path);
    std::vector<Case> cases;
    if (case_names.empty()) cases = all;
    for (const std::string& name : case_names) {
        auto it = std::find_if(all.begin(), all.end(), [&](const Case& c) { return c.name == name; });
        if (it == all.end()) throw Error("unknown case '" + name + "' (" + data_path + " has none)");
        cases.push_back(*it);
    }

    pfs::EglContext ctx(pfs::EglContext::Options{});
    if (!gladLoadGL(pfs::get_proc)) throw Error("gladLoadGL failed");
    std::printf("pf_validation %s, %s\n%s\n", pfs::pf_version_string().c_str(), pfs::utc_timestamp().c_str(),
                ctx.describe().c_str());

    ojson results = ojson::array();
    for (const Case& c : cases) {
        for (const pf_quality quality : presets) {
            const std::string pname = pfs::choice_name(pfs::preset_choices(), quality);
            std::vector<std::vector<double>> rms_over_seeds(c.series.size());
            for (const uint32_t seed : perturb_seeds) {
                const Run r = run_case(c, quality, cells, scale, over, seed, verbose);
                results.push_back(report_run(c, pname, r, cells, scale, seed));
                for (size_t k = 0; k < c.series.size(); ++k) rms_over_seeds[k].push_back(r.comparisons[k].rms);
                std::fflush(stdout);
            }
            if (perturb_seeds.size() > 1) print_spread(c, pname, rms_over_seeds);
        }
    }
    if (!json_path.empty()) {
        ojson j;
        j["tool"] = "pf_validation";
        j["date"] = pfs::utc_timestamp();
        j["gl_renderer"] = ctx.gl_renderer();
        j["data"] = data_path;
        j["cells"] = cells;
        j["scale"] = scale;
        j["results"] = results;
        std::ofstream f(json_path);
        f << j.dump(2) << "\n";
        if (!f) throw Error("cannot write " + json_path);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) { return pfs::run_tool("pf_validation", run, argc, argv); }
