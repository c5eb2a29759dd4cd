// libFuzzer target: the samples' scene loader (pfs::parse_scene) on arbitrary bytes. A file is
// either loaded with every value usable by the library (finite floats, sizes in range) or
// refused with pfs::Error naming the file and a JSON Pointer; anything else (another
// exception, a crash, a sanitizer report, a stack overflow) is a finding. The text is taken as
// a scene in the shipped scenes' folder, so an SDF obstacle's relative "file" reaches the
// .npy files there (bowl.npy) and the grid reader runs on them.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene.h"
#include "sdf_file.h"
#include "util.h"

namespace {

const std::string kScenePath = PF_FUZZ_SCENE_PATH;  // "<scenes>/fuzz.json" (CMake)

[[noreturn]] void finding(const char* what, const std::string& detail) {
    std::fprintf(stderr, "pf_scene_fuzz: %s: %s\n", what, detail.c_str());
    std::abort();
}

bool finite3(const pfs::vec3f& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

void check_loaded(const pfs::Scene& s) {
    for (uint32_t n : s.grid_size)
        if (n < 2 || n > 1024) finding("grid size out of range", std::to_string(n));
    if (!(std::isfinite(s.cell_size) && s.cell_size > 0)) finding("cell_size", std::to_string(s.cell_size));
    if (!finite3(s.origin)) finding("origin not finite", "");
    for (const pfs::FillBox& b : s.boxes)
        if (!finite3(b.lo) || !finite3(b.hi) || !finite3(b.velocity)) finding("fill box not finite", "");
    const pf_sim_params& p = s.params;
    const float scalars[] = {p.gravity[0], p.gravity[1], p.gravity[2], p.flip_ratio, p.jacobi_omega, p.cfl,
                             p.pressure_tolerance, p.sor_omega, s.frame_dt, s.fill_jitter, s.max_speed, s.density};
    for (float v : scalars)
        if (!std::isfinite(v)) finding("a loaded value is not finite", std::to_string(v));
    if (s.has_camera && (!finite3(s.camera.eye) || !finite3(s.camera.target) || !std::isfinite(s.camera.fov_deg)))
        finding("camera not finite", "");
    if (s.obstacle_sdf.size() != s.obstacles.size()) finding("SDF grids not one per obstacle", "");
    for (size_t i = 0; i < s.obstacles.size(); ++i) {
        const pf_obstacle& o = s.obstacles[i];
        const pfs::SdfGrid* g = s.obstacle_sdf[i].get();
        if ((o.shape == PF_OBSTACLE_SDF) != (g != nullptr)) finding("SDF grid without SDF shape or the reverse", "");
        if (!g) continue;
        if (!(std::isfinite(o.sdf_scale) && o.sdf_scale > 0)) finding("sdf_scale", std::to_string(o.sdf_scale));
        size_t n = 1;
        for (uint32_t a : g->size) {
            if (a < 2 || a > pfs::kMaxSdfSamples) finding("SDF grid size out of range", std::to_string(a));
            n *= a;
        }
        if (g->values.size() != n) finding("SDF grid values do not match its size", std::to_string(g->values.size()));
        for (float v : g->values)
            if (!std::isfinite(v)) finding("SDF grid value not finite", std::to_string(v));
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        check_loaded(pfs::parse_scene(text, kScenePath));
    } catch (const pfs::Error& e) {
        const std::string msg = e.what();
        // "<file>: <pointer or (top level)>: <reason>"
        if (msg.rfind(kScenePath + ": /", 0) != 0 && msg.rfind(kScenePath + ": (top level): ", 0) != 0)
            finding("error without file and JSON path", msg);
    }
    return 0;
}
