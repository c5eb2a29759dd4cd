// pf_bench — pflip benchmark harness.
//
// For each scene: create the simulation, fill it, run W warm-up steps, then M measured steps of
// the scene's frame_dt (the library picks the CFL substeps; they are reported). Per step it
// records the wall time with glFinish before and after pf_step, pflip's host time, and —
// once per distinct pf_stats.gpu_step — the per-pass GPU times from pf_get_stats. Results go
// to stdout as a table and optionally to JSON and CSV.

#include <glad/gl.h>

#include <pf/pf.h>

#include "cli.h"
#include "egl_context.h"
#include "roofline.h"
#include "scene.h"
#include "scene_effects.h"
#include "util.h"
#include "world.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using pfs::Error;
using ojson = nlohmann::ordered_json;

struct Options {
    std::vector<std::string> scenes;
    uint32_t warmup = 20;
    uint32_t steps = 100;
    uint32_t pressure_iterations = 40;  // without --preset
    pfs::ParamOverrides overrides;      // --preset, --solver, --tolerance, --transfer, --advection, --p2g, ...
    int separation = -1;        // -1: the scene's
    uint32_t max_substeps = 0; // 0: the scene's
    float frame_dt = 0;        // 0: the scene's
    int64_t features = -1;     // -1: the scene's PF_FEATURE_* bits
    pf_gpu_timing gpu_timing = PF_GPU_TIMING_PASSES;  // --gpu-timing
    float gpu_budget = 0;      // --gpu-budget (0: none)
    std::string json_path, csv_path;
    bool verbose = false;
    std::string command_line;
};

const char* kDefaultScenes[] = {"original_24", "dam_break_1m", "dam_break_10m"};

/// --features: the list becomes its PF_FEATURE_* bits (parse_feature_list knows the names).
class FeatureList : public CLI::Validator {
public:
    FeatureList() {
        func_ = [](std::string& input) -> std::string {
            try {
                input = std::to_string(pfs::parse_feature_list(input, "--features"));
                return {};
            } catch (const Error& e) {
                // CLI11 puts the option's name in front: drop parse_feature_list's own.
                return std::string(e.what()).substr(std::string("--features: ").size());
            }
        };
    }
};

void add_options(CLI::App& app, Options& o) {
    pfs::init_app(app);
    app.add_option("scenes", o.scenes,
                   "scene files or names in the scenes directory (default: original_24 dam_break_1m dam_break_10m)")
        ->type_name("SCENE");
    app.add_option("--warmup", o.warmup, "unmeasured steps first")
        ->check(pfs::Range(0u, 1000000u))
        ->capture_default_str();
    app.add_option("--steps", o.steps, "measured steps")->check(pfs::Range(1u, 1000000u))->capture_default_str();
    app.add_option("--pressure-iterations", o.pressure_iterations,
                   "iteration cap per substep for every scene without --preset (default 40, the original's \"step "
                   "(40 Jacobi iterations)\")")
        ->check(pfs::Range(1u, 10000u));
    pfs::add_param_overrides(app, o.overrides);
    app.add_option("--separation", o.separation, "override the scenes' separation")->check(pfs::Range(0, 1));
    app.add_option("--max-substeps", o.max_substeps, "override the scenes' max_substeps (1 = one substep per step)")
        ->check(pfs::Range(1u, 64u));
    app.add_option("--frame-dt", o.frame_dt, "override the scenes' frame_dt (seconds per pf_step)")
        ->check(pfs::Range(1e-6f, 1.0f));
    app.add_option("--features", o.features,
                   "effects to run, overriding the scenes' (comma-separated force_fields, obstacles, emitters, "
                   "sinks, domain_motion, vorticity_confinement, whitewater, viscosity, surface_tension; or all, "
                   "none); the scenes' objects are added either way")
        ->transform(FeatureList())
        ->type_name("LIST");
    static const pfs::Choices<pf_gpu_timing> kTimings = {
        {"passes", PF_GPU_TIMING_PASSES}, {"step", PF_GPU_TIMING_STEP}, {"off", PF_GPU_TIMING_OFF},
        {"kernels", PF_GPU_TIMING_KERNELS}};
    app.add_option("--gpu-budget", o.gpu_budget,
                   "GPU milliseconds each step may take (pf_set_gpu_budget; 0: none); needs GPU timing")
        ->check(pfs::Range(0.0f, 1e4f));
    app.add_option("--gpu-timing", o.gpu_timing,
                   "what the library's timer queries measure (pf_set_gpu_timing): every pass group (the "
                   "default, the per-pass tables), the step as a whole (the total only), nothing (wall times only) or every "
                   "kernel apart (profiling: one timer pair per dispatch)")
        ->transform(pfs::NameMap(kTimings, "timing"));
    app.add_option("--json", o.json_path, "write results as JSON")->type_name("PATH");
    app.add_option("--csv", o.csv_path, "write results as CSV (one row per scene and metric)")->type_name("PATH");
    app.add_flag("--verbose", o.verbose, "pflip's info messages and EGL details");
    app.footer("environment: PF_EGL_PLATFORM=device|surfaceless, PF_EGL_DEVICE=N, PF_SCENES_DIR=DIR\n"
               "scenes directory: " + pfs::scenes_dir());
}

