// Scene files for the pflip samples (JSON). See samples/scenes/*.json; the format:
//
// {
//   "name": "dam_break_small",                 optional, defaults to the file name
//   "description": "...",                      optional
//   "grid": { "size": [48, 32, 24],            cells per axis (required)
//             "cell_size": 0.03125,            metres (required)
//             "origin": [0, 0, 0] },           world position of the minimum corner (optional)
//   "max_particles": 200000,                   capacity (required)
//   "particles_per_cell": 8,                   1, 8, 27 or 64 (optional, library default 8)
//   "fill_jitter": 0.8, "seed": 1,             optional pf_fill_box settings
//   "max_speed": 100, "density": 1000,         optional pf_sim_desc settings
//   "fill": [ { "lo": [x,y,z], "hi": [x,y,z],  boxes in world metres, filled with pf_fill_box
//               "velocity": [0,0,0] } ],       optional initial velocity
//   "params": { "gravity": [0,-9.81,0], "flip_ratio": 0.95, "pressure_iterations": 40,
//               "jacobi_omega": 1, "cfl": 1, "max_substeps": 8,
//               "extrapolation_layers": 2 },   optional pf_sim_params overrides
//   "frame_dt": 0.016666667,                   seconds per pf_step (optional, 1/60)
//   "frames": 120,                             demo length (optional)
//   "camera": { "eye": [x,y,z], "target": [x,y,z], "fov": 45 }  optional, degrees (vertical)
//   "preset": "balanced",                      optional quality preset (fast, balanced, accurate),
//                                              applied before "params" (keeps the scene's gravity
//                                              and max_substeps)
//   "features": ["obstacles", "emitters"],     effects the scene needs (force_fields, obstacles,
//                                              emitters, sinks); only these are built and run
//   "force_fields": [ { "type": "point", "position": [..], "vector": [..], "strength": 5,
//                       "radius": 0.5, "drag": 0 } ],               pf_force_field (needs the feature)
//   "obstacles": [ { "shape": "sphere", "position": [..], "rotation": [x,y,z,w],
//                    "half_extents": [..], "radius": 0.1, "half_height": 0,
//                    "float_density": 500 } ],   pf_obstacle; with float_density (kg/m^3) the
//                                               samples float it as a rigid body (floating.h);
//                  with "oscillation": {"amplitude": [x,y,z], "period": 2} they move it along
//                  p0 + amplitude sin(2 pi t / period) (driven.h; not with float_density)
//                  shape "box", "sphere", "capsule" or "sdf"; an "sdf" obstacle also takes
//                  "file": "bowl.npy" (required; relative to the scene file's folder: a NumPy
//                  .npy grid, sdf_file.h gives the format), "half_extents" (required: the box the
//                  grid tiles) and "sdf_scale": 1 (metres per unit of the file's values)
//   "emitters": [ { "shape": "disc", "position": [..], "rotation": [..], "half_extents": [..],
//                   "radius": 0.05, "velocity": [..], "rate": 0.002,
//                   "rate_unit": "volume_per_second" } ],          pf_emitter
//   "sinks": [ { "shape": "box", "position": [..], "rotation": [..], "half_extents": [..],
//                "radius": 0.1 } ],                                 pf_sink
//   "domain_motion": { "position": [..], "rotation": [..], "velocity": [..],
//                      "angular_velocity": [..] }                  pf_domain_motion, set once
//   "vorticity_confinement": { "strength": 0.2 }                   pf_vorticity_confinement, set once
//   "whitewater": { "capacity": 262144, "trapped_air_rate": 40, "lifetime": [1, 3], ... }
//                                                                   pf_whitewater (any of its fields), set once
//   "viscosity": { "viscosity": 5.0, "iterations": 60, "tolerance": 1e-3,
//                  "free_slip": false, "coupling_rounds": 1 }       pf_viscosity (Pa s), set once
//   "surface_tension": { "tension": 12.5 }                         pf_surface_tension (N/m), set once
// }
// Effect objects start from pf_default_*() and take the keys given; the library validates them
// when the scene is created, and an error names the object's JSON Pointer ("/emitters/1").
//
// Keys beginning with '_' are ignored (use them for comments); any other unknown key is an
// error, so typos do not go unnoticed.
#pragma once

#include <pf/pf.h>

#include "driven.h"
#include "sdf_file.h"
#include "sdf_texture.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace pfs {

using vec3f = std::array<float, 3>;

struct FillBox {
    vec3f lo{}, hi{}, velocity{};
};

struct SceneCamera {
    vec3f eye{}, target{};
    float fov_deg = 45.0f;
};

