// pf_headless — the pflip demo without a window.
//
// Creates a headless GL 4.3 context (EGL), loads a scene and runs it with pf_step. Every K
// frames it renders the way an engine would: the sample's "world" (sky, floor, tank, crates and
// the scene's obstacles at their current poses, floating ones included: samples/common/world.h,
// drawn with the sample's own GL loader) goes into the sample's own
// framebuffer with a colour and a depth texture, then pflip draws the liquid into that
// framebuffer (pf_render_ssf, or pf_render_particles for the debug view) over the world's
// colour and depth, and the image is read back to frame_NNNN.png. With --video the PNGs are
// encoded to an H.264 MP4 by ffmpeg. At the end it prints pflip's per-pass GPU timings of the
// simulation (the runtime pass list, so the active solver's own passes show) and of the
// rendering, the pressure solver's iterations and final residual, and the wall time per step.
// With --export-ply every frame's particles (positions and velocities) go to DIR/frame_NNNN.ply
// for Blender, Houdini and other DCC tools.
//
// Only the public API (pf/pf.h) is used for the simulation and the liquid.

#include <glad/gl.h>

#include <pf/pf.h>

#include "camera.h"
#include "cli.h"
#include "egl_context.h"
#include "gl_util.h"
#include "image_write.h"
#include "ply_write.h"
#include "vdb_write.h"
#include "floating.h"
#include "obstacle_shapes.h"
#include "scene.h"
#include "util.h"
#include "world.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using pfs::Error;

// ---- command line ---------------------------------------------------------------------------

/// What --export-vdb writes each frame.
enum class VdbContent { volume, points, both };

struct Options {
    std::string scene = "dam_break_small";
    bool frames_set = false;
    uint32_t frames = 0;
    std::string out = "out";
    pfs::Size size{960, 540};
    uint32_t every = 4;
    bool ssf = true;
    pf_ssf_filter filter = pf_default_ssf_params().filter;
    uint32_t filter_radius = 0;       // 0: pflip's default
    float filter_world_radius = 0;    // 0: pflip's default
    float spray_radius_scale = 0;     // 0: pflip's default
    pf_ssf_path path = PF_SSF_PATH_COMPUTE;
    pf_depth_convention depth = PF_DEPTH_STANDARD;
    bool builtin_sky = false;
    bool draw_obstacles = true;       // --hide-obstacles: simulated but not drawn
    float radius = 0;                 // 0: pflip's default
    pf_particle_color color_by = PF_PARTICLE_COLOR_SPEED;
    bool color_by_set = false;
    std::string video;
    float fps = 0;                    // 0: real time
    bool verbose = false;
    bool debug = false;
    pfs::ParamOverrides overrides;    // --preset, --solver, --tolerance, --transfer, --advection, --p2g, ...
    std::string export_ply;           // directory for frame_NNNN.ply; empty: no export
    pfs::PlyFormat ply_format = pfs::PlyFormat::binary_little_endian;
    std::string export_vdb;           // directory for frame_NNNN.vdb / frame_NNNN_points.vdb; empty: none
    VdbContent vdb_content = VdbContent::both;
    float count_above = -1.0f;        // --count-above: print the particles above this height at the end
};

