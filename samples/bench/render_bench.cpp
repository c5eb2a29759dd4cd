// pf_render_bench — per-pass GPU cost of pflip's liquid rendering.
//
// For each scene: simulate W frames so the liquid is in motion, then hold the simulation
// still and, for every resolution x filter x path (and the particle view), draw M frames the
// way an engine does (world first, then pf_render_ssf into the world's framebuffer). Per
// configuration it reports the median of pf_stats.render_gpu_ms per pass over the distinct
// measured render calls, and the wall time of a frame (glFinish around the world + liquid).
// Output: a table on stdout, optionally JSON (--json) and CSV (--csv).

#include <glad/gl.h>

#include <pf/pf.h>

#include "camera.h"
#include "cli.h"
#include "egl_context.h"
#include "scene.h"
#include "util.h"
#include "world.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace {

using pfs::Error;
using ojson = nlohmann::ordered_json;

struct Options {
    std::vector<std::string> scenes{"original_24", "dam_break_1m"};
    std::vector<pfs::Size> sizes{{1280, 720}, {1920, 1080}};
    uint32_t warmup = 60;   // simulated frames before rendering
    uint32_t frames = 60;   // measured render calls per configuration
    float spray_radius_scale = 0;  // 0: pflip's default
    bool compute_only = false;     // no raster path, no particle view
    std::string json_path, csv_path;
};

struct Config {
    uint32_t width, height;
    bool ssf;
    pf_ssf_filter filter;
    pf_ssf_path path;
    std::string name() const {
        if (!ssf) return "particles";
        const char* f = filter == PF_SSF_FILTER_BILATERAL ? "bilateral" : filter == PF_SSF_FILTER_NARROW_RANGE ? "narrow" : "none";
        return std::string("ssf/") + f + "/" + (path == PF_SSF_PATH_COMPUTE ? "compute" : "raster");
    }
};

struct Measurement {
    std::string scene;
    uint32_t particles = 0;
    Config config{};
    pfs::Summary pass[PF_RENDER_PASS_COUNT];
    pfs::Summary whitewater;  // the whitewater layer
    pfs::Summary total, wall;
};

void add_options(CLI::App& app, Options& o) {
    pfs::init_app(app);
    app.add_option("scenes", o.scenes, "scene files or names in the scenes directory")
        ->type_name("SCENE")
        ->capture_default_str();
    app.add_option("--warmup", o.warmup, "frames simulated before rendering")
        ->check(pfs::Range(0u, 100000u))
        ->capture_default_str();
    app.add_option("--frames", o.frames, "measured render calls per configuration")
        ->check(pfs::Range(1u, 100000u))
        ->capture_default_str();
    // One argument (a list), so a scene after it stays a scene.
    app.add_option("--sizes", o.sizes, "render sizes, comma-separated; each x {bilateral, narrow, none} x "
                                       "{compute, raster} plus the particle view")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->check(pfs::SizeValidator())
        ->type_name("WxH,...")
        ->capture_default_str();
    app.add_option("--spray-radius-scale", o.spray_radius_scale,
                   "radius of spray (isolated particles) over the particle radius, 1 = drawn whole (0 = pflip's default)")
        ->check(pfs::Range(0.0f, 1.0f));
    app.add_flag("--compute-only", o.compute_only, "only the compute path's configurations (no raster path, no particle view)");
    app.add_option("--json", o.json_path, "write results as JSON")->type_name("PATH");
    app.add_option("--csv", o.csv_path, "write results as CSV")->type_name("PATH");
}

std::vector<Config> configs(const Options& o) {
    std::vector<Config> c;
    for (const auto& [w, h] : o.sizes) {
        for (pf_ssf_filter f : {PF_SSF_FILTER_BILATERAL, PF_SSF_FILTER_NARROW_RANGE, PF_SSF_FILTER_NONE})
            for (pf_ssf_path p : {PF_SSF_PATH_COMPUTE, PF_SSF_PATH_RASTER})
                if (p == PF_SSF_PATH_COMPUTE || !o.compute_only) c.push_back({w, h, true, f, p});
        if (!o.compute_only) c.push_back({w, h, false, PF_SSF_FILTER_NONE, PF_SSF_PATH_COMPUTE});
    }
    return c;
}