using pfs::SimPtr;

// The names of pf_stats.flags' bits, one per raised flag (world.cpp's flag_names, split).
std::vector<std::string> flag_list(uint32_t flags) {
    std::vector<std::string> v;
    if (!flags) return v;
    std::istringstream names(pfs::flag_names(flags));
    for (std::string name; names >> name;) v.push_back(name);
    return v;
}

ojson summary_json(const pfs::Summary& s) {
    ojson j;
    j["mean"] = s.mean;
    j["median"] = s.median;
    j["min"] = s.min;
    j["max"] = s.max;
    j["stddev"] = s.stddev;
    j["n"] = s.n;
    return j;
}

struct Result {
    std::string name, file, error;
    pfs::Scene scene;
    pf_sim_params params{};
    float frame_dt = 0;
    uint32_t particles = 0, max_particles = 0, ppc = 0;
    uint64_t gpu_memory_bytes = 0, gpu_particle_bytes = 0;  // after the measured steps (first-use buffers made)
    double create_ms = 0, fill_ms = 0;
    pfs::Summary wall, wall_per_substep, cpu, substeps;
    pfs::Summary gpu_total, gpu_per_substep;
    pfs::Summary gpu_pass[PF_PASS_COUNT];
    uint32_t dispatches[PF_PASS_COUNT] = {};          // the most in one measured step
    pfs::Summary dispatch_count[PF_PASS_COUNT];        // per measured step
    size_t gpu_samples = 0;
    bool gpu_valid = false;
    uint32_t flags = 0;
    float max_speed = 0;
    pfs::Summary solver_iterations, solver_residual;
    std::vector<std::pair<std::string, pfs::Summary>> pass_list;  // pf_get_pass_stats entries, ms per step
    std::map<std::string, pfs::Summary> pass_list_dispatches;      // the same entries' dispatches per step
};

uint64_t cell_count(const pfs::Scene& scene) {
    return uint64_t(scene.grid_size[0]) * scene.grid_size[1] * scene.grid_size[2];
}