void add_options(CLI::App& app, Options& o) {
    pfs::init_app(app);
    app.add_option("--scene", o.scene, "scene file, or a name in the scenes directory")
        ->type_name("PATH|NAME")
        ->capture_default_str();
    app.add_option("--frames", o.frames, "frames to simulate (default: the scene's \"frames\")")
        ->check(pfs::Range(0u, 10000000u));
    app.add_option("--out", o.out, "where frame_NNNN.png go")->type_name("DIR")->capture_default_str();
    app.add_option("--size", o.size, "image size")
        ->check(pfs::SizeValidator())
        ->type_name("WxH")
        ->capture_default_str();
    app.add_option("--every", o.every, "write an image every K frames, 0 = none")
        ->check(pfs::Range(0u, 1000000u))
        ->capture_default_str();
    app.add_option("--render", o.ssf, "pflip's screen-space fluid or its debug particles")
        ->transform(pfs::NameMap(pfs::render_choices(), "renderer"))
        ->type_name("NAME")
        ->default_str("ssf");
    app.add_option("--filter", o.filter, "SSF depth filter")
        ->transform(pfs::NameMap(pfs::Choices<pf_ssf_filter>{{"bilateral", PF_SSF_FILTER_BILATERAL},
                                                             {"narrow", PF_SSF_FILTER_NARROW_RANGE},
                                                             {"narrow_range", PF_SSF_FILTER_NARROW_RANGE},
                                                             {"none", PF_SSF_FILTER_NONE}},
                                 "filter"))
        ->type_name("NAME")
        ->default_str("narrow");
    app.add_option("--filter-radius", o.filter_radius, "SSF filter's largest half-width in pixels (0 = pflip's default)")
        ->check(CLI::Range(0u, 64u));
    app.add_option("--filter-world-radius", o.filter_world_radius,
                   "SSF filter's half-width in metres on the liquid (0 = pflip's default: one cell)")
        ->check(CLI::Range(0.0f, 1e6f));
    app.add_option("--spray-radius-scale", o.spray_radius_scale,
                   "radius of spray (isolated particles) over the particle radius, 1 = drawn whole (0 = pflip's default)")
        ->check(CLI::Range(0.0f, 1.0f));
    app.add_option("--path", o.path, "SSF passes as compute or fragment shaders")
        ->transform(pfs::NameMap(
            pfs::Choices<pf_ssf_path>{{"compute", PF_SSF_PATH_COMPUTE}, {"raster", PF_SSF_PATH_RASTER}}, "path"))
        ->type_name("NAME")
        ->default_str("compute");
    app.add_option("--depth", o.depth, "depth convention of the camera (all but standard use glClipControl, GL 4.5)")
        ->transform(pfs::NameMap(pfs::depth_choices(), "depth convention"))
        ->type_name("NAME")
        ->default_str("standard");
    app.add_flag("--builtin-sky", o.builtin_sky, "let pflip reflect its built-in sky instead of the world's cube map");
    app.add_flag_callback("--hide-obstacles", [&o] { o.draw_obstacles = false; },
                          "leave the scene's obstacles out of the images (still simulated; for comparisons)");
    app.add_option("--radius", o.radius, "particle radius in metres (default: half a cell)")
        ->check(pfs::Range(1e-5f, 100.0f));
    app.add_option("--color-by", o.color_by, "particle colouring (with --render particles)")
        ->transform(pfs::NameMap(pfs::Choices<pf_particle_color>{{"speed", PF_PARTICLE_COLOR_SPEED},
                                                                 {"vx", PF_PARTICLE_COLOR_VELOCITY_X},
                                                                 {"vy", PF_PARTICLE_COLOR_VELOCITY_Y},
                                                                 {"vz", PF_PARTICLE_COLOR_VELOCITY_Z},
                                                                 {"height", PF_PARTICLE_COLOR_HEIGHT},
                                                                 {"uniform", PF_PARTICLE_COLOR_UNIFORM}},
                                 "colouring"))
        ->type_name("NAME");
    app.add_option("--video", o.video, "encode the PNGs to H.264 with ffmpeg (needs ffmpeg on PATH and --every > 0)")
        ->type_name("FILE.mp4");
    app.add_option("--fps", o.fps, "video frame rate (default: real time, 1 / (frame_dt * every))")
        ->check(pfs::Range(0.1f, 1000.0f));
    app.add_option("--count-above", o.count_above,
                   "at the end, print how many particles lie above this world height in metres (liquid "
                   "hanging from a lid)")
        ->type_name("METRES");
    app.add_option("--export-ply", o.export_ply,
                   "write every frame's particles to DIR/frame_NNNN.ply (x y z vx vy vz; frame 0: the initial fill)")
        ->type_name("DIR");
    app.add_option("--ply-format", o.ply_format, "PLY encoding (binary is little-endian)")
        ->transform(pfs::NameMap(pfs::Choices<pfs::PlyFormat>{{"binary", pfs::PlyFormat::binary_little_endian},
                                                              {"ascii", pfs::PlyFormat::ascii}},
                                 "PLY format"))
        ->type_name("NAME")
        ->default_str("binary");
    app.add_option("--export-vdb", o.export_vdb,
                   "write every frame to DIR as OpenVDB: frame_NNNN.vdb (grids surface, density, velocity) and "
                   "frame_NNNN_points.vdb (point data P, v); frame 0: the initial fill")
        ->type_name("DIR");
    app.add_option("--vdb-content", o.vdb_content, "which OpenVDB files --export-vdb writes")
        ->transform(pfs::NameMap(pfs::Choices<VdbContent>{{"both", VdbContent::both},
                                                          {"volume", VdbContent::volume},
                                                          {"points", VdbContent::points}},
                                 "VDB content"))
        ->type_name("NAME")
        ->default_str("both");
    pfs::add_param_overrides(app, o.overrides);
    app.add_flag("--verbose", o.verbose, "pflip's info messages and EGL details");
    app.add_flag("--debug-context", o.debug, "request a debug GL context");
    app.footer("environment: PF_EGL_PLATFORM=device|surfaceless, PF_EGL_DEVICE=N, PF_SCENES_DIR=DIR\n"
               "scenes directory: " + pfs::scenes_dir());
    app.callback([&app, &o] {
        o.frames_set = app.count("--frames") > 0;
        o.color_by_set = app.count("--color-by") > 0;
        if (!o.video.empty() && o.every == 0)
            throw CLI::ValidationError("--video", "needs images: --every must be > 0");
    });
}

// ---- video ----------------------------------------------------------------------------------