void bench_scene(const Options& opt, const std::string& arg, std::vector<Measurement>& out) {
    const pfs::Scene scene = pfs::load_scene(pfs::resolve_scene_path(arg));
    pfs::SceneEffectIds effects;  // owns the SDF obstacles' textures: declared first, outlives sim
    pfs::SimPtr sim(
        pfs::create_scene_sim(scene, pfs::get_proc, pfs::stderr_logger(false), &effects));
    for (uint32_t i = 0; i < opt.warmup; ++i) pfs::check(pf_step(sim.get(), scene.frame_dt), "pf_step");
    pf_stats st{};
    st.struct_size = sizeof st;  // every field, render_whitewater_gpu_ms included
    pf_get_stats(sim.get(), &st);
    std::printf("\n[%s] %u particles, %u frames simulated\n", scene.name.c_str(), st.particle_count, opt.warmup);

    pfs::World world(scene, pfs::get_proc);
    pfs::OrbitCamera camera;
    camera.set_from_scene(scene.has_camera ? scene.camera : scene.default_camera());
    world.fit_clip_planes(camera);
    for (const Config& c : configs(opt)) {
        world.resize(int(c.width), int(c.height));
        pfs::LiquidLook look;
        look.ssf = c.ssf;
        look.ssf_params.filter = c.filter;
        look.ssf_params.path = c.path;
        look.ssf_params.spray_radius_scale = opt.spray_radius_scale;
        pfs::RenderTimings timings;
        std::vector<double> wall;
        for (uint32_t i = 0; i < opt.frames + 8; ++i) {  // 8 extra calls let the last timings arrive
            glFinish();
            const double t0 = pfs::now_ms();
            pfs::check(pfs::draw_frame(world, sim.get(), camera, look), "render");
            glFinish();
            if (i < opt.frames) wall.push_back(pfs::now_ms() - t0);
            pf_get_stats(sim.get(), &st);
            timings.add(st);
        }
        // The last `frames` measured calls (the first ones include program compilation).
        const pfs::RenderTimings::Result r = timings.summary(opt.frames);
        Measurement m;
        m.scene = scene.name;
        m.particles = st.particle_count;
        m.config = c;
        for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p) m.pass[p] = r.pass[p];
        m.whitewater = r.whitewater;
        m.total = r.total;
        m.wall = pfs::summarize(wall);
        std::printf("  %4ux%-4u %-22s gpu %8.3f ms (median of %zu)  frame wall %8.3f ms\n", c.width, c.height,
                    c.name().c_str(), m.total.median, m.total.n, m.wall.median);
        out.push_back(m);
    }
}

void write_outputs(const Options& opt, const std::vector<Measurement>& ms, const pfs::EglContext& ctx) {
    if (!opt.json_path.empty()) {
        ojson root;
        root["tool"] = "pf_render_bench";
        root["date"] = pfs::utc_timestamp();
        root["renderer"] = ctx.gl_renderer();
        root["gl_version"] = ctx.gl_version();
        root["frames_per_config"] = opt.frames;
        for (const Measurement& m : ms) {
            ojson j;
            j["scene"] = m.scene;
            j["particles"] = m.particles;
            j["size"] = {m.config.width, m.config.height};
            j["config"] = m.config.name();
            for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p)
                j["gpu_ms_median"][pf_render_pass_name(pf_render_pass(p))] = m.pass[p].median;
            j["gpu_ms_median"]["whitewater"] = m.whitewater.median;
            j["gpu_total_ms_median"] = m.total.median;
            j["frame_wall_ms_median"] = m.wall.median;
            j["samples"] = m.total.n;
            root["results"].push_back(j);
        }
        std::ofstream(opt.json_path) << root.dump(2) << "\n";
    }
    if (!opt.csv_path.empty()) {
        std::ofstream f(opt.csv_path);
        f << "scene,particles,width,height,config";
        for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p) f << ",gpu_" << pf_render_pass_name(pf_render_pass(p));
        f << ",gpu_whitewater,gpu_total,frame_wall\n";
        for (const Measurement& m : ms) {
            f << m.scene << "," << m.particles << "," << m.config.width << "," << m.config.height << "," << m.config.name();
            for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p) f << "," << m.pass[p].median;
            f << "," << m.whitewater.median << "," << m.total.median << "," << m.wall.median << "\n";
        }
    }
}

void print_table(const std::vector<Measurement>& ms) {
    std::printf("\nGPU ms per render call (median), by pass:\n%-14s %-10s %-22s", "scene", "size", "config");
    for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p) std::printf(" %10.10s", pf_render_pass_name(pf_render_pass(p)));
    std::printf(" %10s %10s\n", "whitewater", "total");
    for (const Measurement& m : ms) {
        char size[32];
        std::snprintf(size, sizeof(size), "%ux%u", m.config.width, m.config.height);
        std::printf("%-14.14s %-10s %-22s", m.scene.c_str(), size, m.config.name().c_str());
        for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p) std::printf(" %10.3f", m.pass[p].median);
        std::printf(" %10.3f %10.3f\n", m.whitewater.median, m.total.median);
    }
}

int run(int argc, char** argv) {
    Options opt;
    CLI::App app{"pf_render_bench: per-pass GPU cost of pflip's liquid rendering (docs/performance.md)",
                 "pf_render_bench"};
    add_options(app, opt);
    CLI11_PARSE(app, argc, argv);
    pfs::EglContext ctx;
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(pfs::get_proc))) throw Error("gladLoadGL failed");
    std::printf("pf_render_bench, %s\n%s\n", pfs::utc_timestamp().c_str(), ctx.describe().c_str());
    std::vector<Measurement> ms;
    for (const std::string& s : opt.scenes) bench_scene(opt, s, ms);
    print_table(ms);
    write_outputs(opt, ms, ctx);
    return 0;
}

}  // namespace

int main(int argc, char** argv) { return pfs::run_tool("pf_render_bench", run, argc, argv); }