// Run one scene; fills r (r.error on failure).
void bench_scene(const Options& opt, const std::string& arg, Result& r) {
    r.name = arg;
    const std::string path = pfs::resolve_scene_path(arg);
    r.file = path;
    r.scene = pfs::load_scene(path);
    r.name = r.scene.name;
    r.frame_dt = opt.frame_dt > 0 ? opt.frame_dt : r.scene.frame_dt;

    pf_sim_desc desc = pfs::make_sim_desc(r.scene, pfs::get_proc, pfs::stderr_logger(opt.verbose));
    if (!opt.overrides.has_preset) desc.params.pressure_iterations = opt.pressure_iterations;
    opt.overrides.apply(desc.params);
    if (opt.separation >= 0) desc.params.separation = uint32_t(opt.separation);
    if (opt.max_substeps) desc.params.max_substeps = opt.max_substeps;
    if (opt.features >= 0) desc.features = uint32_t(opt.features);
    r.params = desc.params;
    r.max_particles = desc.max_particles;
    r.ppc = desc.fill_particles_per_cell;

    std::printf("\n[%s] %s\n  grid %ux%ux%u, cell %.4g m; solver %s, at most %u iterations, tolerance %g, "
                "separation %u, max_substeps %u, frame_dt %.5g s\n",
                r.name.c_str(), path.c_str(), desc.grid_size[0], desc.grid_size[1], desc.grid_size[2],
                double(desc.cell_size), pfs::solver_name(desc.params.pressure_solver), desc.params.pressure_iterations,
                double(desc.params.pressure_tolerance), desc.params.separation, desc.params.max_substeps,
                double(r.frame_dt));
    std::fflush(stdout);

    glFinish();
    double t0 = pfs::now_ms();
    pfs::SceneEffectIds effects;  // owns the SDF obstacles' textures: declared first, outlives sim
    SimPtr sim;
    {
        pf_sim* raw = nullptr;
        pfs::check(pf_create(&desc, &raw), "pf_create");
        sim.reset(raw);
    }
    pfs::check(pf_set_gpu_timing(sim.get(), opt.gpu_timing), "pf_set_gpu_timing");
    pfs::check(pf_set_gpu_budget(sim.get(), opt.gpu_budget), "pf_set_gpu_budget");
    glFinish();
    r.create_ms = pfs::now_ms() - t0;
    t0 = pfs::now_ms();
    pfs::fill_scene(sim.get(), r.scene);
    effects = pfs::add_scene_effects(sim.get(), r.scene);
    // Driven obstacles move as in pf_headless (floating ones stay where the scene puts them).
    pfs::DrivenObstacles driven;
    pfs::drive_scene_obstacles(r.scene, effects, driven);
    auto step = [&](const char* what) {
        pfs::check(driven.step(sim.get(), r.frame_dt), "driven obstacles");
        pfs::check(pf_step(sim.get(), r.frame_dt), what);
    };
    glFinish();
    r.fill_ms = pfs::now_ms() - t0;

    pf_stats st{};
    st.struct_size = sizeof st;  // this header's fields (0 would mean the first layout only)
    pfs::check(pf_get_stats(sim.get(), &st), "pf_get_stats");
    r.particles = st.particle_count;
    std::printf("  %u particles; pf_create %.1f ms, fill %.1f ms; warming up %u steps...\n", r.particles,
                r.create_ms, r.fill_ms, opt.warmup);
    std::fflush(stdout);

    for (uint32_t i = 0; i < opt.warmup; ++i) step("pf_step (warm-up)");
    glFinish();
    pfs::check(pf_clear_flags(sim.get()), "pf_clear_flags");
    pfs::check(pf_get_stats(sim.get(), &st), "pf_get_stats");
    const uint64_t first = st.steps + 1, last = st.steps + opt.steps;

    std::map<uint64_t, uint32_t> substeps_of; // step -> substeps
    struct Gpu {
        float ms[PF_PASS_COUNT];
        float total;
    };
    std::map<uint64_t, Gpu> gpu; // distinct gpu_step -> timings
    std::vector<double> wall, cpu, iterations, residual, dispatch_count[PF_PASS_COUNT];
    std::map<std::string, std::vector<double>> pass_list, pass_dispatches;
    std::vector<std::string> pass_order;
    // The pass list as it stands (pf_get_pass_stats: no stall).
    auto entries = [&]() {
        uint32_t n = 0;
        pfs::check(pf_get_pass_count(sim.get(), &n), "pf_get_pass_count");
        std::vector<pf_pass_stats> list(n);
        for (uint32_t i = 0; i < n; ++i) pfs::check(pf_get_pass_stats(sim.get(), i, &list[i]), "pf_get_pass_stats");
        return list;
    };
    // Each entry's dispatches in the step just taken (entries added mid-run count 0 before).
    auto count_dispatches = [&]() {
        for (const pf_pass_stats& ps : entries()) pass_dispatches[ps.name].push_back(ps.dispatches);
    };
    auto collect = [&]() {
        if (st.gpu_step >= first && st.gpu_step <= last && !gpu.count(st.gpu_step)) {
            Gpu g{};
            std::copy(st.gpu_ms, st.gpu_ms + PF_PASS_COUNT, g.ms);
            g.total = st.gpu_total_ms;
            gpu[st.gpu_step] = g;
            for (const pf_pass_stats& ps : entries()) {
                if (!pass_list.count(ps.name)) pass_order.push_back(ps.name);
                pass_list[ps.name].push_back(ps.gpu_ms);
            }
        }
    };

    std::printf("  measuring %u steps...\n", opt.steps);
    std::fflush(stdout);
    const uint32_t progress_every = std::max(1u, opt.steps / 4);
    for (uint32_t i = 0; i < opt.steps; ++i) {
        glFinish();
        const double s0 = pfs::now_ms();
        step("pf_step");
        glFinish();
        const double s1 = pfs::now_ms();
        pfs::check(pf_get_stats(sim.get(), &st), "pf_get_stats");
        wall.push_back(s1 - s0);
        cpu.push_back(st.cpu_ms);
        substeps_of[st.steps] = st.substeps;
        iterations.push_back(st.solver_iterations);
        residual.push_back(st.solver_residual);
        for (int p = 0; p < PF_PASS_COUNT; ++p) {
            r.dispatches[p] = std::max(r.dispatches[p], st.dispatches[p]);
            dispatch_count[p].push_back(st.dispatches[p]);
        }
        count_dispatches();
        collect();
        if ((i + 1) % progress_every == 0 && i + 1 < opt.steps) {
            std::printf("    %u/%u  %.2f ms/step (wall)  substeps %u\n", i + 1, opt.steps, s1 - s0, st.substeps);
            std::fflush(stdout);
        }
    }
    r.flags = st.flags;
    r.max_speed = st.max_speed;
    r.particles = st.particle_count;
    r.gpu_memory_bytes = st.gpu_memory_bytes;
    r.gpu_particle_bytes = st.gpu_particle_bytes;
    // GPU timings lag a few steps: keep stepping (unmeasured) until the last measured step's
    // timings are reported, or give up after a few.
    for (int i = 0; i < 8 && st.gpu_step < last; ++i) {
        step("pf_step (drain)");
        glFinish();
        pfs::check(pf_get_stats(sim.get(), &st), "pf_get_stats");
        collect();
    }

    std::vector<double> subs, wall_sub;
    for (size_t i = 0; i < wall.size(); ++i) {
        const uint32_t k = substeps_of[first + i];
        subs.push_back(k);
        if (k) wall_sub.push_back(wall[i] / k);
    }
    r.wall = pfs::summarize(wall);
    r.wall_per_substep = pfs::summarize(wall_sub);
    r.cpu = pfs::summarize(cpu);
    r.substeps = pfs::summarize(subs);
    std::vector<double> tot, tot_sub, pass[PF_PASS_COUNT];
    for (const auto& [step, g] : gpu) {
        tot.push_back(g.total);
        const uint32_t k = substeps_of.count(step) ? substeps_of[step] : 0;
        if (k) tot_sub.push_back(g.total / k);
        for (int p = 0; p < PF_PASS_COUNT; ++p) pass[p].push_back(g.ms[p]);
    }
    r.gpu_samples = gpu.size();
    r.gpu_total = pfs::summarize(tot);
    r.gpu_per_substep = pfs::summarize(tot_sub);
    for (int p = 0; p < PF_PASS_COUNT; ++p) {
        r.gpu_pass[p] = pfs::summarize(pass[p]);
        r.dispatch_count[p] = pfs::summarize(dispatch_count[p]);
    }
    r.gpu_valid = r.gpu_samples > 0 && r.gpu_total.max > 0;
    r.solver_iterations = pfs::summarize(iterations);
    r.solver_residual = pfs::summarize(residual);
    for (const std::string& name : pass_order) {
        r.pass_list.emplace_back(name, pfs::summarize(pass_list[name]));
        r.pass_list_dispatches[name] = pfs::summarize(pass_dispatches[name]);
    }

    std::printf("  wall %.3f ms/step (median), gpu %.3f ms/step (median of %zu), substeps %.2f\n", r.wall.median,
                r.gpu_total.median, r.gpu_samples, r.substeps.mean);
    std::printf("  solver: %.1f iterations (mean of the most per step; max %.0f), final residual %.3g (mean; max %.3g)\n",
                r.solver_iterations.mean, r.solver_iterations.max, r.solver_residual.mean, r.solver_residual.max);
    const uint64_t cells = cell_count(r.scene);
    std::printf("  GPU memory %.1f MiB: %.1f bytes per particle slot (x %u), %.1f bytes per cell for the rest\n",
                double(r.gpu_memory_bytes) / (1 << 20), double(r.gpu_particle_bytes) / r.max_particles, r.max_particles,
                double(r.gpu_memory_bytes - r.gpu_particle_bytes) / double(cells));
    sim.reset();
    glFinish();
}

