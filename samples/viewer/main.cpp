// pf_viewer — interactive pflip viewer (GLFW window, Dear ImGui).
//
// The frame is built the way a game engine builds it: the sample's world (sky, floor, tank,
// crates; samples/common/world.h) is drawn with the sample's own GL loader into the sample's
// own framebuffer (colour + depth textures), pflip draws the liquid into that framebuffer
// (pf_render_ssf, or pf_render_particles for the debug view), the result is blitted to the
// window and ImGui goes on top.
//
// The simulation panel holds every pf_sim_params field, with the accuracy knobs (pressure
// solver, tolerance, iteration cap, SOR omega, transfer, advection) first; the statistics
// panel shows their price beside them: the runtime pass list (pf_get_pass_stats, so the active
// solver's own passes show), the solver's iterations and final residual, and rolling plots of
// GPU ms per step and log10 residual with a tick where a knob changed.
//
// The world draws the scene's obstacles at the poses the viewer last gave pflip (floating ones
// as they bob). The effects panel toggles each effect live (pf_set_features) and edits the
// obstacles' positions and the emitters' rates.
//
// Mouse: right drag (or Alt + left drag) orbits, middle drag (or Shift + right drag) pans,
// the wheel zooms. Left drag on an obstacle grabs it (the nearest one under the cursor; an SDF
// obstacle is picked by its box) and moves it in the camera-facing plane through the grabbed
// point, with the velocity of the drag so it pushes the liquid; a floating obstacle stops
// floating while held. Left drag anywhere else pushes the liquid (pf_push along the drag).
// Keys: Space pauses, S steps once, R resets the scene, P toggles SSF / particles, Esc quits.
//
// --screenshot PATH --frames N runs N frames, saves the window (UI included) to PATH (PNG, or
// JPEG for .jpg) and exits: scripted screenshots, and the CTest smoke test under xvfb-run.
// --drag and --drag-obstacle script a left drag (a push, an obstacle moved) for tests; at exit
// the viewer prints each obstacle's start and final pose.

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <pf/pf.h>

#include "camera.h"
#include "cli.h"
#include "gl_util.h"
#include "image_write.h"
#include "floating.h"
#include "obstacle_shapes.h"
#include "scene.h"
#include "util.h"
#include "world.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using pfs::Error;

// ---- command line ---------------------------------------------------------------------------

struct Options {
    std::string scene = "dam_break_small";
    pfs::Size size{1280, 720};
    bool ssf = true;
    pf_depth_convention depth = PF_DEPTH_STANDARD;
    std::string screenshot;
    uint32_t frames = 0;        // 0: run until closed (with --screenshot: default 60)
    bool paused = false;
    bool vsync = true;
    bool verbose = false;
    pfs::ParamOverrides overrides; // --preset, --solver, --tolerance, --transfer, --advection, --p2g, ...
    // --drag: a synthetic left drag (scripted pushes, tests)
    bool drag = false;
    float drag_from[2] = {0, 0}, drag_to[2] = {0, 0};
    uint32_t drag_first = 5, drag_last = 15;
    // --drag-obstacle: a synthetic left drag that starts on obstacle drag_obstacle's centre
    int drag_obstacle = -1;     // scene obstacle index; -1: none
    float drag_obstacle_by[2] = {0, 0};
};

/// A scripted drag's text: `count` values (named by `shape`, e.g. "X0,Y0,X1,Y1"), then
/// optionally the frames F0,F1 it spans (default 5..15). Throws CLI::ValidationError naming option.
void parse_scripted_drag(const std::string& v, const char* option, const char* shape, int count, float* values,
                         uint32_t& first, uint32_t& last) {
    float f[8] = {};
    int n = 0;
    for (size_t at = 0; n < 8 && at <= v.size(); ++n) {
        char* end = nullptr;
        f[n] = std::strtof(v.c_str() + at, &end);
        const size_t used = size_t(end - v.c_str());
        if (used == at || (used < v.size() && v[used] != ',')) {
            n = -1; // not a number, or not followed by a comma
            break;
        }
        at = used + 1;
    }
    float f0 = 5, f1 = 15;
    if (n == count + 2) {
        f0 = f[count];
        f1 = f[count + 1];
    }
    if ((n != count && n != count + 2) || f0 < 1 || f1 <= f0)
        throw CLI::ValidationError(option, std::string("expected ") + shape + " or " + shape +
                                               ",F0,F1 (F0 >= 1, F1 > F0), got '" + v + "'");
    std::copy(f, f + count, values);
    first = uint32_t(f0);
    last = uint32_t(f1);
}

void add_options(CLI::App& app, Options& o) {
    pfs::init_app(app);
    app.add_option("--scene", o.scene, "scene file, or a name in the scenes directory")
        ->type_name("PATH|NAME")
        ->capture_default_str();
    app.add_option("--size", o.size, "window size")
        ->check(pfs::SizeValidator())
        ->type_name("WxH")
        ->capture_default_str();
    app.add_option("--render", o.ssf, "start with pflip's screen-space fluid or its particles")
        ->transform(pfs::NameMap(pfs::render_choices(), "renderer"))
        ->type_name("NAME")
        ->default_str("ssf");
    app.add_option("--depth", o.depth, "camera depth convention")
        ->transform(pfs::NameMap(pfs::depth_choices(), "depth convention"))
        ->type_name("NAME")
        ->default_str("standard");
    app.add_flag("--paused", o.paused, "start paused");
    app.add_flag_callback("--no-vsync", [&o] { o.vsync = false; }, "do not wait for the display between frames");
    app.add_option("--screenshot", o.screenshot,
                   "after --frames frames save the window to PATH (.png, or .jpg) and exit")
        ->type_name("PATH");
    app.add_option("--frames", o.frames,
                   "frames to run before the screenshot, or before exiting (default 60 with --screenshot, otherwise "
                   "until the window closes)")
        ->check(pfs::Range(1u, 100000000u));
    app.add_option_function<std::string>(
           "--drag",
           [&o](const std::string& v) {
               float f[4];
               parse_scripted_drag(v, "--drag", "X0,Y0,X1,Y1", 4, f, o.drag_first, o.drag_last);
               o.drag = true;
               o.drag_from[0] = f[0];
               o.drag_from[1] = f[1];
               o.drag_to[0] = f[2];
               o.drag_to[1] = f[3];
           },
           "scripted left drag (a push) from window pixel X0,Y0 to X1,Y1 over frames F0..F1 (default 5..15)")
        ->type_name("X0,Y0,X1,Y1[,F0,F1]");
    app.add_option_function<std::string>(
           "--drag-obstacle",
           [&o](const std::string& v) {
               float f[3];
               parse_scripted_drag(v, "--drag-obstacle", "I,DX,DY", 3, f, o.drag_first, o.drag_last);
               if (f[0] < 0 || f[0] != std::floor(f[0]) || f[0] >= float(PF_MAX_OBSTACLES))
                   throw CLI::ValidationError("--drag-obstacle", "I must be an obstacle index, got '" + v + "'");
               o.drag_obstacle = int(f[0]);
               o.drag_obstacle_by[0] = f[1];
               o.drag_obstacle_by[1] = f[2];
           },
           "scripted left drag that grabs scene obstacle I at its centre (seen from the camera at frame F0) and "
           "moves the cursor by DX,DY window pixels over frames F0..F1; an error if the press grabs no obstacle "
           "or another one")
        ->type_name("I,DX,DY[,F0,F1]");
    pfs::add_param_overrides(app, o.overrides);
    app.add_flag("--verbose", o.verbose, "pflip's info messages");
    app.footer("mouse: right drag / Alt+left drag orbit, middle drag / Shift+right drag pan, wheel zoom,\n"
               "       left drag on an obstacle moves it, elsewhere pushes the liquid.\n"
               "keys: Space pause, S step, R reset, P SSF/particles, Esc quit\n"
               "scenes directory: " + pfs::scenes_dir() + " (PF_SCENES_DIR)");
    app.callback([&app, &o] {
        if (o.drag && o.drag_obstacle >= 0)
            throw CLI::ValidationError("--drag and --drag-obstacle both script the left button: give one");
        if (!o.screenshot.empty()) {
            if (app.count("--frames") == 0) o.frames = 60;
            o.vsync = false;
        }
    });
}

// ---- helpers --------------------------------------------------------------------------------

using pfs::SimPtr;

pf_gl_proc glfw_get_proc(const char* name) { return reinterpret_cast<pf_gl_proc>(glfwGetProcAddress(name)); }
GLADapiproc glad_get_proc(const char* name) { return reinterpret_cast<GLADapiproc>(glfwGetProcAddress(name)); }

/// Scene files (*.json) in the scenes directory, sorted.
std::vector<std::string> list_scenes() {
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(pfs::scenes_dir(), ec))
        if (e.is_regular_file() && e.path().extension() == ".json") out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

/// Ray / plane: distance or -1.
float ray_plane(const glm::vec3& o, const glm::vec3& d, const glm::vec3& p, const glm::vec3& n) {
    const float den = glm::dot(d, n);
    if (std::fabs(den) < 1e-6f) return -1.0f;
    const float t = glm::dot(p - o, n) / den;
    return t >= 0.0f ? t : -1.0f;
}