struct Scene {
    std::string path, name, description;
    uint32_t grid_size[3] = {32, 32, 32};
    float cell_size = 0.05f;
    vec3f origin{};
    uint32_t max_particles = 0;
    uint32_t particles_per_cell = 0; // 0: library default
    bool has_fill_jitter = false, has_seed = false, has_max_speed = false, has_density = false;
    float fill_jitter = 0, max_speed = 0, density = 0;
    uint32_t seed = 0;
    pf_sim_params params{};          // pf_default_sim_params() with the file's overrides
    std::vector<FillBox> boxes;
    float frame_dt = 1.0f / 60.0f;
    uint32_t frames = 120;
    bool has_camera = false;
    SceneCamera camera;
    bool has_preset = false;
    pf_quality preset = PF_QUALITY_FAST;
    uint32_t features = 0;           // PF_FEATURE_* bits named by "features"
    std::vector<pf_force_field> force_fields;
    std::vector<pf_obstacle> obstacles;
    std::vector<float> obstacle_float_density;  // per obstacle; 0: moved only by the app
    std::vector<Oscillation> obstacle_oscillation;  // per obstacle; period 0: not driven
    // Per obstacle: the grid of an "sdf" one (its pf_obstacle's sdf_texture stays 0 until
    // add_scene_effects uploads the grid), null for the other shapes.
    std::vector<std::shared_ptr<const SdfGrid>> obstacle_sdf;
    std::vector<pf_emitter> emitters;
    std::vector<pf_sink> sinks;
    bool has_domain_motion = false;
    pf_domain_motion domain_motion{};
    bool has_vorticity_confinement = false;
    pf_vorticity_confinement vorticity_confinement{};
    bool has_whitewater = false;
    pf_whitewater whitewater{};
    bool has_viscosity = false;
    pf_viscosity viscosity{};
    bool has_surface_tension = false;
    pf_surface_tension surface_tension{};

    /// World-space bounds of the grid.
    vec3f domain_min() const { return origin; }
    vec3f domain_max() const;
    /// Particles the fill boxes should produce (volume clipped to the domain x density); the
    /// library's exact count may differ by rounding at box edges.
    double estimated_particles() const;
    /// A camera looking at the domain from the front-right-above, for scenes without one.
    SceneCamera default_camera() const;
};

/// Parses a scene file; throws pfs::Error("<path>: <JSON Pointer of the bad value>: <reason>"),
/// e.g. "dam.json: /fill/0/velocity/2: is beyond float range ...". Floats must survive the
/// conversion (no value loads as +-Inf or rounds to 0 unless it is 0).
Scene load_scene(const std::string& path);

/// Parses scene JSON text (path is only used in messages).
Scene parse_scene(const std::string& text, const std::string& path);

/// pf_default_sim_desc() with the scene's grid, capacity and parameters; the caller's GL loader
/// and logger.
pf_sim_desc make_sim_desc(const Scene& scene, pf_gl_get_proc_address_fn get_proc, pf_logger logger);

/// Fills the scene's boxes into sim (pf_fill_box each). Throws pfs::Error on failure, naming
/// the box.
void fill_scene(pf_sim* sim, const Scene& scene);

/// The ids the library gave the scene's objects, in file order, and the engine objects they use:
/// the GL textures of the SDF obstacles, which the library samples but never deletes. Keep this
/// while the sim lives (destroy it after pf_destroy, with the GL context current).
struct SceneEffectIds {
    std::vector<uint32_t> force_fields, obstacles, emitters, sinks;
    std::vector<uint32_t> obstacle_textures;  // per obstacle: its sdf_texture as added (0: not an SDF)
    SdfTextures sdf_textures;                 // owns the textures named in obstacle_textures
};

/// The scene's driven obstacles (oscillation), registered with their ids.
void drive_scene_obstacles(const Scene& scene, const SceneEffectIds& ids, DrivenObstacles& out);

/// The scene's floating obstacles (float_density), registered with their ids.
class FloatingBodies;
void float_scene_obstacles(const Scene& scene, const SceneEffectIds& ids, FloatingBodies& out);

/// Adds the scene's force fields, obstacles, emitters and sinks to sim, first uploading each SDF
/// obstacle's grid as a GL 3D texture (with the app's GL loader, gladLoadGL, already run; the
/// textures are the result's). Throws pfs::Error naming the object's JSON Pointer and the
/// library's reason on failure. (samples/common/scene_sim.cpp: GL code, kept out of the loader.)
SceneEffectIds add_scene_effects(pf_sim* sim, const Scene& scene);

/// pf_create + fill_scene + add_scene_effects (ids into *ids when given; a scene with SDF
/// obstacles needs ids, which own their textures); throws on failure (and destroys the half-made
/// sim).
pf_sim* create_scene_sim(const Scene& scene, pf_gl_get_proc_address_fn get_proc, pf_logger logger,
                         SceneEffectIds* ids = nullptr);

} // namespace pfs