// The particle passes against the ceilings: modelled bytes and atomics per step (the model per
// substep times the mean substeps) over the median GPU time.
struct RooflineRow {
    pf_pass pass;
    double ms = 0, bytes = 0, gbps = 0, copy_pct = 0, atomics = 0, gops = 0, atomics_pct = 0;
};
std::vector<RooflineRow> roofline_rows(const Result& r, const pfb::Ceilings& ceilings) {
    pfb::TrafficInputs in;
    in.particles = r.particles;
    const uint64_t nx = r.scene.grid_size[0], ny = r.scene.grid_size[1], nz = r.scene.grid_size[2];
    in.cells = cell_count(r.scene);
    in.faces = (nx + 1) * ny * nz + nx * (ny + 1) * nz + nx * ny * (nz + 1);
    in.p2g = r.params.p2g;
    in.apic = r.params.transfer == PF_TRANSFER_APIC;
    in.rk_advection = r.params.advection == PF_ADVECTION_RK2 || r.params.advection == PF_ADVECTION_RK3 ||
                      r.params.advection == PF_ADVECTION_RK2_OFFSET;
    in.volume_correction = r.params.volume_correction > 0.0f;
    std::vector<RooflineRow> rows;
    for (pf_pass pass : {PF_PASS_P2G, PF_PASS_G2P, PF_PASS_ADVECT}) {
        const pfb::Traffic t = pfb::pass_traffic(pass, in);
        RooflineRow row{pass};
        row.ms = r.gpu_pass[pass].median;
        row.bytes = t.bytes * r.substeps.mean;
        row.atomics = t.atomics * r.substeps.mean;
        if (row.ms > 0) {
            row.gbps = row.bytes / (row.ms * 1e6);
            row.gops = row.atomics / (row.ms * 1e6);
        }
        if (ceilings.copy_gbps > 0) row.copy_pct = 100.0 * row.gbps / ceilings.copy_gbps;
        if (ceilings.atomics_gops > 0) row.atomics_pct = 100.0 * row.gops / ceilings.atomics_gops;
        rows.push_back(row);
    }
    return rows;
}