std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) {
        if (c == '\'') q += "'\\''";
        else q += c;
    }
    return q + "'";
}

bool have_ffmpeg() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

/// Encodes dir/frame_0000.png .. frame_{count-1}.png to an H.264 MP4; false (with a message
/// on stderr) when ffmpeg is missing or fails.
bool encode_video(const std::string& dir, uint32_t count, float fps, const std::string& out) {
    if (!have_ffmpeg()) {
        std::fprintf(stderr,
                     "pf_headless: --video: ffmpeg is not on PATH, no video written (the PNGs are in %s;\n"
                     "  Debian/Ubuntu: apt-get install ffmpeg, or scripts/setup.sh)\n",
                     dir.c_str());
        return false;
    }
    char rate[32];
    std::snprintf(rate, sizeof rate, "%.6g", double(fps));
    // yuv420p needs even sizes; libx264 is in Debian's ffmpeg.
    const std::string cmd = "ffmpeg -y -hide_banner -loglevel error -framerate " + std::string(rate) + " -i " +
                            shell_quote((std::filesystem::path(dir) / "frame_%04d.png").string()) + " -frames:v " +
                            std::to_string(count) +
                            " -vf 'scale=trunc(iw/2)*2:trunc(ih/2)*2' -c:v libx264 -pix_fmt yuv420p -crf 20 "
                            "-movflags +faststart " +
                            shell_quote(out);
    std::printf("encoding video: %s\n", cmd.c_str());
    std::fflush(stdout);
    const int rc = std::system(cmd.c_str());
    if (rc != 0) {
        std::fprintf(stderr, "pf_headless: --video: ffmpeg failed (exit status %d)\n", rc);
        return false;
    }
    return true;
}

// ---- particle export (PLY, OpenVDB) ---------------------------------------------------------

/// Every frame's particles, read back once for all the exports asked for (a stall, acceptable
/// for an export), and the wall time each part took.
struct ParticleExport {
    std::string ply_dir, vdb_dir;
    pfs::PlyFormat ply_format = pfs::PlyFormat::binary_little_endian;
    VdbContent vdb_content = VdbContent::both;
    std::string scene_name;
    float cell_size = 0;
    uint32_t particles_per_cell = 8;
    std::vector<float> xyz, vel;
    double readback_ms = 0, ply_ms = 0, vdb_ms = 0;
    uint64_t particles_written = 0;
    uint32_t frames_written = 0;

    bool any() const { return !ply_dir.empty() || !vdb_dir.empty(); }

    void write(pf_sim* sim, uint32_t frame) {
        if (!any()) return;
        const double t0 = pfs::now_ms();
        pf_stats st{};
        pfs::check(pf_get_stats(sim, &st), "pf_get_stats");
        const uint32_t n = st.particle_count;
        xyz.resize(3 * size_t(n));
        vel.resize(3 * size_t(n));
        if (n > 0) pfs::check(pf_read_particles(sim, 0, n, xyz.data(), vel.data()), "pf_read_particles");
        const double t1 = pfs::now_ms();
        readback_ms += t1 - t0;
        char stem[32];
        std::snprintf(stem, sizeof stem, "frame_%04u", frame);
        if (!ply_dir.empty()) {
            const std::string path = (std::filesystem::path(ply_dir) / (std::string(stem) + ".ply")).string();
            const std::string comment = "pflip " + pfs::pf_version_string() + " scene " + scene_name + " frame " +
                                        std::to_string(frame) + ", metres and m/s";
            if (!pfs::write_ply_particles(path, xyz.data(), vel.data(), n, ply_format, comment))
                throw Error("writing " + path + " failed: " + std::strerror(errno));
        }
        const double t2 = pfs::now_ms();
        ply_ms += t2 - t1;
        if (!vdb_dir.empty()) {
            std::string error;
            const std::filesystem::path dir(vdb_dir);
            if (vdb_content != VdbContent::points) {
                pfs::VdbVolumeParams p;
                p.cell_size = cell_size;
                p.particles_per_cell = float(particles_per_cell);
                const std::string path = (dir / (std::string(stem) + ".vdb")).string();
                if (!pfs::write_vdb_volume(path, xyz.data(), vel.data(), n, p, &error))
                    throw Error("writing " + path + " failed: " + error);
            }
            if (vdb_content != VdbContent::volume) {
                const std::string path = (dir / (std::string(stem) + "_points.vdb")).string();
                if (!pfs::write_vdb_points(path, xyz.data(), vel.data(), n, cell_size, &error))
                    throw Error("writing " + path + " failed: " + error);
            }
        }
        vdb_ms += pfs::now_ms() - t2;
        particles_written += n;
        ++frames_written;
    }
};

/// Creates an export directory or says why it cannot.
void make_export_dir(const std::string& dir, const char* what) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw Error(std::string("cannot create ") + what + " directory '" + dir + "': " + ec.message());
}