constexpr float kPanelWidth = 420.0f;  // the parameter panel, on the left
constexpr float kStatsWidth = 410.0f;  // the statistics panel, on the right: both stay in view,
                                       // so a knob's price shows while turning it

/// An error line, wrapped to the panel: the library's messages name the field and its range.
void error_text(const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 0.3f, 1));
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

/// Hover help for the previous widget (ImGui 1.86 has no SetItemTooltip).
void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

// ---- pflip's messages -----------------------------------------------------------------------

/// Forwards pflip's messages to the samples' stderr logger and keeps the newest error or
/// warning, so the panel can show the library's own words (which field, which range) next to
/// a refused change instead of a bare result code.
class LogCapture {
public:
    explicit LogCapture(bool verbose) : forward_(pfs::stderr_logger(verbose)) {}
    pf_logger logger() { return pf_logger{&LogCapture::log, this}; }
    /// Forgets the kept message (before a call whose failure is to be explained).
    void clear() { last_.clear(); }
    /// What to show when `call` returned r: the logged message, else the result code.
    std::string explain(const char* call, pf_result r) const {
        return last_.empty() ? std::string(call) + ": " + pf_result_string(r) : last_;
    }

private:
    static void log(void* user, pf_log_level level, pf_result code, const char* message) {
        auto* self = static_cast<LogCapture*>(user);
        if (self->forward_.fn) self->forward_.fn(self->forward_.user, level, code, message);
        if (level == PF_LOG_ERROR || level == PF_LOG_WARNING) self->last_ = message ? message : "";
    }
    pf_logger forward_;
    std::string last_;
};

// ---- parameter presets ----------------------------------------------------------------------

/// A named starting point for every simulation parameter.
struct ParamPreset {
    const char* name;
    const char* help;
    pf_sim_params (*make)(const pfs::Scene& scene);
};

/// The presets of the simulation panel's combo, in order: the scene's own values, the library's
/// defaults, and the library's quality presets (pf_quality_params over the scene's values).
const std::vector<ParamPreset>& param_presets() {
    static const std::vector<ParamPreset> presets = {
        {"scene file", "the scene file's values (with the command line's --solver/--tolerance/--transfer/--advection)",
         [](const pfs::Scene& scene) { return scene.params; }},
        {"library defaults", "pf_default_sim_params()", [](const pfs::Scene&) { return pf_default_sim_params(); }},
        {"fast", "PF_QUALITY_FAST: MGPCG to 1e-2, FLIP, Euler (docs/accuracy.md)",
         [](const pfs::Scene& scene) {
             pf_sim_params p = scene.params;
             pfs::apply_preset(PF_QUALITY_FAST, p);
             return p;
         }},
        {"balanced", "PF_QUALITY_BALANCED (the library default): MGPCG to 1e-3, separation off",
         [](const pfs::Scene& scene) {
             pf_sim_params p = scene.params;
             pfs::apply_preset(PF_QUALITY_BALANCED, p);
             return p;
         }},
        {"accurate", "PF_QUALITY_ACCURATE: MGPCG to 1e-5 with separation, APIC",
         [](const pfs::Scene& scene) {
             pf_sim_params p = scene.params;
             pfs::apply_preset(PF_QUALITY_ACCURATE, p);
             return p;
         }},
    };
    return presets;
}

/// Display names of the enums the combos select (pfs::*_name gives the command-line names).
const char* const kSolverLabels[] = {"Jacobi", "red-black GS / SOR", "CG", "PCG (Jacobi)", "MGPCG (multigrid)",
                                     "MGPCG (Galerkin multigrid)"};
static_assert(sizeof(kSolverLabels) / sizeof(kSolverLabels[0]) == PF_PRESSURE_SOLVER_COUNT, "a label for every solver");
const char* const kTransferLabels[PF_TRANSFER_COUNT] = {"PIC/FLIP", "APIC"};
const char* const kAdvectionLabels[PF_ADVECTION_COUNT] = {"Euler", "RK2 (midpoint)", "RK3 (Ralston)", "Leapfrog", "RK2 + own velocity"};

/// One measured step in the rolling plots.
struct StepSample {
    float gpu_ms = 0;        // pf_stats.gpu_total_ms
    float log_residual = 0;  // log10 pf_stats.solver_residual
    bool knob = false;       // the first measured step after a parameter change
};
constexpr size_t kHistorySteps = 240;

/// PlotLines over the whole width with a tick at every sample where a knob changed and, when
/// ref is within [lo, hi], a horizontal line at ref: a knob's price shows as a step in the
/// curve right after its tick.
void plot_history(const char* id, const std::vector<float>& v, const std::vector<bool>& knob, float lo, float hi,
                  const std::string& overlay, float ref) {
    const ImVec2 size(ImGui::GetContentRegionAvail().x, 48); // 1.86: no negative sizes here
    ImGui::PlotLines(id, v.data(), int(v.size()), 0, overlay.c_str(), lo, hi, size);
    if (v.size() < 2) return;
    const ImVec2 pad = ImGui::GetStyle().FramePadding;
    const ImVec2 a(ImGui::GetItemRectMin().x + pad.x, ImGui::GetItemRectMin().y + pad.y);
    const ImVec2 b(ImGui::GetItemRectMax().x - pad.x, ImGui::GetItemRectMax().y - pad.y);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    for (size_t i = 0; i < knob.size(); ++i) {
        if (!knob[i]) continue;
        const float x = a.x + (b.x - a.x) * float(i) / float(v.size() - 1);
        dl->AddLine(ImVec2(x, a.y), ImVec2(x, b.y), IM_COL32(255, 220, 80, 200), 1.0f);
    }
    if (ref >= lo && ref <= hi && hi > lo) {
        const float y = b.y - (b.y - a.y) * (ref - lo) / (hi - lo);
        dl->AddLine(ImVec2(a.x, y), ImVec2(b.x, y), IM_COL32(120, 220, 120, 160), 1.0f);
    }
}

// ---- the application ------------------------------------------------------------------------

class Viewer {
public:
    Viewer(const Options& opt, GLFWwindow* window) : opt_(opt), window_(window), log_(opt.verbose) {
        look_.ssf = opt.ssf;
        camera_depth_ = opt.depth;
        paused_ = opt.paused;
        scene_files_ = list_scenes();
        load_scene(pfs::resolve_scene_path(opt.scene));
    }

    ~Viewer() {
        world_.reset();
        sim_.reset();
    }

    bool frame(uint64_t frame_index);
    /// Each scene obstacle's pose at load and now, and where its centre is on screen: the
    /// scripted drag's outcome, for tests.
    void print_obstacles() const;
    /// The error the panel shows now (empty if none).
    const std::string& last_error() const { return last_error_; }

private:
    void load_scene(const std::string& path);
    void reset_scene();
    void handle_mouse(int fb_w, int fb_h, uint64_t frame_index);
    void begin_push(double x, double y, int fb_w, int fb_h);
    bool scripted_cursor(uint64_t frame_index, double& x, double& y);
    pf_obstacle obstacle_pose(size_t i) const;
    std::vector<pf_obstacle> obstacle_poses() const;
    pf_result place_obstacle(size_t i, const pf_obstacle& o);
    bool begin_obstacle_drag(double x, double y);
    // The camera ray through cursor position (x, y) in window coordinates.
    void cursor_ray(double x, double y, glm::vec3& origin, glm::vec3& dir) const;
    void move_grabbed_obstacle(double x, double y);
    void release_obstacle();
    void check_scripted_grab() const;
    void ui(int fb_w, int fb_h);
    void ui_scene();
    void ui_simulation();
    bool ui_presets(pf_sim_params& p);
    bool ui_accuracy_knobs(pf_sim_params& p);
    bool ui_other_params(pf_sim_params& p);
    void apply_params(const pf_sim_params& p);
    void ui_effects();
    void ui_rendering();
    void ui_stats();
    void ui_history();
    void ui_pass_table();
    void ui_accuracy();
    void ui_render_pass_table();
    void record_step();
    void draw_push_marker(int fb_w, int fb_h);

    const Options& opt_;
    GLFWwindow* window_;
    LogCapture log_; // before sim_: the sim logs into it until destroyed
    pfs::Scene scene_;
    pfs::SceneEffectIds effect_ids_;    // the library's ids of scene_'s objects
    pfs::FloatingBodies floating_;      // scene_'s floating obstacles
    pfs::DrivenObstacles driven_;       // scene_'s driven obstacles (the drag does not hold them)
    std::string effects_error_;         // why the last effects edit was refused
    std::string scene_path_;
    std::vector<std::string> scene_files_;
    SimPtr sim_;
    std::unique_ptr<pfs::World> world_;
    pfs::OrbitCamera camera_;
    pf_depth_convention camera_depth_ = PF_DEPTH_STANDARD;
    pfs::LiquidLook look_;
    pf_sim_params params_{};
    pf_stats stats_{};
    std::vector<pf_pass_stats> passes_; // the runtime pass list, read every frame
    std::string last_error_;
    std::string params_error_;          // why the last pf_set_params was refused
    int preset_ = 0;                    // param_presets() index applied last; -1: edited since
    bool show_idle_passes_ = false;