// Each pass group against the dispatch floor: its median dispatches per step times the GPU time
// of a dependent dispatch of one workgroup (the least a pass can cost) and of 4,096 idle
// workgroups (a grid-sized pass that does nothing), over the group's median time. The last row
// is the whole step.
struct DispatchRow {
    std::string name;
    double ms = 0, dispatches = 0, floor_ms = 0, wide_floor_ms = 0;
};
std::vector<DispatchRow> dispatch_rows(const Result& r, const pfb::Ceilings& ceilings) {
    std::vector<DispatchRow> rows;
    DispatchRow total{"total", r.gpu_total.median};
    for (int k = 0; k < PF_PASS_COUNT; ++k) {
        const double n = r.dispatch_count[k].median;
        if (n <= 0) continue;
        rows.push_back({pf_pass_name(pf_pass(k)), r.gpu_pass[k].median, n, n * ceilings.dispatch_us * 1e-3,
                        n * ceilings.wide_dispatch_us * 1e-3});
        total.dispatches += n;
    }
    total.floor_ms = total.dispatches * ceilings.dispatch_us * 1e-3;
    total.wide_floor_ms = total.dispatches * ceilings.wide_dispatch_us * 1e-3;
    rows.push_back(total);
    return rows;
}

ojson result_json(const Result& r, const pfb::Ceilings& ceilings) {
    ojson j;
    j["scene"] = r.name;
    j["file"] = r.file;
    if (!r.error.empty()) {
        j["error"] = r.error;
        return j;
    }
    j["description"] = r.scene.description;
    j["grid"] = {r.scene.grid_size[0], r.scene.grid_size[1], r.scene.grid_size[2]};
    j["cell_size"] = r.scene.cell_size;
    j["particles"] = r.particles;
    j["max_particles"] = r.max_particles;
    j["particles_per_cell"] = r.ppc;
    j["frame_dt"] = r.frame_dt;
    ojson p;
    p["gravity"] = {r.params.gravity[0], r.params.gravity[1], r.params.gravity[2]};
    p["flip_ratio"] = r.params.flip_ratio;
    p["pressure_iterations"] = r.params.pressure_iterations;
    p["jacobi_omega"] = r.params.jacobi_omega;
    p["cfl"] = r.params.cfl;
    p["max_substeps"] = r.params.max_substeps;
    p["extrapolation_layers"] = r.params.extrapolation_layers;
    p["separation"] = r.params.separation;
    p["pressure_solver"] = pfs::solver_name(r.params.pressure_solver);
    p["pressure_tolerance"] = r.params.pressure_tolerance;
    p["sor_omega"] = r.params.sor_omega;
    p["transfer"] = pfs::transfer_name(r.params.transfer);
    p["advection"] = pfs::advection_name(r.params.advection);
    p["p2g"] = pfs::p2g_name(r.params.p2g);
    p["free_surface"] = pfs::free_surface_name(r.params.free_surface);
    j["params"] = p;
    j["solver_iterations"] = summary_json(r.solver_iterations);
    j["solver_residual"] = summary_json(r.solver_residual);
    ojson memory;
    const double cells = double(cell_count(r.scene));
    memory["bytes"] = r.gpu_memory_bytes;
    memory["particle_bytes"] = r.gpu_particle_bytes;
    memory["bytes_per_particle_slot"] = double(r.gpu_particle_bytes) / r.max_particles;
    memory["other_bytes_per_cell"] = double(r.gpu_memory_bytes - r.gpu_particle_bytes) / cells;
    j["gpu_memory"] = memory;
    j["create_ms"] = r.create_ms;
    j["fill_ms"] = r.fill_ms;
    j["substeps_per_step"] = summary_json(r.substeps);
    j["wall_ms_per_step"] = summary_json(r.wall);
    j["wall_ms_per_substep"] = summary_json(r.wall_per_substep);
    j["cpu_ms_per_step"] = summary_json(r.cpu);
    ojson g;
    g["samples"] = r.gpu_samples;
    g["timer_valid"] = r.gpu_valid;
    g["total_ms_per_step"] = summary_json(r.gpu_total);
    g["total_ms_per_substep"] = summary_json(r.gpu_per_substep);
    ojson passes;
    for (int k = 0; k < PF_PASS_COUNT; ++k) {
        ojson pj = summary_json(r.gpu_pass[k]);
        pj["dispatches_per_step"] = r.dispatches[k];  // the most in one measured step
        pj["dispatches_per_step_median"] = r.dispatch_count[k].median;
        passes[pf_pass_name(pf_pass(k))] = pj;
    }
    g["passes_ms_per_step"] = passes;
    ojson list;
    for (const auto& [name, summary] : r.pass_list) list[name] = summary_json(summary);
    g["pass_list_ms_per_step"] = list;
    ojson list_dispatches;
    for (const auto& [name, summary] : r.pass_list_dispatches) list_dispatches[name] = summary_json(summary);
    g["pass_list_dispatches_per_step"] = list_dispatches;
    j["gpu"] = g;
    ojson roofline;
    for (const RooflineRow& row : roofline_rows(r, ceilings)) {
        ojson rj;
        rj["ms_per_step"] = row.ms;
        rj["modelled_bytes_per_step"] = row.bytes;
        rj["gb_per_s"] = row.gbps;
        rj["percent_of_copy_bandwidth"] = row.copy_pct;
        rj["modelled_global_atomics_per_step"] = row.atomics;
        rj["g_atomics_per_s"] = row.gops;
        rj["percent_of_atomics_rate"] = row.atomics_pct;
        roofline[pf_pass_name(row.pass)] = rj;
    }
    j["roofline"] = roofline;
    if (ceilings.dispatch_us > 0) {
        ojson floor;
        for (const DispatchRow& row : dispatch_rows(r, ceilings)) {
            ojson fj;
            fj["ms_per_step"] = row.ms;
            fj["dispatches_per_step"] = row.dispatches;
            fj["floor_ms_one_workgroup"] = row.floor_ms;
            fj["floor_ms_4096_idle_workgroups"] = row.wide_floor_ms;
            floor[row.name] = fj;
        }
        j["dispatch_floor"] = floor;
    }
    j["flags"] = flag_list(r.flags);
    j["max_speed"] = r.max_speed;
    return j;
}