// ---- the simulation handle ------------------------------------------------------------------

using pfs::SimPtr;

const char* obstacle_shape_name(pf_obstacle_shape shape) {
    switch (shape) {
    case PF_OBSTACLE_BOX: return "box";
    case PF_OBSTACLE_SPHERE: return "sphere";
    case PF_OBSTACLE_CAPSULE: return "capsule";
    default: return "sdf";
    }
}

/// Where each obstacle's centre starts in the images (pixels, origin top-left as in the PNGs):
/// image checks look there.
void print_obstacle_pixels(const std::vector<pf_obstacle>& obstacles, const pfs::OrbitCamera& camera,
                           const Options& opt, bool drawn) {
    for (size_t i = 0; i < obstacles.size(); ++i) {
        const pf_obstacle& o = obstacles[i];
        glm::vec2 px(0.0f);
        float depth = 0.0f;
        const glm::vec3 centre(o.position[0], o.position[1], o.position[2]);
        if (camera.window_position(centre, int(opt.size.width), int(opt.size.height), px, depth))
            std::printf("  obstacle %zu (%s, %s) centre at pixel %.1f,%.1f\n", i, obstacle_shape_name(o.shape),
                        drawn ? "drawn" : "hidden", double(px.x), double(px.y));
        else
            std::printf("  obstacle %zu (%s, %s) centre behind the camera\n", i, obstacle_shape_name(o.shape),
                        drawn ? "drawn" : "hidden");
    }
}

const char* filter_name(pf_ssf_filter f) {
    switch (f) {
    case PF_SSF_FILTER_NARROW_RANGE: return "narrow range";
    case PF_SSF_FILTER_NONE: return "none";
    default: return "bilateral";
    }
}