    // rolling plots: one sample per measured step (GPU figures lag a few steps)
    std::deque<StepSample> history_;
    uint64_t last_sampled_step_ = 0;
    bool knob_pending_ = false;         // a parameter changed; mark the first step measured after it
    uint64_t knob_step_ = 0;            // pf_stats.steps when it changed

    bool paused_ = false, step_once_ = false;
    int steps_per_frame_ = 1;

    // mouse
    enum class Drag { none, orbit, pan, push, obstacle } drag_ = Drag::none;
    double last_x_ = 0, last_y_ = 0;
    glm::vec3 grab_point_{0.0f}, grab_normal_{0.0f, 0.0f, 1.0f};
    glm::vec3 push_center_{0.0f}, push_dv_{0.0f};
    bool push_active_ = false;
    float push_radius_frac_ = 0.12f;  // of the largest tank extent
    float push_gain_ = 0.5f;
    float push_max_dv_ = 2.0f;         // m/s added per frame of dragging
    size_t grabbed_ = 0;               // scene obstacle index while drag_ == Drag::obstacle
    glm::vec3 grab_offset_{0.0f};      // obstacle centre - grabbed surface point
    std::vector<pf_obstacle> start_poses_; // scene_'s obstacles as loaded
    glm::vec2 scripted_from_{0.0f};    // --drag-obstacle: the cursor's start (obstacle centre)

    // keys (ImGui 1.86 has no named letter keys): pressed = down now, up last frame
    std::map<int, bool> key_down_;
    bool key_pressed(int key) { return glfwGetKey(window_, key) == GLFW_PRESS && !key_down_[key]; }

    // timing
    std::deque<float> frame_ms_;
    double last_frame_time_ = 0;
    double step_wall_ms_ = 0;
};

void Viewer::load_scene(const std::string& path) {
    pfs::Scene s = pfs::load_scene(path); // throws before anything is torn down
    // The command line's knobs count as part of every scene, so "scene file" keeps them.
    opt_.overrides.apply(s.params);
    world_.reset();
    sim_.reset();
    scene_ = std::move(s);
    scene_path_ = path;
    sim_.reset(pfs::create_scene_sim(scene_, glfw_get_proc, log_.logger(), &effect_ids_));
    effects_error_.clear();
    floating_ = pfs::FloatingBodies{};
    pfs::float_scene_obstacles(scene_, effect_ids_, floating_);
    driven_ = pfs::DrivenObstacles{};
    pfs::drive_scene_obstacles(scene_, effect_ids_, driven_);
    // From here scene_.obstacles are the viewer's poses as the library holds them (SDF ones
    // with their textures, which pf_set_obstacle needs again).
    scene_.obstacles = pfs::obstacles_as_added(scene_, effect_ids_);
    start_poses_ = scene_.obstacles;
    drag_ = Drag::none;
    pfs::check(pf_get_params(sim_.get(), &params_), "pf_get_params");
    preset_ = 0;
    params_error_.clear();
    history_.clear(); // a new sim counts steps from 0
    last_sampled_step_ = 0;
    knob_pending_ = false;
    world_ = std::make_unique<pfs::World>(scene_, glad_get_proc);
    world_->set_sun(glm::vec3(look_.ssf_params.light_direction[0], look_.ssf_params.light_direction[1],
                              look_.ssf_params.light_direction[2]));
    camera_.set_from_scene(scene_.has_camera ? scene_.camera : scene_.default_camera());
    if (camera_depth_ != PF_DEPTH_STANDARD && !world_->has_clip_control()) {
        std::fprintf(stderr, "pf_viewer: no glClipControl on this context; using the standard depth convention\n");
        camera_depth_ = PF_DEPTH_STANDARD;
    }
    camera_.depth = camera_depth_;
    // Centre the tank between the two panels and step back so it fits there.
    {
        int win_w = 0, win_h = 0;
        glfwGetWindowSize(window_, &win_w, &win_h);
        camera_.pan(0.5f * (kPanelWidth - kStatsWidth), 0.0f, std::max(win_h, 1));
        camera_.zoom(1.6f);
    }
    // Particle colours: the speed range of a tank-deep dam break.
    const pfs::vec3f lo = scene_.domain_min(), hi = scene_.domain_max();
    look_.particle_params.range[1] = std::max(0.5f, 0.8f * std::sqrt(9.81f * (hi[1] - lo[1])));
    last_error_.clear();
}

void Viewer::reset_scene() {
    pfs::check(pf_clear_particles(sim_.get()), "pf_clear_particles");
    pfs::fill_scene(sim_.get(), scene_);
    pfs::check(pf_clear_flags(sim_.get()), "pf_clear_flags");
}

// Left press: find where the ray meets the liquid (particles read back once per press: the
// nearest one close to the ray, else the particles' bounding box) or else the tank's vertical
// mid-plane facing the camera; the drag then moves along the camera-facing plane through that
// point, and every frame of movement calls pf_push there with dv along the drag.
void Viewer::cursor_ray(double x, double y, glm::vec3& origin, glm::vec3& dir) const {
    int win_w = 0, win_h = 0;
    glfwGetWindowSize(window_, &win_w, &win_h);
    camera_.ray(x, y, win_w, win_h, origin, dir);
}

void Viewer::begin_push(double x, double y, int fb_w, int fb_h) {
    glm::vec3 o, d;
    cursor_ray(x, y, o, d);
    (void)fb_w;
    (void)fb_h;
    const glm::vec3 tlo = world_->tank_min(), thi = world_->tank_max();
    float t = -1.0f;
    pf_stats st{};
    pf_get_stats(sim_.get(), &st);
    if (st.particle_count > 0) {
        std::vector<float> xyz(size_t(st.particle_count) * 3);
        if (pf_read_particles(sim_.get(), 0, st.particle_count, xyz.data(), nullptr) == PF_OK) {
            // Nearest particle within two cells of the ray: the liquid surface under the cursor.
            // Else the ray's entry into the particles' bounding box.
            const float pick = 2.0f * scene_.cell_size;
            glm::vec3 lo(1e30f), hi(-1e30f);
            float best = 1e30f;
            for (size_t i = 0; i < xyz.size(); i += 3) {
                const glm::vec3 p(xyz[i], xyz[i + 1], xyz[i + 2]);
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
                const glm::vec3 op = p - o;
                const float tp = glm::dot(op, d);
                if (tp > 0 && tp < best && glm::dot(op, op) - tp * tp < pick * pick) best = tp;
            }
            float enter = -1.0f, exit = -1.0f;
            t = best < 1e30f ? best : (pfs::ray_box_span(o, d, lo, hi, enter, exit) ? enter : -1.0f);
        }
    }
    if (t < 0) {
        glm::vec3 n = camera_.forward();
        n.y = 0;
        n = glm::length(n) > 1e-4f ? glm::normalize(n) : glm::vec3(0, 0, 1);
        t = ray_plane(o, d, 0.5f * (tlo + thi), n);
    }
    if (t < 0) return;
    grab_point_ = glm::clamp(o + t * d, tlo, thi);
    grab_normal_ = camera_.forward();
    drag_ = Drag::push;
}

// --drag / --drag-obstacle: during frames F0..F1 the cursor moves linearly from its start to its
// end with the left button held. --drag-obstacle starts on the obstacle's centre as seen at F0.
bool Viewer::scripted_cursor(uint64_t frame_index, double& x, double& y) {
    const bool scripting = opt_.drag || opt_.drag_obstacle >= 0;
    if (!scripting || frame_index < opt_.drag_first || frame_index > opt_.drag_last) return false;
    glm::vec2 from(opt_.drag_from[0], opt_.drag_from[1]), to(opt_.drag_to[0], opt_.drag_to[1]);
    if (opt_.drag_obstacle >= 0) {
        if (frame_index == opt_.drag_first) {
            const size_t i = size_t(opt_.drag_obstacle);
            if (i >= scene_.obstacles.size())
                throw Error("--drag-obstacle: scene " + scene_.name + " has " + std::to_string(scene_.obstacles.size()) +
                            " obstacles, no obstacle " + std::to_string(i));
            int win_w = 0, win_h = 0;
            glfwGetWindowSize(window_, &win_w, &win_h);
            const pf_obstacle o = obstacle_pose(i);
            float depth = 0.0f;
            if (!camera_.window_position(glm::vec3(o.position[0], o.position[1], o.position[2]), win_w, win_h,
                                         scripted_from_, depth))
                throw Error("--drag-obstacle: obstacle " + std::to_string(i) + " is behind the camera");
        }
        from = scripted_from_;
        to = from + glm::vec2(opt_.drag_obstacle_by[0], opt_.drag_obstacle_by[1]);
    }
    const double t = double(frame_index - opt_.drag_first) / double(opt_.drag_last - opt_.drag_first);
    x = from.x + t * (to.x - from.x);
    y = from.y + t * (to.y - from.y);
    return true;
}