void write_csv(const std::string& path, const std::vector<Result>& results) {
    std::ofstream f(path);
    if (!f) throw Error("cannot write " + path);
    f << "scene,particles,grid,pressure_iterations,frame_dt,substeps_mean,metric,mean_ms,median_ms,min_ms,max_ms,"
         "samples\n";
    for (const Result& r : results) {
        if (!r.error.empty()) continue;
        char grid[64];
        std::snprintf(grid, sizeof grid, "%ux%ux%u", r.scene.grid_size[0], r.scene.grid_size[1], r.scene.grid_size[2]);
        auto row = [&](const std::string& metric, const pfs::Summary& s) {
            char buf[512];
            std::snprintf(buf, sizeof buf, "%s,%u,%s,%u,%.9g,%.4f,%s,%.6f,%.6f,%.6f,%.6f,%zu\n", r.name.c_str(),
                          r.particles, grid, r.params.pressure_iterations, double(r.frame_dt), r.substeps.mean,
                          metric.c_str(), s.mean, s.median, s.min, s.max, s.n);
            f << buf;
        };
        row("wall_step", r.wall);
        row("wall_substep", r.wall_per_substep);
        row("cpu_step", r.cpu);
        row("gpu_total_step", r.gpu_total);
        row("gpu_total_substep", r.gpu_per_substep);
        for (int k = 0; k < PF_PASS_COUNT; ++k) row(std::string("gpu_") + pf_pass_name(pf_pass(k)), r.gpu_pass[k]);
    }
    if (!f) throw Error("error writing " + path);
}

