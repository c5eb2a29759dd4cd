// pf_surface_bench — how smooth pflip's rendered liquid surface is, and what it costs.
//
// For each resting pool (samples/common/surface_metric.h: N^3 cells, liquid to 40% of the depth,
// 8 particles a cell), left to settle, and each render size and look, draw the pool through the
// pool's camera and measure the RMS and 95th-percentile angle between the normal the rendered
// depth implies and straight up, with the median GPU ms of each render pass over the calls.
// Looks: "default" (pf_default_ssf_params) and "bilateral_8px" (the look before issue 19: the
// bilateral filter, 8 pixels wide whatever the distance). With --dam-break, also the dam break of
// surface_metric.h at those sizes: its roughness (the angle between each pixel's normal and its
// neighbourhood's mean). Output: a table, optionally JSON.

#include <glad/gl.h>

#include <pf/pf.h>

#include "cli.h"
#include "egl_context.h"
#include "surface_metric.h"
#include "util.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace {

using ojson = nlohmann::ordered_json;
constexpr float kBox = 1.6f;  // metres, as the engine test's pool

struct Options {
    std::vector<uint32_t> cells{32, 72, 144};
    std::vector<uint32_t> dam_break_cells;  // none unless asked
    std::vector<pfs::Size> sizes{{1280, 720}, {1920, 1080}};
    uint32_t settle = 20;  // frames simulated before measuring
    uint32_t frames = 30;  // timed render calls per configuration
    std::string json_path;
};

struct Look {
    const char* name;
    pf_ssf_params params;
};

std::vector<Look> looks() {
    pf_ssf_params before = pf_default_ssf_params();
    before.filter = PF_SSF_FILTER_BILATERAL;
    before.filter_radius = 8;
    before.filter_iterations = 1;
    before.filter_world_radius = 1e6f;  // always past the 8-pixel cap
    return {{"default", pf_default_ssf_params()}, {"bilateral_8px", before}};
}

// The engine's target: an FBO with an RGBA16F colour and a DEPTH_COMPONENT32F depth texture.
class Target {
public:
    Target(int w, int h) : width(w), height(h) {
        glGenTextures(2, tex_);
        glBindTexture(GL_TEXTURE_2D, tex_[0]);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA16F, w, h);
        glBindTexture(GL_TEXTURE_2D, tex_[1]);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, w, h);
        glGenFramebuffers(1, &fbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex_[0], 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex_[1], 0);
    }
    ~Target() {
        glDeleteFramebuffers(1, &fbo_);
        glDeleteTextures(2, tex_);
    }
    Target(const Target&) = delete;
    Target& operator=(const Target&) = delete;

    void clear() const {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
        glViewport(0, 0, width, height);
        glClearColor(0.4f, 0.5f, 0.6f, 1.0f);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    std::vector<float> read_depth() const {
        std::vector<float> d(size_t(width) * height);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, d.data());
        return d;
    }
    pf_render_target target() const { return {fbo_, tex_[0], tex_[1], 0}; }

    const int width, height;

private:
    GLuint fbo_ = 0, tex_[2] = {};
};

// The scene's depth at width x height through its camera, measured: the pool's normal error or
// the dam break's roughness.
using Metric = pfs::NormalError (*)(const std::vector<float>& depth, const std::vector<uint8_t>& liquid, int w, int h,
                                   const glm::dmat4& view, const glm::dmat4& proj);
using CameraFor = pf_camera (*)(int w, int h, glm::dmat4& view, glm::dmat4& proj);

// Every size and look of one settled simulation: the metric of its first render, the median GPU
// ms per pass over the timed calls.
ojson measure(const Options& opt, pf_sim* sim, const char* scene, uint32_t cells, CameraFor camera_for, Metric metric) {
    pf_stats st{};
    st.struct_size = sizeof st;  // every field, render_whitewater_gpu_ms included
    pf_get_stats(sim, &st);
    std::printf("  %u particles\n", st.particle_count);
    ojson rows = ojson::array();
    for (const auto& [w, h] : opt.sizes) {
        Target t{int(w), int(h)};
        glm::dmat4 view, proj;
        const pf_camera camera = camera_for(int(w), int(h), view, proj);
        const pf_render_target target = t.target();
        for (const Look& look : looks()) {
            pfs::RenderTimings timings;
            pfs::NormalError e;
            for (uint32_t i = 0; i < opt.frames + 8; ++i) {  // 8 extra calls let the last timings arrive
                t.clear();
                pfs::check(pf_render_ssf(sim, &camera, &target, &look.params), "pf_render_ssf");
                if (i == 0) {
                    const std::vector<float> depth = t.read_depth();
                    std::vector<uint8_t> liquid(depth.size());
                    for (size_t k = 0; k < depth.size(); ++k) liquid[k] = depth[k] != 1.0f;
                    e = metric(depth, liquid, int(w), int(h), view, proj);
                }
                pf_get_stats(sim, &st);
                timings.add(st);
            }
            const pfs::RenderTimings::Result r = timings.summary(opt.frames);
            ojson j;
            j["scene"] = scene;
            j["cells"] = cells;
            j["particles"] = st.particle_count;
            j["size"] = {w, h};
            j["look"] = look.name;
            j["rms_deg"] = e.rms_deg;
            j["p95_deg"] = e.p95_deg;
            j["pixels"] = e.pixels;
            for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p)
                j["gpu_ms_median"][pf_render_pass_name(pf_render_pass(p))] = r.pass[p].median;
            j["gpu_total_ms_median"] = r.total.median;
            std::printf("  %4ux%-4u %-14s RMS %6.2f deg  p95 %6.2f deg  (%d px)  gpu %7.3f ms (smooth %.3f)\n", w, h,
                        look.name, e.rms_deg, e.p95_deg, e.pixels, j["gpu_total_ms_median"].get<double>(),
                        j["gpu_ms_median"]["smooth"].get<double>());
            rows.push_back(j);
        }
    }
    return rows;
}