// The scripted obstacle drag must have grabbed the obstacle it names: otherwise it would push
// the liquid and a test of the obstacle's motion would measure nothing.
void Viewer::check_scripted_grab() const {
    if (opt_.drag_obstacle < 0) return;
    if (drag_ != Drag::obstacle)
        throw Error("--drag-obstacle: the press at window " + std::to_string(scripted_from_.x) + "," +
                    std::to_string(scripted_from_.y) + " grabbed no obstacle");
    if (grabbed_ != size_t(opt_.drag_obstacle))
        throw Error("--drag-obstacle: the press grabbed obstacle " + std::to_string(grabbed_) + ", not " +
                    std::to_string(opt_.drag_obstacle) + " (another one is in front of it)");
}

pf_obstacle Viewer::obstacle_pose(size_t i) const { return obstacle_poses()[i]; }

std::vector<pf_obstacle> Viewer::obstacle_poses() const {
    return driven_.poses(floating_.poses(scene_.obstacles, effect_ids_.obstacles), effect_ids_.obstacles);
}

// One place moves an obstacle: the library's, then (if it took it) the viewer's copy (what the
// world draws) and the floating body's state (so it goes on from there).
pf_result Viewer::place_obstacle(size_t i, const pf_obstacle& o) {
    const pf_result r = pf_set_obstacle(sim_.get(), effect_ids_.obstacles[i], &o);
    if (r != PF_OK) return r;
    scene_.obstacles[i] = o;
    floating_.set_pose(effect_ids_.obstacles[i], o);
    return PF_OK;
}

// Left press: the nearest obstacle whose shape the cursor's ray meets is grabbed at the hit
// point; the drag then moves that point in the camera-facing plane through it.
bool Viewer::begin_obstacle_drag(double x, double y) {
    glm::vec3 o, d;
    cursor_ray(x, y, o, d);
    const std::vector<pf_obstacle> poses = obstacle_poses();
    float best = -1.0f;
    for (size_t i = 0; i < poses.size() && i < effect_ids_.obstacles.size(); ++i) {
        const float t = pfs::ray_obstacle(o, d, poses[i]);
        if (t >= 0.0f && (best < 0.0f || t < best)) {
            best = t;
            grabbed_ = i;
        }
    }
    if (best < 0.0f) return false;
    const pf_obstacle& g = poses[grabbed_];
    grab_point_ = o + best * d;
    grab_normal_ = camera_.forward();
    grab_offset_ = glm::vec3(g.position[0], g.position[1], g.position[2]) - grab_point_;
    floating_.set_held(effect_ids_.obstacles[grabbed_], true);
    drag_ = Drag::obstacle;
    return true;
}

// The grabbed point follows the cursor; the obstacle's velocity is its displacement over the
// simulated time this frame advances (steps x frame_dt), which is how fast the liquid sees its
// faces move. Paused, no time passes: it moves at rest.
void Viewer::move_grabbed_obstacle(double x, double y) {
    glm::vec3 o, d;
    cursor_ray(x, y, o, d);
    const float t = ray_plane(o, d, grab_point_, grab_normal_);
    if (t < 0) return;
    grab_point_ = o + t * d;
    pf_obstacle ob = obstacle_pose(grabbed_);
    const glm::vec3 old_centre(ob.position[0], ob.position[1], ob.position[2]);
    const glm::vec3 centre = grab_point_ + grab_offset_;
    const bool simulating = !paused_ || step_once_;
    const float sim_dt = simulating ? scene_.frame_dt * float(steps_per_frame_) : 0.0f;
    const glm::vec3 velocity = sim_dt > 0.0f ? (centre - old_centre) / sim_dt : glm::vec3(0.0f);
    for (int a = 0; a < 3; ++a) {
        ob.position[a] = centre[a];
        ob.velocity[a] = velocity[a];
    }
    if (pf_result r = place_obstacle(grabbed_, ob); r != PF_OK) last_error_ = log_.explain("pf_set_obstacle", r);
}

// Let go: the obstacle stops where it is (a floating one falls or floats from rest).
void Viewer::release_obstacle() {
    pf_obstacle ob = obstacle_pose(grabbed_);
    std::fill(ob.velocity, ob.velocity + 3, 0.0f);
    if (pf_result r = place_obstacle(grabbed_, ob); r != PF_OK) last_error_ = log_.explain("pf_set_obstacle", r);
    floating_.set_held(effect_ids_.obstacles[grabbed_], false);
}

void Viewer::print_obstacles() const {
    int win_w = 0, win_h = 0;
    glfwGetWindowSize(window_, &win_w, &win_h);
    const std::vector<pf_obstacle> now = obstacle_poses();
    for (size_t i = 0; i < now.size() && i < start_poses_.size(); ++i) {
        const pf_obstacle& a = start_poses_[i];
        const pf_obstacle& b = now[i];
        const glm::vec3 pa(a.position[0], a.position[1], a.position[2]), pb(b.position[0], b.position[1], b.position[2]);
        glm::vec2 sa(0.0f), sb(0.0f);
        float da = 0.0f, db = 0.0f;
        const bool visible = camera_.window_position(pa, win_w, win_h, sa, da) && camera_.window_position(pb, win_w, win_h, sb, db);
        std::printf("obstacle %zu: start %.4f %.4f %.4f  final %.4f %.4f %.4f  velocity %.4f %.4f %.4f  moved %.4f m",
                    i, double(pa.x), double(pa.y), double(pa.z), double(pb.x), double(pb.y), double(pb.z),
                    double(b.velocity[0]), double(b.velocity[1]), double(b.velocity[2]), double(glm::length(pb - pa)));
        if (visible)
            std::printf("  window %.0f,%.0f -> %.0f,%.0f  view depth %.3f -> %.3f m\n", double(sa.x), double(sa.y),
                        double(sb.x), double(sb.y), double(da), double(db));
        else
            std::printf("  (behind the camera)\n");
    }
}