void print_tables(const std::vector<Result>& results, const pfb::Ceilings& ceilings) {
    std::printf("\n%-16s %10s %13s %7s %12s %12s %14s %10s\n", "scene", "particles", "grid", "subst", "wall ms/step",
                "gpu ms/step", "gpu ms/substep", "cpu ms");
    for (const Result& r : results) {
        if (!r.error.empty()) {
            std::printf("%-16s  FAILED: %s\n", r.name.c_str(), r.error.c_str());
            continue;
        }
        char grid[64];
        std::snprintf(grid, sizeof grid, "%ux%ux%u", r.scene.grid_size[0], r.scene.grid_size[1], r.scene.grid_size[2]);
        std::printf("%-16s %10u %13s %7.2f %12.3f %12.3f %14.3f %10.3f\n", r.name.c_str(), r.particles, grid,
                    r.substeps.mean, r.wall.median, r.gpu_total.median, r.gpu_per_substep.median, r.cpu.median);
    }
    std::printf("(medians; wall = glFinish around pf_step; gpu = pf_get_stats timer queries)\n");

    std::vector<const Result*> ok;
    for (const Result& r : results)
        if (r.error.empty()) ok.push_back(&r);
    if (ok.empty()) return;
    std::printf("\nGPU ms per step by pass (median):\n%-18s", "pass");
    for (const Result* r : ok) std::printf(" %16.16s", r->name.c_str());
    std::printf("\n");
    for (int k = 0; k < PF_PASS_COUNT; ++k) {
        std::printf("%-18s", pf_pass_name(pf_pass(k)));
        for (const Result* r : ok) std::printf(" %16.4f", r->gpu_pass[k].median);
        std::printf("\n");
    }
    std::printf("%-18s", "total");
    for (const Result* r : ok) std::printf(" %16.4f", r->gpu_total.median);
    std::printf("\n");
    if (ceilings.measured()) {
        std::printf("\nParticle passes against the ceilings (copy %.0f GB/s, atomics %.1f G/s):\n", ceilings.copy_gbps,
                    ceilings.atomics_gops);
        std::printf("%-16s %-8s %10s %12s %9s %8s %10s %8s\n", "scene", "pass", "ms/step", "MB/step", "GB/s", "% copy",
                    "G atom/s", "% atom");
        for (const Result* r : ok) {
            for (const RooflineRow& row : roofline_rows(*r, ceilings)) {
                if (row.bytes <= 0) {
                    std::printf("%-16s %-8s %10.4f %12s\n", r->name.c_str(), pf_pass_name(row.pass), row.ms, "(no model)");
                    continue;
                }
                std::printf("%-16s %-8s %10.4f %12.1f %9.1f %8.1f", r->name.c_str(), pf_pass_name(row.pass), row.ms,
                            row.bytes / 1e6, row.gbps, row.copy_pct);
                if (row.atomics > 0) std::printf(" %10.2f %8.1f", row.gops, row.atomics_pct);
                std::printf("\n");
            }
        }
        std::printf("(%s)\n", pfb::traffic_model_note());
    }
    if (ceilings.dispatch_us > 0) {
        std::printf("\nPass groups against the dispatch floor (a dependent dispatch: %.2f us of one workgroup, %.2f us "
                    "of 4,096 idle ones; medians per step):\n",
                    ceilings.dispatch_us, ceilings.wide_dispatch_us);
        std::printf("%-16s %-16s %10s %11s %10s %8s %10s %8s\n", "scene", "pass", "ms/step", "dispatches", "floor ms",
                    "% floor", "wide ms", "% wide");
        for (const Result* r : ok)
            for (const DispatchRow& row : dispatch_rows(*r, ceilings))
                std::printf("%-16s %-16s %10.4f %11.0f %10.4f %8.1f %10.4f %8.1f\n", r->name.c_str(), row.name.c_str(),
                            row.ms, row.dispatches, row.floor_ms, row.ms > 0 ? 100.0 * row.floor_ms / row.ms : 0.0,
                            row.wide_floor_ms, row.ms > 0 ? 100.0 * row.wide_floor_ms / row.ms : 0.0);
    }
    // Kernel timing (--gpu-timing kernels): the "<pass>:<kernel>" entries, dearest first, each
    // dispatch's mean cost against the dependent-dispatch floor.
    for (const Result* r : ok) {
        std::vector<std::pair<double, std::string>> kernels;
        for (const auto& [name, summary] : r->pass_list)
            if (name.find(':') != std::string::npos && summary.median > 0) kernels.emplace_back(summary.median, name);
        if (kernels.empty()) continue;
        std::sort(kernels.rbegin(), kernels.rend());
        std::printf("\nKernels of %s (medians per step; the dependent-dispatch floor %.2f us):\n", r->name.c_str(),
                    ceilings.dispatch_us);
        std::printf("%-52s %10s %11s %12s %8s\n", "pass:kernel", "ms/step", "dispatches", "us/dispatch", "x floor");
        for (const auto& [ms, name] : kernels) {
            const auto d = r->pass_list_dispatches.find(name);
            const double n = d != r->pass_list_dispatches.end() ? d->second.median : 0.0;
            const double us = n > 0 ? 1e3 * ms / n : 0.0;
            std::printf("%-52s %10.4f %11.0f %12.2f %8.2f\n", name.c_str(), ms, n, us,
                        ceilings.dispatch_us > 0 ? us / ceilings.dispatch_us : 0.0);
        }
    }
    bool any_invalid = false;
    for (const Result* r : ok) any_invalid = any_invalid || !r->gpu_valid;
    if (any_invalid)
        std::printf("note: some scenes have no non-zero GPU timings (timer queries unsupported or reading 0 on this "
                    "driver, e.g. llvmpipe); use the wall times.\n");
    for (const Result* r : ok)
        if (r->flags)
            std::printf("note: %s raised flags:%s\n", r->name.c_str(), [&] {
                std::string s;
                for (const auto& f : flag_list(r->flags)) s += " " + f;
                return s;
            }().c_str());
}