pfs::SimPtr create_sim(pf_sim_desc d) {
    d.gl_get_proc_address = pfs::get_proc;
    d.logger = pfs::stderr_logger(false);
    pf_sim* raw = nullptr;
    pfs::check(pf_create(&d, &raw), "pf_create");
    return pfs::SimPtr(raw);
}

ojson measure_pool(const Options& opt, uint32_t cells) {
    pfs::SimPtr sim = create_sim(pfs::pool_desc(cells, kBox));
    const float lo[3] = {0.0f, 0.0f, 0.0f}, hi[3] = {kBox, float(pfs::kPoolDepth) * kBox, kBox};
    pfs::check(pf_fill_box(sim.get(), lo, hi, nullptr), "pf_fill_box");
    for (uint32_t f = 0; f < opt.settle; ++f) pfs::check(pf_step(sim.get(), 1.0f / 60.0f), "pf_step");
    std::printf("\n[pool %u^3] %u frames settled\n", cells, opt.settle);
    return measure(
        opt, sim.get(), "pool", cells,
        [](int w, int h, glm::dmat4& view, glm::dmat4& proj) { return pfs::pool_camera(kBox, w, h, view, proj); },
        [](const std::vector<float>& depth, const std::vector<uint8_t>& liquid, int w, int h, const glm::dmat4& view,
           const glm::dmat4& proj) {
            return pfs::normal_error(depth, liquid, w, h, view, proj, PF_DEPTH_STANDARD, {0.0, 1.0, 0.0}, 3);
        });
}

ojson measure_dam_break(const Options& opt, uint32_t cells) {
    pfs::SimPtr sim = create_sim(pfs::dam_break_desc(cells));
    const float lo[3] = {0.0f, 0.0f, 0.0f};
    pfs::check(pf_fill_box(sim.get(), lo, pfs::kDamBreakColumn, nullptr), "pf_fill_box");
    for (int f = 0; f < pfs::kDamBreakFrames; ++f) pfs::check(pf_step(sim.get(), 1.0f / 60.0f), "pf_step");
    std::printf("\n[dam break, %u cells along x] %d frames after the release\n", cells, pfs::kDamBreakFrames);
    return measure(opt, sim.get(), "dam_break", cells, pfs::dam_break_camera,
                   [](const std::vector<float>& depth, const std::vector<uint8_t>& liquid, int w, int h,
                      const glm::dmat4& view, const glm::dmat4& proj) {
                       return pfs::normal_roughness(depth, liquid, w, h, view, proj, PF_DEPTH_STANDARD, 3,
                                                    pfs::roughness_window(w));
                   });
}

int run(int argc, char** argv) {
    Options opt;
    CLI::App app{"pf_surface_bench: smoothness and cost of pflip's rendered liquid surface on a resting pool "
                 "(docs/rendering.md)",
                 "pf_surface_bench"};
    pfs::init_app(app);
    app.add_option("--cells", opt.cells, "pool sizes in cells per axis, comma-separated (32: 105k particles, "
                                         "72: 1.19M, 144: 9.6M)")
        ->delimiter(',')
        ->check(pfs::Range(8u, 256u))
        ->capture_default_str();
    app.add_option("--dam-break", opt.dam_break_cells, "also the dam break at these cells along x, comma-separated "
                                                       "(128: 1.2M particles, 256: 9.4M)")
        ->delimiter(',')
        ->check(pfs::Range(16u, 512u));
    app.add_option("--sizes", opt.sizes, "render sizes, comma-separated")
        ->delimiter(',')
        ->check(pfs::SizeValidator())
        ->type_name("WxH,...")
        ->capture_default_str();
    app.add_option("--settle", opt.settle, "frames simulated before measuring")
        ->check(pfs::Range(0u, 100000u))
        ->capture_default_str();
    app.add_option("--frames", opt.frames, "timed render calls per configuration")
        ->check(pfs::Range(1u, 100000u))
        ->capture_default_str();
    app.add_option("--json", opt.json_path, "write results as JSON")->type_name("PATH");
    CLI11_PARSE(app, argc, argv);
    pfs::EglContext ctx;
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(pfs::get_proc))) throw pfs::Error("gladLoadGL failed");
    std::printf("pf_surface_bench, %s\n%s\n", pfs::utc_timestamp().c_str(), ctx.describe().c_str());
    ojson root;
    root["tool"] = "pf_surface_bench";
    root["date"] = pfs::utc_timestamp();
    root["renderer"] = ctx.gl_renderer();
    root["gl_version"] = ctx.gl_version();
    root["results"] = ojson::array();
    for (uint32_t cells : opt.cells) {
        for (ojson& row : measure_pool(opt, cells)) root["results"].push_back(row);
    }
    for (uint32_t cells : opt.dam_break_cells) {
        for (ojson& row : measure_dam_break(opt, cells)) root["results"].push_back(row);
    }
    if (!opt.json_path.empty()) std::ofstream(opt.json_path) << root.dump(2) << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) { return pfs::run_tool("pf_surface_bench", run, argc, argv); }