void Viewer::handle_mouse(int fb_w, int fb_h, uint64_t frame_index) {
    ImGuiIO& io = ImGui::GetIO();
    double x = 0, y = 0;
    glfwGetCursorPos(window_, &x, &y);
    bool left = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    const bool scripted = scripted_cursor(frame_index, x, y);
    if (scripted) left = true;
    const bool right = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    const bool middle = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
    const bool alt = glfwGetKey(window_, GLFW_KEY_LEFT_ALT) == GLFW_PRESS || glfwGetKey(window_, GLFW_KEY_RIGHT_ALT) == GLFW_PRESS;
    const bool shift =
        glfwGetKey(window_, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(window_, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    push_active_ = false;
    const double dx = x - last_x_, dy = y - last_y_;

    if (drag_ == Drag::none && (scripted || !io.WantCaptureMouse)) {
        if ((left && alt) || (right && !shift)) drag_ = Drag::orbit;
        else if (middle || (right && shift)) drag_ = Drag::pan;
        else if (left && !begin_obstacle_drag(x, y)) begin_push(x, y, fb_w, fb_h);
        if (scripted && frame_index == opt_.drag_first) check_scripted_grab();
    }
    if (drag_ == Drag::obstacle && !left) release_obstacle();
    if ((drag_ == Drag::orbit && !(left || right)) || (drag_ == Drag::pan && !(middle || right)) ||
        ((drag_ == Drag::push || drag_ == Drag::obstacle) && !left))
        drag_ = Drag::none;

    int win_w = 0, win_h = 0;
    glfwGetWindowSize(window_, &win_w, &win_h);
    switch (drag_) {
    case Drag::orbit: camera_.orbit(float(dx), float(dy)); break;
    case Drag::pan: camera_.pan(float(dx), float(dy), win_h); break;
    case Drag::obstacle: move_grabbed_obstacle(x, y); break;
    case Drag::push: {
        glm::vec3 o, d;
        cursor_ray(x, y, o, d);
        const float t = ray_plane(o, d, grab_point_, grab_normal_);
        if (t < 0) break;
        const glm::vec3 p = o + t * d;
        const glm::vec3 delta = p - grab_point_;
        const glm::vec3 tlo = world_->tank_min(), thi = world_->tank_max();
        const glm::vec3 ext = thi - tlo;
        const float radius = push_radius_frac_ * std::max({ext.x, ext.y, ext.z});
        push_center_ = glm::clamp(p, tlo, thi);
        push_active_ = true;
        if (glm::length(delta) > 1e-6f) {
            // The drag speed in world metres per simulated frame, as a velocity change.
            glm::vec3 dv = delta / std::max(scene_.frame_dt, 1e-4f) * push_gain_;
            const float len = glm::length(dv);
            if (len > push_max_dv_) dv *= push_max_dv_ / len;
            push_dv_ = dv;
            const float c[3] = {push_center_.x, push_center_.y, push_center_.z};
            const float v[3] = {dv.x, dv.y, dv.z};
            const pf_result r = pf_push(sim_.get(), c, radius, v);
            if (r != PF_OK) last_error_ = std::string("pf_push: ") + pf_result_string(r);
            grab_point_ = p;
        }
        break;
    }
    default: break;
    }
    if (!io.WantCaptureMouse && io.MouseWheel != 0.0f) camera_.zoom(std::pow(0.9f, io.MouseWheel));
    last_x_ = x;
    last_y_ = y;

    if (!io.WantCaptureKeyboard) {
        if (key_pressed(GLFW_KEY_SPACE)) paused_ = !paused_;
        if (key_pressed(GLFW_KEY_S)) step_once_ = true;
        if (key_pressed(GLFW_KEY_R)) reset_scene();
        if (key_pressed(GLFW_KEY_P)) look_.ssf = !look_.ssf;
        if (key_pressed(GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(window_, 1);
    }
    for (int k : {GLFW_KEY_SPACE, GLFW_KEY_S, GLFW_KEY_R, GLFW_KEY_P, GLFW_KEY_ESCAPE})
        key_down_[k] = glfwGetKey(window_, k) == GLFW_PRESS;
}

void Viewer::draw_push_marker(int fb_w, int fb_h) {
    if (!push_active_) return;
    int win_w = 0, win_h = 0;
    glfwGetWindowSize(window_, &win_w, &win_h);
    const glm::mat4 vp = camera_.proj(float(fb_w) / float(std::max(fb_h, 1))) * camera_.view();
    const glm::vec3 tlo = world_->tank_min(), thi = world_->tank_max();
    const glm::vec3 ext = thi - tlo;
    const float radius = push_radius_frac_ * std::max({ext.x, ext.y, ext.z});
    auto to_screen = [&](const glm::vec3& p, ImVec2& s) {
        const glm::vec4 c = vp * glm::vec4(p, 1.0f);
        if (c.w <= 0) return false;
        s = ImVec2(float((c.x / c.w * 0.5 + 0.5) * win_w), float((0.5 - c.y / c.w * 0.5) * win_h));
        return true;
    };
    ImVec2 c, e, a;
    if (!to_screen(push_center_, c) || !to_screen(push_center_ + camera_.right() * radius, e)) return;
    const float r = std::hypot(e.x - c.x, e.y - c.y);
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    dl->AddCircle(c, r, IM_COL32(255, 220, 80, 200), 48, 2.0f);
    const float len = glm::length(push_dv_);
    if (len > 1e-4f && to_screen(push_center_ + push_dv_ / push_max_dv_ * radius * 1.5f, a))
        dl->AddLine(c, a, IM_COL32(255, 220, 80, 230), 2.0f);
}

bool Viewer::frame(uint64_t frame_index) {
    const double now = pfs::now_ms();
    if (last_frame_time_ > 0) {
        frame_ms_.push_back(float(now - last_frame_time_));
        if (frame_ms_.size() > 120) frame_ms_.pop_front();
    }
    last_frame_time_ = now;

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();

    int fb_w = 0, fb_h = 0;
    glfwGetFramebufferSize(window_, &fb_w, &fb_h);
    if (fb_w < 1 || fb_h < 1) { // minimised
        ImGui::Render();
        return true;
    }
    handle_mouse(fb_w, fb_h, frame_index);

    // Simulate.
    if (!paused_ || step_once_) {
        const double s0 = pfs::now_ms();
        for (int i = 0; i < steps_per_frame_; ++i) {
            if (pf_result f = floating_.step(sim_.get(), scene_.frame_dt, params_.gravity); f != PF_OK)
                last_error_ = log_.explain("floating obstacles", f);
            if (pf_result f = driven_.step(sim_.get(), scene_.frame_dt); f != PF_OK)
                last_error_ = log_.explain("driven obstacles", f);
            const pf_result r = pf_step(sim_.get(), scene_.frame_dt);
            if (r != PF_OK) {
                last_error_ = std::string("pf_step: ") + pf_result_string(r);
                paused_ = true;
                break;
            }
        }
        step_wall_ms_ = pfs::now_ms() - s0;
        step_once_ = false;
    }
    stats_.struct_size = sizeof stats_;  // this header's layout (0 would be the first one)
    pf_get_stats(sim_.get(), &stats_);
    pfs::get_pass_list(sim_.get(), passes_);
    record_step();

    // Render: world, then the liquid into the world's framebuffer, then to the window.
    world_->resize(fb_w, fb_h);
    world_->fit_clip_planes(camera_);
    camera_.depth = camera_depth_;
    world_->set_obstacles(obstacle_poses());
    const pf_result r = pfs::draw_frame(*world_, sim_.get(), camera_, look_);
    if (r != PF_OK) last_error_ = std::string(look_.ssf ? "pf_render_ssf: " : "pf_render_particles: ") + pf_result_string(r);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, world_->framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, fb_w, fb_h, 0, 0, fb_w, fb_h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    draw_push_marker(fb_w, fb_h);
    ui(fb_w, fb_h);
    ImGui::Render();
    glViewport(0, 0, fb_w, fb_h);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    return true;
}

// ---- UI -------------------------------------------------------------------------------------

void Viewer::ui(int fb_w, int fb_h) {
    (void)fb_w;
    (void)fb_h;
    const ImVec2 display = ImGui::GetIO().DisplaySize; // window coordinates, not framebuffer pixels
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, std::max(200.0f, display.y - 16)), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.82f);
    ImGui::Begin("pflip");
    ImGui::PushItemWidth(-150.0f); // room for the longest label ("extrapolation layers")
    ImGui::Text("pflip %s  |  %s", pfs::pf_version_string().c_str(), reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
    if (!last_error_.empty()) error_text(last_error_);
    ui_scene();
    ui_simulation();
    ui_effects();
    ui_rendering();
    ImGui::PopItemWidth();
    ImGui::End();

    // Fixed width, height following the content: the pass list grows with the solvers used.
    ImGui::SetNextWindowPos(ImVec2(std::max(kPanelWidth + 16, display.x - kStatsWidth - 8), 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(kStatsWidth, 0), ImVec2(kStatsWidth, std::max(200.0f, display.y - 16)));
    ImGui::SetNextWindowBgAlpha(0.82f);
    ImGui::Begin("statistics", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ui_stats();
    ImGui::End();
}

void Viewer::ui_scene() {
    if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const std::string current = std::filesystem::path(scene_path_).stem().string();
    if (ImGui::BeginCombo("scene", current.c_str())) {
        for (const auto& f : scene_files_) {
            const std::string name = std::filesystem::path(f).stem().string();
            if (ImGui::Selectable(name.c_str(), f == scene_path_)) {
                try {
                    load_scene(f);
                } catch (const std::exception& e) {
                    last_error_ = e.what();
                }
            }
        }
        ImGui::EndCombo();
    }
    if (ImGui::Button("Reload file")) {
        try {
            load_scene(scene_path_);
        } catch (const std::exception& e) {
            last_error_ = e.what();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Reset (R)")) reset_scene();
    ImGui::SameLine();
    ImGui::Checkbox("Pause (Space)", &paused_);
    ImGui::SameLine();
    if (ImGui::Button("Step (S)")) step_once_ = true;
    ImGui::SliderInt("steps / frame", &steps_per_frame_, 1, 8);
    ImGui::TextDisabled("%s", scene_.description.c_str());
    ImGui::TextDisabled("grid %ux%ux%u, cell %.4g m, dt %.4g s", scene_.grid_size[0], scene_.grid_size[1],
                        scene_.grid_size[2], double(scene_.cell_size), double(scene_.frame_dt));
    if (ImGui::TreeNode("Push (left drag off the obstacles)")) {
        ImGui::SliderFloat("radius (of tank)", &push_radius_frac_, 0.02f, 0.5f, "%.2f");
        ImGui::SliderFloat("gain", &push_gain_, 0.05f, 4.0f, "%.2f");
        ImGui::SliderFloat("max dv m/s", &push_max_dv_, 0.1f, 20.0f, "%.1f");
        ImGui::TreePop();
    }
}

void Viewer::ui_simulation() {
    if (!ImGui::CollapsingHeader("Simulation parameters", ImGuiTreeNodeFlags_DefaultOpen)) return;
    pf_sim_params p = params_;
    if (ui_presets(p)) {
        apply_params(p);
        return;
    }
    bool changed = ui_accuracy_knobs(p);
    changed |= ui_other_params(p);
    if (changed) {
        preset_ = -1;
        apply_params(p);
    }
    if (!params_error_.empty()) error_text(params_error_);
}

// The preset combo: replaces every parameter at once.
bool Viewer::ui_presets(pf_sim_params& p) {
    const auto& presets = param_presets();
    const char* current = preset_ >= 0 && size_t(preset_) < presets.size() ? presets[size_t(preset_)].name : "(edited)";
    bool picked = false;
    if (ImGui::BeginCombo("preset", current)) {
        for (size_t i = 0; i < presets.size(); ++i) {
            if (ImGui::Selectable(presets[i].name, int(i) == preset_)) {
                p = presets[i].make(scene_);
                preset_ = int(i);
                picked = true;
            }
            tooltip(presets[i].help);
        }
        ImGui::EndCombo();
    }
    tooltip("every simulation parameter at once; moving a knob below makes it \"(edited)\"");
    return picked;
}

// What the pressure solve, the transfers and the integrator cost and buy: the knobs whose
// price the statistics below show.
bool Viewer::ui_accuracy_knobs(pf_sim_params& p) {
    bool changed = false;
    int solver = int(p.pressure_solver);
    if (ImGui::Combo("pressure solver", &solver, kSolverLabels, PF_PRESSURE_SOLVER_COUNT)) {
        p.pressure_solver = pf_pressure_solver(solver);
        changed = true;
    }
    tooltip("cheapest per iteration first; CG, PCG and MGPCG need far fewer iterations (docs/accuracy.md)");
    changed |= ImGui::SliderFloat("tolerance", &p.pressure_tolerance, 1e-7f, 1e-1f, "%.1e", ImGuiSliderFlags_Logarithmic);
    tooltip("relative residual |b - Ap| / |b| at which a solve stops (checked on the GPU)");
    int iters = int(p.pressure_iterations);
    if (ImGui::SliderInt("iteration cap", &iters, 1, 10000, "%d", ImGuiSliderFlags_Logarithmic)) {
        p.pressure_iterations = uint32_t(iters);
        changed = true;
    }
    tooltip("most iterations per substep (a Jacobi sweep, a red-black pair, a CG step) when the tolerance is not met");
    changed |= ImGui::SliderFloat("SOR omega (RBGS)", &p.sor_omega, 0.05f, 1.99f, "%.3f");
    tooltip("over-relaxation of the red-black Gauss-Seidel solver only; the other solvers ignore it");
    changed |= ImGui::SliderFloat("Jacobi omega", &p.jacobi_omega, 0.05f, 1.0f, "%.3f");
    tooltip("relaxation weight of the Jacobi solver only");
    bool separation = p.separation != 0;
    if (ImGui::Checkbox("separation (pressure >= 0)", &separation)) {
        p.separation = separation ? 1u : 0u;
        changed = true;
    }
    int transfer = int(p.transfer);
    if (ImGui::Combo("transfer", &transfer, kTransferLabels, PF_TRANSFER_COUNT)) {
        p.transfer = pf_transfer(transfer);
        changed = true;
    }
    tooltip("APIC keeps rotation and shear without FLIP's noise (flip ratio is then ignored)");
    int advection = int(p.advection);
    if (ImGui::Combo("advection", &advection, kAdvectionLabels, PF_ADVECTION_COUNT)) {
        p.advection = pf_advection(advection);
        changed = true;
    }
    tooltip("RK2 / RK3 sample the grid velocity 2 / 3 times per substep");
    return changed;
}

bool Viewer::ui_other_params(pf_sim_params& p) {
    bool changed = false;
    changed |= ImGui::SliderFloat("flip ratio", &p.flip_ratio, 0.0f, 1.0f, "%.3f");
    tooltip("0 = pure PIC, 1 = pure FLIP (PIC/FLIP transfer only)");
    changed |= ImGui::DragFloat3("gravity", p.gravity, 0.05f, -50.0f, 50.0f, "%.2f");
    changed |= ImGui::SliderFloat("cfl", &p.cfl, 0.1f, 8.0f, "%.2f");
    int subs = int(p.max_substeps);
    if (ImGui::SliderInt("max substeps", &subs, 1, 64)) {
        p.max_substeps = uint32_t(subs);
        changed = true;
    }
    int layers = int(p.extrapolation_layers);
    if (ImGui::SliderInt("extrapolation layers", &layers, 1, 16)) {
        p.extrapolation_layers = uint32_t(layers);
        changed = true;
    }
    return changed;
}

// Effects: each PF_FEATURE_* toggled live (pf_set_features builds an effect the first time it is
// turned on and dispatches nothing for it while off: the pass table shows it), the scene's
// obstacles moved and its emitters' rates changed between steps. A refused edit shows the
// library's logged reason and changes nothing.
void Viewer::ui_effects() {
    if (!ImGui::CollapsingHeader("Effects", ImGuiTreeNodeFlags_DefaultOpen)) return;
    uint32_t features = 0;
    pfs::check(pf_get_features(sim_.get(), &features), "pf_get_features");
    struct Toggle {
        const char* label;
        uint32_t bit;
        size_t objects;
    };
    const Toggle toggles[] = {{"force fields", PF_FEATURE_FORCE_FIELDS, scene_.force_fields.size()},
                              {"obstacles", PF_FEATURE_OBSTACLES, scene_.obstacles.size()},
                              {"emitters", PF_FEATURE_EMITTERS, scene_.emitters.size()},
                              {"sinks", PF_FEATURE_SINKS, scene_.sinks.size()}};
    auto report = [&](const char* call, pf_result r) { effects_error_ = r == PF_OK ? std::string() : log_.explain(call, r); };
    for (const Toggle& t : toggles) {
        bool on = (features & t.bit) != 0;
        const std::string label = std::string(t.label) + " (" + std::to_string(t.objects) + ")";
        if (ImGui::Checkbox(label.c_str(), &on)) {
            log_.clear();
            report("pf_set_features", pf_set_features(sim_.get(), on ? (features | t.bit) : (features & ~t.bit)));
        }
    }
    {
        // Vorticity confinement: a switch and its strength (no objects).
        bool on = (features & PF_FEATURE_VORTICITY_CONFINEMENT) != 0;
        if (ImGui::Checkbox("vorticity confinement", &on)) {
            log_.clear();
            report("pf_set_features",
                   pf_set_features(sim_.get(), on ? (features | PF_FEATURE_VORTICITY_CONFINEMENT)
                                                  : (features & ~uint32_t(PF_FEATURE_VORTICITY_CONFINEMENT))));
        }
        pf_vorticity_confinement c = pf_default_vorticity_confinement();
        pfs::check(pf_get_vorticity_confinement(sim_.get(), &c), "pf_get_vorticity_confinement");
        if (ImGui::SliderFloat("confinement strength", &c.strength, 0.0f, 1.0f, "%.3f")) {
            log_.clear();
            report("pf_set_vorticity_confinement", pf_set_vorticity_confinement(sim_.get(), &c));
        }
    }
    {
        // Viscosity: a switch and mu on a logarithmic slider (water 1e-3 to lava 1e4 Pa s spans
        // seven decades), and what the solve took in the last measured step.
        bool on = (features & PF_FEATURE_VISCOSITY) != 0;
        if (ImGui::Checkbox("viscosity", &on)) {
            log_.clear();
            report("pf_set_features", pf_set_features(sim_.get(), on ? (features | PF_FEATURE_VISCOSITY)
                                                                     : (features & ~uint32_t(PF_FEATURE_VISCOSITY))));
        }
        pf_viscosity v = pf_default_viscosity();
        pfs::check(pf_get_viscosity(sim_.get(), &v), "pf_get_viscosity");
        if (ImGui::SliderFloat("viscosity (Pa s)", &v.viscosity, 1e-3f, 1e4f, "%.3g", ImGuiSliderFlags_Logarithmic)) {
            log_.clear();
            report("pf_set_viscosity", pf_set_viscosity(sim_.get(), &v));
        }
        ImGui::Text("viscosity solve: %u iterations, residual %.2e", stats_.viscosity_iterations,
                    double(stats_.viscosity_residual));
    }
    {
        // Surface tension: a switch and sigma on a logarithmic slider (water's 0.072 N/m rounds
        // nothing at game scales; tens of N/m round a 10 cm blob), and the substeps it costs: the
        // force is explicit, so a large tension on a fine grid raises the count, and where
        // max_substeps cannot cover it the step uses a smaller tension (SUBSTEPS_CLAMPED).
        bool on = (features & PF_FEATURE_SURFACE_TENSION) != 0;
        if (ImGui::Checkbox("surface tension", &on)) {
            log_.clear();
            report("pf_set_features",
                   pf_set_features(sim_.get(), on ? (features | PF_FEATURE_SURFACE_TENSION)
                                                  : (features & ~uint32_t(PF_FEATURE_SURFACE_TENSION))));
        }
        pf_surface_tension t = pf_default_surface_tension();
        pfs::check(pf_get_surface_tension(sim_.get(), &t), "pf_get_surface_tension");
        if (ImGui::SliderFloat("tension (N/m)", &t.tension, 0.01f, 1000.0f, "%.3g", ImGuiSliderFlags_Logarithmic)) {
            log_.clear();
            report("pf_set_surface_tension", pf_set_surface_tension(sim_.get(), &t));
        }
        ImGui::Text("substeps: %u%s", stats_.substeps,
                    (stats_.flags & PF_FLAG_SUBSTEPS_CLAMPED) ? " (clamped: max substeps too few)" : "");
    }
    {
        // Whitewater: a switch, its two rates and its lifetimes (the look is under "look").
        bool on = (features & PF_FEATURE_WHITEWATER) != 0;
        if (ImGui::Checkbox("whitewater", &on)) {
            log_.clear();
            report("pf_set_features", pf_set_features(sim_.get(), on ? (features | PF_FEATURE_WHITEWATER)
                                                                     : (features & ~uint32_t(PF_FEATURE_WHITEWATER))));
        }
        pf_whitewater w = pf_default_whitewater();
        pfs::check(pf_get_whitewater(sim_.get(), &w), "pf_get_whitewater");
        bool changed = ImGui::SliderFloat("trapped-air rate", &w.trapped_air_rate, 0.0f, 400.0f, "%.0f /cell/s");
        changed |= ImGui::SliderFloat("wave-crest rate", &w.wave_crest_rate, 0.0f, 400.0f, "%.0f /cell/s");
        changed |= ImGui::SliderFloat2("lifetime", w.lifetime, 0.1f, 10.0f, "%.2f s");
        if (changed) {
            log_.clear();
            report("pf_set_whitewater", pf_set_whitewater(sim_.get(), &w));
        }
        ImGui::Text("whitewater particles: %u", stats_.whitewater_count);
    }
    for (size_t i = 0; i < scene_.obstacles.size() && i < effect_ids_.obstacles.size(); ++i) {
        pf_obstacle o = obstacle_pose(i); // a floating one where it floats now
        const std::string label = "obstacle " + std::to_string(i) + " position";
        if (ImGui::DragFloat3(label.c_str(), o.position, 0.005f, -1e4f, 1e4f, "%.3f")) {
            log_.clear();
            report("pf_set_obstacle", place_obstacle(i, o));
        }
    }
    for (size_t i = 0; i < scene_.emitters.size() && i < effect_ids_.emitters.size(); ++i) {
        pf_emitter& e = scene_.emitters[i];
        const std::string label = "emitter " + std::to_string(i) +
                                  (e.rate_unit == PF_RATE_VOLUME_PER_SECOND ? " rate (m^3/s)" : " rate (1/s)");
        const float most = e.rate_unit == PF_RATE_VOLUME_PER_SECOND ? 0.1f : 1e5f;
        if (ImGui::SliderFloat(label.c_str(), &e.rate, 0.0f, most, "%.4g", ImGuiSliderFlags_Logarithmic)) {
            log_.clear();
            report("pf_set_emitter", pf_set_emitter(sim_.get(), effect_ids_.emitters[i], &e));
        }
    }
    if (!effects_error_.empty()) error_text(effects_error_);
}

// Every change goes through pf_set_params; a refused one leaves the library's parameters as
// they were (the panel then shows them again) and the logged reason under the knobs.
void Viewer::apply_params(const pf_sim_params& p) {
    log_.clear();
    const pf_result r = pf_set_params(sim_.get(), &p);
    if (r == PF_OK) {
        params_error_.clear();
        knob_pending_ = true;
        knob_step_ = stats_.steps;
    } else {
        params_error_ = log_.explain("pf_set_params", r);
    }
    pf_get_params(sim_.get(), &params_); // what the library holds now
}

void Viewer::ui_rendering() {
    if (!ImGui::CollapsingHeader("Rendering")) return;
    int mode = look_.ssf ? 0 : 1;
    ImGui::RadioButton("screen-space fluid", &mode, 0);
    ImGui::SameLine();
    ImGui::RadioButton("particles (P)", &mode, 1);
    look_.ssf = mode == 0;
    {
        const char* names[] = {"standard", "zero_to_one", "reversed_z"};
        int d = int(camera_depth_);
        if (ImGui::Combo("depth convention", &d, names, world_->has_clip_control() ? 3 : 1))
            camera_depth_ = pf_depth_convention(d);
    }
    if (look_.ssf) {
        pf_ssf_params& s = look_.ssf_params;
        const char* filters[] = {"bilateral", "narrow range", "none"};
        int f = int(s.filter);
        if (ImGui::Combo("filter", &f, filters, 3)) s.filter = pf_ssf_filter(f);
        const char* paths[] = {"compute", "raster"};
        int pth = int(s.path);
        if (ImGui::Combo("path", &pth, paths, 2)) s.path = pf_ssf_path(pth);
        ImGui::SliderFloat("particle radius", &s.particle_radius, 0.0f, 4.0f * scene_.cell_size, "%.4f m (0 = default)");
        int fr = int(s.filter_radius), fi = int(s.filter_iterations);
        ImGui::SliderFloat("filter width", &s.filter_world_radius, 0.0f, 8.0f * scene_.cell_size, "%.4f m (0 = one cell)");
        if (ImGui::SliderInt("filter cap px", &fr, 0, 64, fr ? "%d" : "%d (default)")) s.filter_radius = uint32_t(fr);
        if (ImGui::SliderInt("filter iterations", &fi, 0, 16, fi ? "%d" : "%d (default)")) s.filter_iterations = uint32_t(fi);
        ImGui::SliderFloat("depth range", &s.filter_depth_range, 0.0f, 8.0f * scene_.cell_size, "%.4f m (0 = default)");
        ImGui::DragFloat3("absorption /m", s.absorption, 0.02f, 0.0f, 100.0f, "%.2f");
        ImGui::SliderFloat("refraction", &s.refraction, 0.0f, 0.2f, "%.3f");
        ImGui::SliderFloat("fresnel f0", &s.fresnel_f0, 0.0f, 1.0f, "%.3f");
        ImGui::SliderFloat("specular", &s.specular, 0.0f, 10.0f, "%.2f");
        ImGui::SliderFloat("shininess", &s.shininess, 1.0f, 2000.0f, "%.0f", ImGuiSliderFlags_Logarithmic);
        bool whitewater = s.skip_whitewater == 0;
        if (ImGui::Checkbox("whitewater layer", &whitewater)) s.skip_whitewater = whitewater ? 0u : 1u;
        ImGui::SliderFloat("whitewater radius", &s.whitewater_radius, 0.0f, scene_.cell_size, "%.4f m (0 = default)");
        ImGui::SliderFloat("whitewater opacity", &s.whitewater_opacity, 0.0f, 1.0f, "%.2f (0 = default)");
        ImGui::SliderFloat("spray radius scale", &s.spray_radius_scale, 0.0f, 1.0f, "%.2f (0 = default 0.5, 1 = off)");
        if (ImGui::DragFloat3("light direction", s.light_direction, 0.01f, -1.0f, 1.0f, "%.2f")) {
            if (glm::length(glm::vec3(s.light_direction[0], s.light_direction[1], s.light_direction[2])) < 1e-3f)
                s.light_direction[1] = 1.0f;
            world_->set_sun(glm::vec3(s.light_direction[0], s.light_direction[1], s.light_direction[2]));
        }
        ImGui::Checkbox("reflect the world's sky cube map", &look_.sky_cubemap);
        if (ImGui::Button("Defaults")) {
            s = pf_default_ssf_params();
            world_->set_sun(glm::vec3(s.light_direction[0], s.light_direction[1], s.light_direction[2]));
        }
    } else {
        pf_particle_params& p = look_.particle_params;
        const char* colors[] = {"speed", "velocity x", "velocity y", "velocity z", "height", "uniform"};
        int c = int(p.color_by);
        if (ImGui::Combo("colour by", &c, colors, 6)) p.color_by = pf_particle_color(c);
        ImGui::SliderFloat("sprite radius", &p.particle_radius, 0.0f, 4.0f * scene_.cell_size, "%.4f m (0 = default)");
        ImGui::DragFloat2("range", p.range, 0.01f, -100.0f, 100.0f, "%.2f");
        if (p.range[0] == p.range[1]) p.range[1] = p.range[0] + 0.01f;
        ImGui::ColorEdit3("low", p.color_low);
        ImGui::ColorEdit3("high", p.color_high);
        if (ImGui::Button("Defaults")) p = pf_default_particle_params();
    }
}

void Viewer::ui_stats() {
    const pf_stats& s = stats_;
    float avg = 0;
    for (float v : frame_ms_) avg += v;
    avg = frame_ms_.empty() ? 0 : avg / float(frame_ms_.size());
    ImGui::Text("frame %.1f ms (%.1f fps), pf_step wall %.1f ms", double(avg), avg > 0 ? 1000.0 / double(avg) : 0.0,
                step_wall_ms_);
    if (!frame_ms_.empty()) {
        std::vector<float> v(frame_ms_.begin(), frame_ms_.end());
        ImGui::PlotLines("##frame", v.data(), int(v.size()), 0, "frame ms", 0.0f, 2.0f * avg,
                         ImVec2(ImGui::GetContentRegionAvail().x, 32)); // 1.86: no negative sizes here
    }
    ImGui::Text("particles %u / %u, max speed %.2f m/s", s.particle_count, s.max_particles, double(s.max_speed));
    ImGui::Text("step %llu, substeps %u", static_cast<unsigned long long>(s.steps), s.substeps);
    ui_history();
    // Simulation passes (GPU ms of one step, dispatches) beside what the solve reached; the
    // render passes (GPU ms of one pf_render_* call) below. GPU figures lag a few frames: the
    // timers are read without stalling.
    ImGui::Text("GPU ms: step %llu (%u substeps) | render call %llu", static_cast<unsigned long long>(s.gpu_step),
                s.gpu_substeps, static_cast<unsigned long long>(s.render_frame));
    if (ImGui::BeginTable("price", 2, ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("passes", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("accuracy", ImGuiTableColumnFlags_WidthFixed, 150.0f);
        ImGui::TableNextColumn();
        ui_pass_table();
        ImGui::TableNextColumn();
        ui_accuracy();
        ImGui::EndTable();
    }
    ui_render_pass_table();
    ImGui::Text("host ms: pf_step %.2f, render call %.2f", double(s.cpu_ms), double(s.render_cpu_ms));
}

// One sample per newly measured step: GPU ms and the residual come from the same readback.
void Viewer::record_step() {
    if (stats_.gpu_step == 0 || stats_.gpu_step == last_sampled_step_) return;
    last_sampled_step_ = stats_.gpu_step;
    StepSample sample;
    sample.gpu_ms = stats_.gpu_total_ms;
    sample.log_residual = std::log10(std::max(stats_.solver_residual, 1e-12f));
    if (knob_pending_ && stats_.gpu_step > knob_step_) {
        sample.knob = true;
        knob_pending_ = false;
    }
    history_.push_back(sample);
    if (history_.size() > kHistorySteps) history_.pop_front();
}

// GPU ms per step and log10 residual over the last kHistorySteps measured steps; yellow ticks
// where a knob changed, the green line is the tolerance.
void Viewer::ui_history() {
    if (history_.empty()) return;
    std::vector<float> ms, res;
    std::vector<bool> knob;
    float ms_max = 0, res_lo = 0, res_hi = -12;
    for (const StepSample& h : history_) {
        ms.push_back(h.gpu_ms);
        res.push_back(h.log_residual);
        knob.push_back(h.knob);
        ms_max = std::max(ms_max, h.gpu_ms);
        res_lo = std::min(res_lo, h.log_residual);
        res_hi = std::max(res_hi, h.log_residual);
    }
    // Whole decades around the curve and the tolerance, so the scale only moves when a
    // knob moves the residual by a decade.
    const float log_tol = std::log10(std::max(params_.pressure_tolerance, 1e-12f));
    const float lo = std::floor(std::min(res_lo, log_tol)) - 0.5f;
    const float hi = std::ceil(std::max(res_hi, log_tol)) + 0.5f;
    char text[96];
    std::snprintf(text, sizeof text, "GPU %.2f ms / step (last %zu)", double(ms.back()), ms.size());
    plot_history("##gpu_ms", ms, knob, 0.0f, 1.15f * std::max(ms_max, 1e-3f), text, -1.0f);
    std::snprintf(text, sizeof text, "log10 residual %.2f (tolerance %.1e)", double(res.back()),
                  double(params_.pressure_tolerance));
    plot_history("##residual", res, knob, lo, hi, text, log_tol);
}

// The runtime pass list in the library's order. Passes of solvers no longer selected stay in
// the list with nothing to report; they are hidden unless asked for.
void Viewer::ui_pass_table() {
    const ImGuiTableFlags tf = ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp;
    if (!ImGui::BeginTable("passes", 3, tf)) return;
    ImGui::TableSetupColumn("sim pass", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthFixed, 56.0f);
    ImGui::TableSetupColumn("disp", ImGuiTableColumnFlags_WidthFixed, 36.0f);
    ImGui::TableHeadersRow();
    uint32_t idle = 0;
    for (const pf_pass_stats& p : passes_) {
        if (!show_idle_passes_ && p.dispatches == 0 && p.gpu_ms == 0.0f) {
            ++idle;
            continue;
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(p.name);
        tooltip(pf_pass_name(p.group));
        ImGui::TableNextColumn();
        ImGui::Text("%.3f", double(p.gpu_ms));
        ImGui::TableNextColumn();
        ImGui::Text("%u", p.dispatches);
    }
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("total");
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", double(stats_.gpu_total_ms));
    ImGui::EndTable();
    if (idle > 0 || show_idle_passes_) {
        char label[48];
        std::snprintf(label, sizeof label, "show %u idle passes", idle);
        ImGui::Checkbox(show_idle_passes_ ? "show idle passes" : label, &show_idle_passes_);
    }
}

// What the solve reached against what was asked: iterations against the cap, residual
// against the tolerance, plus the GPU's flags.
void Viewer::ui_accuracy() {
    const pf_stats& s = stats_;
    const pf_sim_params& p = params_;
    ImGui::TextDisabled("accuracy");
    ImGui::Text("solver %s", pfs::solver_name(p.pressure_solver));
    ImGui::Text("iterations %u / %u", s.solver_iterations, p.pressure_iterations);
    ImGui::Text("residual %.2e", double(s.solver_residual));
    ImGui::Text("tolerance %.1e", double(p.pressure_tolerance));
    if (s.gpu_step == 0)
        ImGui::TextDisabled("(not measured yet)");
    else if (s.solver_iterations >= p.pressure_iterations && s.solver_residual > p.pressure_tolerance)
        ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "stopped at the cap");
    else
        ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1), "converged");
    tooltip("per step: the most iterations and the largest final residual of its substeps");
    ImGui::Text("%s, %s", pfs::transfer_name(p.transfer), pfs::advection_name(p.advection));
    // The metrics of pf_stats (docs/design.md §4.11): what the step left, a few steps late.
    ImGui::Text("divergence %.2e (max %.2e) 1/s", double(s.divergence_l2), double(s.divergence_max));
    ImGui::Text("liquid volume %+.2f%%, density %.3f", 100.0 * double(s.liquid_volume_drift), double(s.interior_density));
    tooltip("mass over density: the particles' rest volume over their mean count in interior cells, against "
            "the first measured step; density is that mean over the rest count (1 at rest)");
    ImGui::Text("energy %+.2f%% (kinetic %.3g J)", 100.0 * double(s.energy_drift), double(s.kinetic_energy));
    ImGui::TextWrapped("flags: %s", pfs::flag_names(s.flags).c_str());
    if (s.flags && ImGui::SmallButton("clear flags")) pf_clear_flags(sim_.get());
}

void Viewer::ui_render_pass_table() {
    const ImGuiTableFlags tf = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp;
    if (!ImGui::BeginTable("render passes", 2, tf)) return;
    ImGui::TableSetupColumn("render pass", ImGuiTableColumnFlags_WidthStretch, 3.0f);
    ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableHeadersRow();
    for (int row = 0; row <= PF_RENDER_PASS_COUNT; ++row) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        const bool total = row == PF_RENDER_PASS_COUNT;
        ImGui::TextUnformatted(total ? "total" : pf_render_pass_name(pf_render_pass(row)));
        ImGui::TableNextColumn();
        ImGui::Text("%.3f", double(total ? stats_.render_gpu_total_ms : stats_.render_gpu_ms[row]));
        if (row == PF_RENDER_PASS_COUNT - 1) {  // the whitewater layer, before the total
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted("whitewater");
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", double(stats_.render_whitewater_gpu_ms));
        }
    }
    ImGui::EndTable();
}

// ---- main -----------------------------------------------------------------------------------

void glfw_error(int code, const char* message) { std::fprintf(stderr, "pf_viewer: GLFW error %d: %s\n", code, message); }

int run(int argc, char** argv) {
    Options opt;
    CLI::App app{"pf_viewer: the interactive pflip viewer (GLFW + Dear ImGui)", "pf_viewer"};
    add_options(app, opt);
    CLI11_PARSE(app, argc, argv); // before any window or GL context: a refused option costs none
    pfs::resolve_scene_path(opt.scene); // fail early on a typo

    glfwSetErrorCallback(glfw_error);
    if (!glfwInit()) throw Error("glfwInit failed (no display? try xvfb-run -s '-screen 0 1280x720x24')");
    struct GlfwGuard {
        ~GlfwGuard() { glfwTerminate(); }
    } glfw_guard;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_DEPTH_BITS, 0);   // the world has its own depth texture
    glfwWindowHint(GLFW_SAMPLES, 0);
    GLFWwindow* window = glfwCreateWindow(int(opt.size.width), int(opt.size.height), "pflip viewer", nullptr, nullptr);
    if (!window) throw Error("could not create a GL 4.3 core window");
    glfwMakeContextCurrent(window);
    glfwSwapInterval(opt.vsync ? 1 : 0);

    const int glv = gladLoadGL(glad_get_proc);
    if (!glv || GLAD_VERSION_MAJOR(glv) * 100 + GLAD_VERSION_MINOR(glv) < 403)
        throw Error("gladLoadGL: OpenGL 4.3 core functions not available");
    std::printf("pflip %s viewer: %s, %s\n", pfs::pf_version_string().c_str(),
                reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                reinterpret_cast<const char*>(glGetString(GL_VERSION)));

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini in the working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 430 core");

    int rc = 0;
    {
        Viewer viewer(opt, window);
        for (uint64_t f = 1; !glfwWindowShouldClose(window); ++f) {
            glfwPollEvents();
            viewer.frame(f);
            if (opt.frames && f >= opt.frames) {
                if (!opt.screenshot.empty()) {
                    int w = 0, h = 0;
                    glfwGetFramebufferSize(window, &w, &h);
                    std::vector<uint8_t> px;
                    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
                    glReadBuffer(GL_BACK);
                    pfs::read_rgba(w, h, px);
                    pfs::check_gl("screenshot");
                    if (!pfs::write_image_rgba(opt.screenshot, uint32_t(w), uint32_t(h), px.data(), true))
                        throw Error("writing " + opt.screenshot + " failed: " + std::strerror(errno));
                    std::printf("screenshot: %s (%dx%d, frame %llu)\n", opt.screenshot.c_str(), w, h,
                                static_cast<unsigned long long>(f));
                }
                glfwSwapBuffers(window);
                break;
            }
            glfwSwapBuffers(window);
        }
        viewer.print_obstacles();
        // Shown in the panel, where a scripted run's log would never see it.
        if (!viewer.last_error().empty()) std::fprintf(stderr, "pf_viewer: error shown at exit: %s\n", viewer.last_error().c_str());
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    return rc;
}

} // namespace

int main(int argc, char** argv) { return pfs::run_tool("pf_viewer", run, argc, argv); }