int run(int argc, char** argv) {
    Options opt;
    for (int i = 0; i < argc; ++i) opt.command_line += std::string(i ? " " : "") + argv[i];
    CLI::App app{"pf_bench: pflip benchmark harness (per-pass GPU times, docs/performance.md)", "pf_bench"};
    add_options(app, opt);
    CLI11_PARSE(app, argc, argv);
    if (opt.scenes.empty())
        for (const char* s : kDefaultScenes) opt.scenes.push_back(s);

    pfs::EglContext::Options copt;
    copt.verbose = opt.verbose;
    pfs::EglContext ctx(copt);
    const int glv = gladLoadGL(pfs::get_proc);
    if (!glv || GLAD_VERSION_MAJOR(glv) * 100 + GLAD_VERSION_MINOR(glv) < 403)
        throw Error("gladLoadGL: OpenGL 4.3 core functions not available");

    const std::string date = pfs::utc_timestamp();
    std::printf("pflip %s benchmark, %s\n%s\nwarm-up %u steps, measured %u steps, %u Jacobi iterations\n",
                pfs::pf_version_string().c_str(), date.c_str(), ctx.describe().c_str(), opt.warmup, opt.steps,
                opt.pressure_iterations);

    const pfb::Ceilings ceilings = pfb::measure_ceilings();
    if (ceilings.measured()) {
        std::printf("ceilings measured now: compute copy %.0f GB/s (read + write), read %.0f GB/s, random 32-bit "
                    "atomicAdd %.1f G/s; a dependent dispatch %.2f us (indirect %.2f, 4,096 idle workgroups %.2f; "
                    "through a record nothing wrote %.2f, of 4,096 idle workgroups %.2f); "
                    "a 2 MiB copy %.2f us a dispatch after a barrier each, %.2f in independent pairs\n",
                    ceilings.copy_gbps, ceilings.read_gbps, ceilings.atomics_gops, ceilings.dispatch_us,
                    ceilings.indirect_dispatch_us, ceilings.wide_dispatch_us, ceilings.static_indirect_dispatch_us,
                    ceilings.wide_static_indirect_dispatch_us, ceilings.copy_dispatch_us,
                    ceilings.paired_copy_dispatch_us);
    } else {
        std::printf("ceilings: not measured (this GL's timer queries read 0)\n");
    }

    std::vector<Result> results(opt.scenes.size());
    bool failed = false;
    for (size_t i = 0; i < opt.scenes.size(); ++i) {
        try {
            bench_scene(opt, opt.scenes[i], results[i]);
        } catch (const std::exception& e) {
            results[i].error = e.what();
            failed = true;
            std::fprintf(stderr, "pf_bench: %s: %s\n", opt.scenes[i].c_str(), e.what());
            while (glGetError() != GL_NO_ERROR) {
            }
        }
    }

    print_tables(results, ceilings);

    if (!opt.json_path.empty()) {
        ojson j;
        j["tool"] = "pf_bench";
        j["pflip_version"] = pfs::pf_version_string();
        j["date"] = date;
        j["host"] = pfs::host_name();
        j["command_line"] = opt.command_line;
        ojson gl;
        gl["egl_platform"] = ctx.platform();
        gl["egl_device"] = ctx.device_info();
        gl["egl_vendor"] = ctx.egl_vendor();
        gl["vendor"] = ctx.gl_vendor();
        gl["renderer"] = ctx.gl_renderer();
        gl["version"] = ctx.gl_version();
        j["gl"] = gl;
        ojson settings;
        settings["warmup_steps"] = opt.warmup;
        settings["measured_steps"] = opt.steps;
        settings["pressure_iterations"] = opt.pressure_iterations;
        settings["max_substeps_override"] = opt.max_substeps;
        settings["frame_dt_override"] = opt.frame_dt;
        settings["gpu_budget_ms"] = opt.gpu_budget;
        settings["gpu_timing"] = opt.gpu_timing == PF_GPU_TIMING_PASSES ? "passes"
                                 : opt.gpu_timing == PF_GPU_TIMING_STEP    ? "step"
                                 : opt.gpu_timing == PF_GPU_TIMING_KERNELS ? "kernels"
                                                                           : "off";
        settings["wall_time"] = "glFinish; t0; pf_step; glFinish; t1";
        settings["gpu_time"] = "pf_get_stats per-pass timer queries, each distinct gpu_step once, summed over substeps";
        j["settings"] = settings;
        ojson cj;
        cj["copy_gb_per_s"] = ceilings.copy_gbps;
        cj["read_gb_per_s"] = ceilings.read_gbps;
        cj["atomics_g_per_s"] = ceilings.atomics_gops;
        cj["dispatch_us"] = ceilings.dispatch_us;
        cj["indirect_dispatch_us"] = ceilings.indirect_dispatch_us;
        cj["wide_dispatch_us"] = ceilings.wide_dispatch_us;
        cj["static_indirect_dispatch_us"] = ceilings.static_indirect_dispatch_us;
        cj["wide_static_indirect_dispatch_us"] = ceilings.wide_static_indirect_dispatch_us;
        cj["copy_dispatch_us"] = ceilings.copy_dispatch_us;
        cj["paired_copy_dispatch_us"] = ceilings.paired_copy_dispatch_us;
        cj["traffic_model"] = pfb::traffic_model_note();
        j["ceilings"] = cj;
        ojson arr = ojson::array();
        for (const Result& r : results) arr.push_back(result_json(r, ceilings));
        j["scenes"] = arr;
        std::ofstream f(opt.json_path);
        f << j.dump(2) << "\n";
        if (!f) throw Error("cannot write " + opt.json_path);
        std::printf("wrote %s\n", opt.json_path.c_str());
    }
    if (!opt.csv_path.empty()) {
        write_csv(opt.csv_path, results);
        std::printf("wrote %s\n", opt.csv_path.c_str());
    }
    return failed ? 1 : 0;
}

} // namespace

int main(int argc, char** argv) { return pfs::run_tool("pf_bench", run, argc, argv); }