int run(int argc, char** argv) {
    const double t_start = pfs::now_ms();
    Options opt;
    CLI::App app{"pf_headless: the pflip demo without a window (EGL): a scene simulated, its frames rendered to PNG",
                 "pf_headless"};
    add_options(app, opt);
    CLI11_PARSE(app, argc, argv);

    // Scene first: a typo in the file should not cost a context creation.
    const std::string scene_path = pfs::resolve_scene_path(opt.scene);
    const pfs::Scene scene = pfs::load_scene(scene_path);
    const uint32_t frames = opt.frames_set ? opt.frames : scene.frames;

    pfs::EglContext::Options copt;
    copt.debug = opt.debug;
    copt.verbose = opt.verbose;
    pfs::EglContext ctx(copt);
    std::printf("pflip %s headless demo\n%s\n", pfs::pf_version_string().c_str(), ctx.describe().c_str());

    // The sample's own GL loader, as an engine would have.
    const int glv = gladLoadGL(pfs::get_proc);
    if (!glv || GLAD_VERSION_MAJOR(glv) * 100 + GLAD_VERSION_MINOR(glv) < 403)
        throw Error("gladLoadGL: OpenGL 4.3 core functions not available");

    pf_sim_desc desc = pfs::make_sim_desc(scene, pfs::get_proc, pfs::stderr_logger(opt.verbose));
    opt.overrides.apply(desc.params);
    std::printf("scene: %s (%s)\n  grid %ux%ux%u, cell %.4g m, domain %.3g x %.3g x %.3g m, capacity %u\n",
                scene.name.c_str(), scene_path.c_str(), desc.grid_size[0], desc.grid_size[1], desc.grid_size[2],
                double(desc.cell_size), double(desc.grid_size[0] * desc.cell_size),
                double(desc.grid_size[1] * desc.cell_size), double(desc.grid_size[2] * desc.cell_size),
                desc.max_particles);
    std::printf("  frame_dt %.5g s, frames %u, flip_ratio %.3g, cfl %.3g, max_substeps %u\n", double(scene.frame_dt),
                frames, double(desc.params.flip_ratio), double(desc.params.cfl), desc.params.max_substeps);
    // pressure_tolerance 0 means the library default; say which value that is.
    const float tolerance =
        desc.params.pressure_tolerance > 0 ? desc.params.pressure_tolerance : pf_default_sim_params().pressure_tolerance;
    std::printf("  solver %s (at most %u iterations, tolerance %.3g, separation %u), transfer %s, advection %s\n",
                pfs::solver_name(desc.params.pressure_solver), desc.params.pressure_iterations, double(tolerance),
                desc.params.separation, pfs::transfer_name(desc.params.transfer),
                pfs::advection_name(desc.params.advection));

    double t0 = pfs::now_ms();
    pfs::SceneEffectIds effects;  // owns the SDF obstacles' textures: declared first, outlives sim
    SimPtr sim;
    {
        pf_sim* raw = nullptr;
        pfs::check(pf_create(&desc, &raw), "pf_create");
        sim.reset(raw);
    }
    const double create_ms = pfs::now_ms() - t0;
    t0 = pfs::now_ms();
    pfs::fill_scene(sim.get(), scene);
    pfs::FloatingBodies floating;
    pfs::DrivenObstacles driven;
    effects = pfs::add_scene_effects(sim.get(), scene);
    pfs::float_scene_obstacles(scene, effects, floating);
    pfs::drive_scene_obstacles(scene, effects, driven);
    // The obstacles as the library holds them (SDF ones with their textures); floating and driven ones move.
    const std::vector<pf_obstacle> placed_obstacles = pfs::obstacles_as_added(scene, effects);
    glFinish();
    const double fill_ms = pfs::now_ms() - t0;

    pf_stats st{};
    st.struct_size = sizeof st;  // every field, whitewater_count included
    pfs::check(pf_get_stats(sim.get(), &st), "pf_get_stats");
    std::printf("  %u particles (estimate %.0f); pf_create %.1f ms, fill %.1f ms\n", st.particle_count,
                scene.estimated_particles(), create_ms, fill_ms);

    // Rendering setup: the world, its camera, pflip's look.
    std::unique_ptr<pfs::World> world;
    pfs::OrbitCamera camera;
    pfs::LiquidLook look;
    if (opt.every > 0) {
        std::error_code ec;
        std::filesystem::create_directories(opt.out, ec);
        if (ec) throw Error("cannot create output directory '" + opt.out + "': " + ec.message());
        world = std::make_unique<pfs::World>(scene, pfs::get_proc);
        world->resize(int(opt.size.width), int(opt.size.height));
        if (opt.depth != PF_DEPTH_STANDARD && !world->has_clip_control())
            throw Error(std::string("--depth ") + pfs::depth_convention_name(opt.depth) +
                        ": this context has no glClipControl (GL 4.5 / ARB_clip_control)");
        camera.set_from_scene(scene.has_camera ? scene.camera : scene.default_camera());
        camera.depth = opt.depth;
        world->fit_clip_planes(camera);

        look.ssf = opt.ssf;
        look.sky_cubemap = !opt.builtin_sky;
        look.ssf_params.filter = opt.filter;
        look.ssf_params.filter_radius = opt.filter_radius;
        look.ssf_params.filter_world_radius = opt.filter_world_radius;
        look.ssf_params.spray_radius_scale = opt.spray_radius_scale;
        look.ssf_params.path = opt.path;
        look.ssf_params.particle_radius = opt.radius;
        look.particle_params.particle_radius = opt.radius;
        if (opt.color_by_set) look.particle_params.color_by = opt.color_by;
        world->set_sun(glm::vec3(look.ssf_params.light_direction[0], look.ssf_params.light_direction[1],
                                 look.ssf_params.light_direction[2]));
        if (opt.ssf)
            std::printf("  images: %ux%u every %u frames -> %s/frame_NNNN.png; pf_render_ssf, %s filter, %s path, "
                        "%s depth, %s sky\n",
                        opt.size.width, opt.size.height, opt.every, opt.out.c_str(), filter_name(opt.filter),
                        opt.path == PF_SSF_PATH_RASTER ? "raster" : "compute", pfs::depth_convention_name(opt.depth),
                        opt.builtin_sky ? "built-in" : "world cube-map");
        else
            std::printf("  images: %ux%u every %u frames -> %s/frame_NNNN.png; pf_render_particles, %s depth\n",
                        opt.size.width, opt.size.height, opt.every, opt.out.c_str(),
                        pfs::depth_convention_name(opt.depth));
        print_obstacle_pixels(scene.obstacles, camera, opt, opt.draw_obstacles);
    }

    // ---- main loop ----
    struct GpuSample {
        uint64_t step;
        float total;
    };
    std::vector<GpuSample> gpu_samples;
    // The runtime pass list: GPU ms of every measured step per entry, in the library's order
    // (first appearance), and the dispatches of the last pf_step.
    std::vector<std::string> pass_order;
    std::map<std::string, std::vector<double>> pass_ms;
    std::map<std::string, uint32_t> pass_dispatches;
    std::vector<pf_pass_stats> pass_list;
    std::vector<uint32_t> substeps_of_step(1, 0); // index: step number (1-based)
    std::vector<double> wall_ms, cpu_ms, solver_iterations, solver_residual;
    uint64_t last_gpu_step = 0;
    uint32_t image_index = 0;
    double sim_total_ms = 0, render_total_ms = 0, png_total_ms = 0;
    std::vector<uint8_t> pixels;
    const uint32_t report_every = std::max(1u, frames / 10);

    struct RenderSample {
        uint64_t frame;
        float ms[PF_RENDER_PASS_COUNT];
        float total, cpu;
    };
    std::vector<RenderSample> render_samples;
    uint64_t last_render_frame = 0;
    std::vector<double> render_wall_ms;

    auto collect_render_stats = [&]() {
        pf_stats rs{};
        pfs::check(pf_get_stats(sim.get(), &rs), "pf_get_stats");
        if (rs.render_frame != 0 && rs.render_frame != last_render_frame) {
            RenderSample r{};
            r.frame = rs.render_frame;
            std::copy(rs.render_gpu_ms, rs.render_gpu_ms + PF_RENDER_PASS_COUNT, r.ms);
            r.total = rs.render_gpu_total_ms;
            r.cpu = rs.render_cpu_ms;
            render_samples.push_back(r);
            last_render_frame = rs.render_frame;
        }
    };

    auto write_image = [&]() {
        if (opt.draw_obstacles)
            world->set_obstacles(driven.poses(floating.poses(placed_obstacles, effects.obstacles), effects.obstacles));
        glFinish();
        const double r0 = pfs::now_ms();
        pfs::check(pfs::draw_frame(*world, sim.get(), camera, look), look.ssf ? "pf_render_ssf" : "pf_render_particles");
        glBindFramebuffer(GL_READ_FRAMEBUFFER, world->framebuffer());
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        pfs::read_rgba(int(opt.size.width), int(opt.size.height), pixels);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        pfs::check_gl("rendering");
        const double r1 = pfs::now_ms();
        render_wall_ms.push_back(r1 - r0);
        collect_render_stats();
        char name[64];
        std::snprintf(name, sizeof name, "frame_%04u.png", image_index++);
        const std::string path = (std::filesystem::path(opt.out) / name).string();
        if (!pfs::write_png_rgba(path, opt.size.width, opt.size.height, pixels.data(), true))
            throw Error("writing " + path + " failed: " + std::strerror(errno));
        render_total_ms += r1 - r0;
        png_total_ms += pfs::now_ms() - r1;
    };

    ParticleExport exporter;
    exporter.ply_dir = opt.export_ply;
    exporter.ply_format = opt.ply_format;
    exporter.vdb_dir = opt.export_vdb;
    exporter.vdb_content = opt.vdb_content;
    exporter.scene_name = scene.name;
    exporter.cell_size = scene.cell_size;
    exporter.particles_per_cell = scene.particles_per_cell ? scene.particles_per_cell
                                                           : pf_default_sim_desc().fill_particles_per_cell;
    if (!opt.export_ply.empty()) {
        make_export_dir(opt.export_ply, "PLY");
        std::printf("  particles: every frame -> %s/frame_NNNN.ply (%s)\n", opt.export_ply.c_str(),
                    opt.ply_format == pfs::PlyFormat::ascii ? "ascii" : "binary little-endian");
    }
    if (!opt.export_vdb.empty()) {
        make_export_dir(opt.export_vdb, "VDB");
        std::printf("  OpenVDB: every frame -> %s/frame_NNNN%s\n", opt.export_vdb.c_str(),
                    opt.vdb_content == VdbContent::both     ? ".vdb and frame_NNNN_points.vdb"
                    : opt.vdb_content == VdbContent::volume ? ".vdb"
                                                            : "_points.vdb");
    }
    exporter.write(sim.get(), 0);

    if (world) write_image();
    for (uint32_t f = 1; f <= frames; ++f) {
        glFinish();
        const double s0 = pfs::now_ms();
        pfs::check(floating.step(sim.get(), scene.frame_dt, scene.params.gravity), "floating obstacles");
        pfs::check(driven.step(sim.get(), scene.frame_dt), "driven obstacles");
        pfs::check(pf_step(sim.get(), scene.frame_dt), "pf_step");
        glFinish();
        const double s1 = pfs::now_ms();
        wall_ms.push_back(s1 - s0);
        sim_total_ms += s1 - s0;

        pfs::check(pf_get_stats(sim.get(), &st), "pf_get_stats");
        cpu_ms.push_back(st.cpu_ms);
        if (substeps_of_step.size() <= st.steps) substeps_of_step.resize(st.steps + 1, 0);
        substeps_of_step[st.steps] = st.substeps;
        solver_iterations.push_back(st.solver_iterations);
        solver_residual.push_back(st.solver_residual);
        pfs::check(pfs::get_pass_list(sim.get(), pass_list), "pf_get_pass_stats");
        const bool new_gpu_step = st.gpu_step != 0 && st.gpu_step != last_gpu_step;
        for (const pf_pass_stats& p : pass_list) {
            if (!pass_ms.count(p.name)) pass_order.push_back(p.name);
            std::vector<double>& ms = pass_ms[p.name];
            if (new_gpu_step) ms.push_back(p.gpu_ms);
            pass_dispatches[p.name] = p.dispatches;
        }
        if (new_gpu_step) {
            gpu_samples.push_back(GpuSample{st.gpu_step, st.gpu_total_ms});
            last_gpu_step = st.gpu_step;
        }

        if (f % report_every == 0 || f == frames)
            std::printf("frame %4u/%u  t=%.3f s  substeps %u  max|v| %.2f m/s  step %.1f ms (wall)  gpu %.2f ms  "
                        "solver %u it, res %.2e%s%s\n",
                        f, frames, double(f) * double(scene.frame_dt), st.substeps, double(st.max_speed),
                        s1 - s0, double(st.gpu_total_ms), st.solver_iterations, double(st.solver_residual),
                        st.flags ? "  flags: " : "", st.flags ? pfs::flag_names(st.flags).c_str() : "");
        std::fflush(stdout);

        if (world && (f % opt.every == 0 || f == frames)) write_image();
        exporter.write(sim.get(), f);
    }

    // ---- report ----
    pfs::check(pf_get_stats(sim.get(), &st), "pf_get_stats");
    std::printf("\n=== %s: %u frames, %u particles (capacity %u), GL_RENDERER %s ===\n", scene.name.c_str(), frames,
                st.particle_count, st.max_particles, ctx.gl_renderer().c_str());

    double gpu_sum_total = 0;
    for (const auto& g : gpu_samples) gpu_sum_total += g.total;
    const bool gpu_valid = !gpu_samples.empty() && gpu_sum_total > 0;
    std::printf("GPU time per step (pf_get_stats, %zu distinct measured steps%s):\n", gpu_samples.size(),
                gpu_valid ? "" : "; timer queries read 0 on this driver");
    // The runtime list (pf_get_pass_stats) in the library's order: its entries are disjoint, so
    // their means add up to the total and the shares to 100%.
    const int name_width = 24;
    std::printf("  %-*s %12s %12s %7s %12s\n", name_width, "pass", "mean ms", "median ms", "share", "dispatches*");
    double total_mean = 0;
    std::vector<pfs::Summary> per_pass;
    for (const std::string& name : pass_order) {
        per_pass.push_back(pfs::summarize(pass_ms[name]));
        total_mean += per_pass.back().mean;
    }
    for (size_t i = 0; i < pass_order.size(); ++i) {
        const auto& s = per_pass[i];
        std::printf("  %-*s %12.4f %12.4f %6.1f%% %12u\n", name_width, pass_order[i].c_str(), s.mean, s.median,
                    total_mean > 0 ? 100.0 * s.mean / total_mean : 0.0, pass_dispatches[pass_order[i]]);
    }
    {
        std::vector<double> tot, per_sub;
        for (const auto& g : gpu_samples) {
            tot.push_back(g.total);
            const uint32_t k = g.step < substeps_of_step.size() ? substeps_of_step[g.step] : 0;
            if (k) per_sub.push_back(g.total / k);
        }
        const auto t = pfs::summarize(tot), ps = pfs::summarize(per_sub);
        std::printf("  %-*s %12.4f %12.4f\n", name_width, "total", t.mean, t.median);
        std::printf("  %-*s %12.4f %12.4f\n", name_width, "total / substep", ps.mean, ps.median);
        std::printf("  (* dispatches in the last pf_step, all its substeps)\n");
    }
    {
        // What the solve bought: iterations taken against the cap, and the residual reached
        // against the tolerance (the largest over each step's substeps).
        const auto it = pfs::summarize(solver_iterations), res = pfs::summarize(solver_residual);
        std::printf("pressure solver %s (pf_stats.solver_iterations / solver_residual, per step):\n",
                    pfs::solver_name(desc.params.pressure_solver));
        std::printf("  iterations: mean %.1f  median %.0f  max %.0f  (cap %u)\n", it.mean, it.median, it.max,
                    desc.params.pressure_iterations);
        std::printf("  final residual: mean %.3g  median %.3g  max %.3g  (tolerance %.3g)\n", res.mean, res.median,
                    res.max, double(tolerance));
    }
    {
        std::vector<double> subs;
        for (size_t i = 1; i < substeps_of_step.size(); ++i)
            if (substeps_of_step[i]) subs.push_back(substeps_of_step[i]);
        const auto s = pfs::summarize(subs);
        const auto w = pfs::summarize(wall_ms), c = pfs::summarize(cpu_ms);
        std::printf("wall ms per step (glFinish before and after pf_step): mean %.2f  median %.2f  min %.2f  max %.2f\n",
                    w.mean, w.median, w.min, w.max);
        std::printf("  per substep: %.2f ms\n", s.mean > 0 ? w.mean / s.mean : 0.0);
        std::printf("host ms inside pf_step (pf_stats.cpu_ms): mean %.3f  median %.3f\n", c.mean, c.median);
        std::printf("substeps per step: mean %.2f  min %.0f  max %.0f  (total %.0f over %zu steps)\n", s.mean, s.min,
                    s.max, s.mean * double(s.n), s.n);
    }
    if (world) {
        // Timer results lag a few calls: the newest images may not have been measured yet.
        collect_render_stats();
        double sum = 0;
        for (const auto& r : render_samples) sum += r.total;
        std::printf("GPU time per image (%s, pf_stats.render_gpu_ms, %zu distinct measured calls%s):\n",
                    look.ssf ? "pf_render_ssf" : "pf_render_particles", render_samples.size(),
                    render_samples.empty() || sum > 0 ? "" : "; timer queries read 0 on this driver");
        std::printf("  %-18s %12s %12s %7s\n", "pass", "mean ms", "median ms", "share");
        std::vector<pfs::Summary> rp(PF_RENDER_PASS_COUNT);
        double rtotal = 0;
        for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p) {
            std::vector<double> v;
            for (const auto& r : render_samples) v.push_back(r.ms[p]);
            rp[size_t(p)] = pfs::summarize(v);
            rtotal += rp[size_t(p)].mean;
        }
        for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p)
            std::printf("  %-18s %12.4f %12.4f %6.1f%%\n", pf_render_pass_name(pf_render_pass(p)), rp[size_t(p)].mean,
                        rp[size_t(p)].median, rtotal > 0 ? 100.0 * rp[size_t(p)].mean / rtotal : 0.0);
        std::vector<double> tot, cpu;
        for (const auto& r : render_samples) {
            tot.push_back(r.total);
            cpu.push_back(r.cpu);
        }
        const auto t = pfs::summarize(tot), c = pfs::summarize(cpu), w = pfs::summarize(render_wall_ms);
        std::printf("  %-18s %12.4f %12.4f\n", "total", t.mean, t.median);
        std::printf("host ms inside the render call (pf_stats.render_cpu_ms): mean %.3f  median %.3f\n", c.mean,
                    c.median);
        std::printf("wall ms per image (world + liquid + glReadPixels, glFinish before): mean %.2f  median %.2f\n",
                    w.mean, w.median);
    }
    std::printf("flags: %s; largest speed %.3f m/s\n", pfs::flag_names(st.flags).c_str(), double(st.max_speed));
    if (scene.features & PF_FEATURE_WHITEWATER) std::printf("whitewater particles: %u\n", st.whitewater_count);
    if (scene.features & PF_FEATURE_VISCOSITY)
        std::printf("viscosity solve: %u iterations, residual %.2g\n", st.viscosity_iterations, double(st.viscosity_residual));
    if (scene.features & PF_FEATURE_SURFACE_TENSION) {
        // Its cost shows as substeps: the explicit force keeps each under half the capillary limit.
        pf_surface_tension t = pf_default_surface_tension();
        pfs::check(pf_get_surface_tension(sim.get(), &t), "pf_get_surface_tension");
        std::printf("surface tension: %.3g N/m, %u substeps in the last step\n", double(t.tension), st.substeps);
    }
    if (opt.count_above >= 0.0f) {
        uint32_t n = 0;
        pfs::check(pf_get_particle_count(sim.get(), &n), "pf_get_particle_count");
        std::vector<float> xyz(3 * size_t(n));
        if (n > 0) pfs::check(pf_read_particles(sim.get(), 0, n, xyz.data(), nullptr), "pf_read_particles");
        uint32_t above = 0;
        for (uint32_t i = 0; i < n; ++i) above += xyz[3 * size_t(i) + 1] > opt.count_above ? 1 : 0;
        std::printf("particles above %.4g m: %u of %u\n", double(opt.count_above), above, n);
    }
    const double total_s = (pfs::now_ms() - t_start) / 1000.0;
    std::printf("total wall time %.2f s: simulation %.2f s, rendering %.2f s, PNG encoding %.2f s, %u images in %s\n",
                total_s, sim_total_ms / 1000.0, render_total_ms / 1000.0, png_total_ms / 1000.0, image_index,
                world ? opt.out.c_str() : "(none)");
    if (exporter.any()) {
        const double write_s = (exporter.ply_ms + exporter.vdb_ms) / 1000.0;
        std::printf("export: %u frames, %llu particles in all: read back %.2f s, PLY %.2f s, OpenVDB %.2f s "
                    "(%.3g particles/s written)\n",
                    exporter.frames_written, static_cast<unsigned long long>(exporter.particles_written),
                    exporter.readback_ms / 1000.0, exporter.ply_ms / 1000.0, exporter.vdb_ms / 1000.0,
                    write_s > 0 ? double(exporter.particles_written) / write_s : 0.0);
    }

    bool video_failed = false;
    if (!opt.video.empty() && image_index > 0) {
        const float fps = opt.fps > 0 ? opt.fps : 1.0f / (scene.frame_dt * float(opt.every));
        if (encode_video(opt.out, image_index, fps, opt.video))
            std::printf("video: %s (%u frames at %.3g fps)\n", opt.video.c_str(), image_index, double(fps));
        else
            video_failed = true;
    }

    // Tear down in order: our GL objects and the sim while the context is current; the context
    // goes last (it is declared first).
    world.reset();
    sim.reset();
    return video_failed ? 1 : 0;
}

} // namespace

int main(int argc, char** argv) { return pfs::run_tool("pf_headless", run, argc, argv); }
