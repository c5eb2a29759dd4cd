// The samples' scene loader (samples/common/scene.cpp) on malformed files: each one must be
// refused with a message that names the file, the JSON Pointer of the bad value and the
// reason, and nothing may escape as anything but pfs::Error (no bare nlohmann exception, no
// crash on deep nesting). Also: every shipped scene loads, and the edges of float range load
// exactly. No GL is needed: parse_scene only reads text.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "scene.h"
#include "util.h"

namespace {

// The smallest valid scene; cases splice their bad value into a copy of it.
const std::string kGrid = R"("grid": {"size": [4, 4, 4], "cell_size": 0.1})";
const std::string kValid = "{" + kGrid + R"(, "max_particles": 1000})";

std::string with(const std::string& members) { return "{" + kGrid + R"(, "max_particles": 1000, )" + members + "}"; }

std::string repeat(const std::string& s, size_t n) {
    std::string r;
    while (n--) r += s;
    return r;
}

std::string nested_arrays(size_t depth) { return std::string(depth, '[') + "1" + std::string(depth, ']'); }

struct BadScene {
    const char* name;
    std::string text;
    std::string pointer;  // JSON Pointer the message must carry
    std::string reason;   // and a piece of the reason
};

std::vector<BadScene> bad_scenes() {
    return {
        {"not_an_object", "[1, 2]", "(top level)", "must be an object, found an array of 2"},
        {"syntax_error_in_vector", R"({"grid": {"size": [4, 4, x]}})", "/grid/size/2", "invalid JSON"},
        {"trailing_garbage", kValid + " x", "(top level)", "invalid JSON"},
        {"unterminated", R"({"grid": {"size": [4, 4)", "/grid/size/2", "invalid JSON"},
        {"beyond_double_cell_size", R"({"grid": {"size": [4, 4, 4], "cell_size": 1e400}})", "/grid/cell_size",
         "beyond double range"},
        {"beyond_double_long_integer", with(R"("seed": 1)" + std::string(400, '0')), "/seed", "beyond double range"},
        {"beyond_double_in_velocity",
         with(R"("fill": [{"lo": [0, 0, 0], "hi": [0.1, 0.1, 0.1], "velocity": [0, 0, -1e999]}])"),
         "/fill/0/velocity/2", "beyond double range"},
        {"beyond_float_velocity",
         with(R"("fill": [{"lo": [0, 0, 0], "hi": [0.1, 0.1, 0.1], "velocity": [0, 0, 1e39]}])"),
         "/fill/0/velocity/2", "beyond float range"},
        {"beyond_float_gravity", with(R"("params": {"gravity": [0, 1e300, 0]})"), "/params/gravity/1",
         "beyond float range"},
        {"beyond_float_origin", R"({"grid": {"size": [4, 4, 4], "cell_size": 0.1, "origin": [-1e39, 0, 0]}})",
         "/grid/origin/0", "beyond float range"},
        {"beyond_float_camera", with(R"("camera": {"eye": [1, 2, 3], "target": [0, 0, 0], "fov": 4e38})"),
         "/camera/fov", "beyond float range"},
        {"oscillation_without_period",
         with(R"("features": ["obstacles"], "obstacles": [{"shape": "sphere", "oscillation": {"amplitude": [0, 1, 0]}}])"),
         "/obstacles/0/oscillation/period", "is required but missing"},
        {"oscillation_of_zero_period",
         with(R"("features": ["obstacles"], "obstacles": [{"shape": "sphere", "oscillation": {"amplitude": [0, 1, 0], "period": 0}}])"),
         "/obstacles/0/oscillation/period", "must be in"},
        {"oscillation_with_unknown_key",
         with(R"("features": ["obstacles"], "obstacles": [{"shape": "sphere", "oscillation": {"amplitude": [0, 1, 0], "period": 1, "phase": 2}}])"),
         "/obstacles/0/oscillation/phase", "unknown"},
        {"oscillation_of_a_floating_obstacle",
         with(R"("features": ["obstacles"], "obstacles": [{"shape": "sphere", "float_density": 500, "oscillation": {"amplitude": [0, 1, 0], "period": 1}}])"),
         "/obstacles/0/oscillation", "cannot move an obstacle that floats"},
        {"underflows_float", R"({"grid": {"size": [4, 4, 4], "cell_size": 1e-50}})", "/grid/cell_size",
         "too small for a float"},
        {"deeply_nested_vector", with(R"("fill": [{"lo": )" + nested_arrays(200000) + "}]"),
         // 32 levels open (the document, /fill, /fill/0, lo and 28 more); the 33rd is refused
         "/fill/0/lo" + repeat("/0", 29),
         "nested deeper than"},
        {"nested_vector_within_depth", R"({"grid": {"size": [4, 4, 4], "cell_size": 0.1, "origin": [[[[1]]]]}})",
         "/grid/origin", "must be an array of 3 numbers, found an array of 1 element(s)"},
        {"vector_too_short", with(R"("params": {"gravity": [0, -9.81]})"), "/params/gravity",
         "must be an array of 3 numbers, found an array of 2"},
        {"vector_element_string", with(R"("camera": {"eye": [1, "2", 3], "target": [0, 0, 0]})"), "/camera/eye/1",
         "must be a number, found string"},
        {"unknown_key", with(R"("params": {"flipratio": 0.5})"), "/params/flipratio", "is not a known key"},
        {"unknown_key_escaped", with(R"("a/b~c": 1)"), "/a~1b~0c", "is not a known key"},
        {"missing_required", R"({"grid": {"size": [4, 4, 4]}, "max_particles": 1})", "/grid/cell_size",
         "is required but missing"},
        {"integer_as_string", "{" + kGrid + R"(, "max_particles": "1000"})", "/max_particles",
         "must be an integer, found string"},
        {"integer_fraction", with(R"("frames": 2.5)"), "/frames", "must be an integer, found 2.5"},
        {"integer_huge", "{" + kGrid + R"(, "max_particles": 1e30})", "/max_particles", "must be in [1, 268435456]"},
        {"grid_size_out_of_range", R"({"grid": {"size": [4, 1, 4], "cell_size": 0.1}, "max_particles": 1})",
         "/grid/size/1", "must be in [2, 1024], found 1"},
        {"grid_size_not_array", R"({"grid": {"size": {"x": 4}, "cell_size": 0.1}, "max_particles": 1})", "/grid/size",
         "found an object of 1 member(s)"},
        {"negative_cell_size", R"({"grid": {"size": [4, 4, 4], "cell_size": -0.1}, "max_particles": 1})",
         "/grid/cell_size", "must be in (0, 1e+06], found -0.1"},
        {"particles_per_cell", with(R"("particles_per_cell": 9)"), "/particles_per_cell", "must be 1, 8, 27 or 64"},
        {"fill_box_inverted", with(R"("fill": [{"lo": [0, 0.2, 0], "hi": [0.1, 0.1, 0.1]}])"), "/fill/0/hi/1",
         "must be greater than lo[1]"},
        {"fill_not_array", with(R"("fill": {"lo": [0, 0, 0]})"), "/fill", "must be an array of boxes"},
        {"fill_box_not_object", with(R"("fill": [[0, 0, 0]])"), "/fill/0", "must be an object"},
        {"capacity", "{" + kGrid + R"(, "max_particles": 10, "fill": [{"lo": [0, 0, 0], "hi": [0.4, 0.4, 0.4]}]})",
         "/max_particles", "the fill boxes need about 512"},
        {"solver_name", with(R"("params": {"pressure_solver": "gauss"})"), "/params/pressure_solver", "gauss"},
        {"solver_not_string", with(R"("params": {"pressure_solver": 2})"), "/params/pressure_solver",
         "must be a string"},
        {"advection_name", with(R"("params": {"advection": "rk4"})"), "/params/advection", "rk4"},
        {"transfer_name", with(R"("params": {"transfer": "mpm"})"), "/params/transfer", "mpm"},
        {"advection_not_string", with(R"("params": {"advection": 0})"), "/params/advection", "must be a string"},
        {"free_surface_not_string", with(R"("params": {"free_surface": true})"), "/params/free_surface",
         "must be a string"},
        {"name_not_string", with(R"("name": ["a"])"), "/name", "must be a string, found an array of 1"},
        {"camera_degenerate", with(R"("camera": {"eye": [1, 1, 1], "target": [1, 1, 1]})"), "/camera/target",
         "coincides with /camera/eye"},
        {"frame_dt_zero", with(R"("frame_dt": 0)"), "/frame_dt", "must be in (0, 1]"},
        // effects
        {"features_not_array", with(R"("features": "obstacles")"), "/features", "must be an array of feature names"},
        {"feature_unknown", with(R"("features": ["obstacles", "foam"])"), "/features/1", "unknown \"foam\""},
        {"objects_without_their_feature", with(R"("obstacles": [{"shape": "sphere"}])"), "/obstacles",
         "is not listed in /features"},
        {"obstacle_shape_unknown", with(R"("features": ["obstacles"], "obstacles": [{"shape": "cone"}])"),
         "/obstacles/0/shape", "unknown \"cone\" (one of box, sphere, capsule, sdf)"},
        // SDF obstacles: the JSON side (test_scene_sdf_file.cpp has the files)
        {"sdf_without_file", with(R"("features": ["obstacles"], "obstacles": [{"shape": "sdf", "half_extents": [1, 1, 1]}])"),
         "/obstacles/0/file", "is required but missing"},
        {"sdf_without_half_extents", with(R"("features": ["obstacles"], "obstacles": [{"shape": "sdf", "file": "a.npy"}])"),
         "/obstacles/0/half_extents", "is required for shape \"sdf\""},
        {"sdf_file_not_string",
         with(R"("features": ["obstacles"], "obstacles": [{"shape": "sdf", "half_extents": [1, 1, 1], "file": 3}])"),
         "/obstacles/0/file", "must be a string, found 3"},
        {"sdf_file_empty",
         with(R"("features": ["obstacles"], "obstacles": [{"shape": "sdf", "half_extents": [1, 1, 1], "file": ""}])"),
         "/obstacles/0/file", "must name an .npy file"},
        {"sdf_file_missing",
         with(R"("features": ["obstacles"], "obstacles": [{"shape": "sdf", "half_extents": [1, 1, 1], "file": "no.npy"}])"),
         "/obstacles/0/file", "malformed/no.npy: does not exist"},
        {"sdf_scale_zero",
         with(R"("features": ["obstacles"], "obstacles": [{"shape": "sdf", "half_extents": [1, 1, 1], "file": "a.npy", "sdf_scale": 0}])"),
         "/obstacles/0/sdf_scale", "must be in (0, 1e+06], found 0"},
        {"file_on_a_sphere", with(R"("features": ["obstacles"], "obstacles": [{"shape": "sphere", "file": "a.npy"}])"),
         "/obstacles/0/file", "is only for shape \"sdf\""},
        {"sdf_scale_on_a_box", with(R"("features": ["obstacles"], "obstacles": [{"sdf_scale": 2}])"),
         "/obstacles/0/sdf_scale", "is only for shape \"sdf\""},
        {"emitter_rotation_short", with(R"("features": ["emitters"], "emitters": [{"rotation": [0, 0, 1]}])"),
         "/emitters/0/rotation", "must be an array of 4 numbers"},
        {"emitter_rate_unit", with(R"("features": ["emitters"], "emitters": [{"rate_unit": "litres"}])"),
         "/emitters/0/rate_unit", "unknown \"litres\""},
        {"emitter_unknown_key", with(R"("features": ["emitters"], "emitters": [{"speed": 1}])"), "/emitters/0/speed",
         "is not a known key"},
        {"sink_beyond_float", with(R"("features": ["sinks"], "sinks": [{"radius": 1e39}])"), "/sinks/0/radius",
         "beyond float range"},
        {"force_field_not_object", with(R"("features": ["force_fields"], "force_fields": [3])"), "/force_fields/0",
         "must be an object"},
        {"effect_list_not_array", with(R"("features": ["sinks"], "sinks": {"shape": "box"})"), "/sinks",
         "must be an array of objects"},
        {"preset_unknown", with(R"("preset": "ultra")"), "/preset", "ultra"},
        {"domain_motion_without_feature", with(R"("domain_motion": {"velocity": [1, 0, 0]})"), "/domain_motion",
         "is not listed in /features"},
        {"domain_motion_unknown_key", with(R"("features": ["domain_motion"], "domain_motion": {"spin": [1, 0, 0]})"),
         "/domain_motion/spin", "is not a known key"},
        {"viscosity_without_feature", with(R"("features": ["emitters"], "viscosity": {"viscosity": 5})"), "/viscosity",
         "is not listed in /features"},
        {"viscosity_unknown_key", with(R"("features": ["viscosity"], "viscosity": {"mu": 5})"), "/viscosity/mu",
         "is not a known key"},
        {"viscosity_not_object", with(R"("features": ["viscosity"], "viscosity": 5)"), "/viscosity", "must be an object"},
        {"viscosity_iterations_fraction", with(R"("features": ["viscosity"], "viscosity": {"iterations": 2.5})"),
         "/viscosity/iterations", "must be an integer"},
        {"viscosity_iterations_negative", with(R"("features": ["viscosity"], "viscosity": {"iterations": -1})"),
         "/viscosity/iterations", "must be in [0, 4294967295]"},
        {"viscosity_free_slip_number", with(R"("features": ["viscosity"], "viscosity": {"free_slip": 1})"),
         "/viscosity/free_slip", "must be true or false"},
        {"viscosity_beyond_float", with(R"("features": ["viscosity"], "viscosity": {"viscosity": 1e39})"),
         "/viscosity/viscosity", "beyond float range"},
        {"surface_tension_without_feature",
         with(R"("features": ["viscosity"], "surface_tension": {"tension": 12.5})"), "/surface_tension",
         "is not listed in /features"},
        {"surface_tension_unknown_key", with(R"("features": ["surface_tension"], "surface_tension": {"sigma": 12.5})"),
         "/surface_tension/sigma", "is not a known key"},
        {"surface_tension_not_object", with(R"("features": ["surface_tension"], "surface_tension": 12.5)"),
         "/surface_tension", "must be an object"},
        {"surface_tension_string", with(R"("features": ["surface_tension"], "surface_tension": {"tension": "12.5"})"),
         "/surface_tension/tension", "must be a number, found string"},
        {"surface_tension_beyond_float",
         with(R"("features": ["surface_tension"], "surface_tension": {"tension": 1e39})"), "/surface_tension/tension",
         "beyond float range"},
    };
}

// gtest prints a case by its name, not its bytes.
void PrintTo(const BadScene& c, std::ostream* os) { *os << c.name; }

class MalformedScene : public ::testing::TestWithParam<BadScene> {};

TEST_P(MalformedScene, IsRefusedWithFilePathAndReason) {
    const BadScene& c = GetParam();
    const std::string file = std::string("malformed/") + c.name + ".json";
    try {
        pfs::parse_scene(c.text, file);
        ADD_FAILURE() << "accepted";
    } catch (const pfs::Error& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind(file + ": ", 0), 0u) << "does not start with the file name: " << msg;
        EXPECT_EQ(msg.find(file, 1), std::string::npos) << "a report wrapped in another: " << msg;
        EXPECT_NE(msg.find(": " + c.pointer + ": "), std::string::npos) << "no JSON path " << c.pointer << ": " << msg;
        EXPECT_NE(msg.find(c.reason), std::string::npos) << "no reason '" << c.reason << "': " << msg;
        // The value is never re-serialised into the message (a nested one could be huge).
        EXPECT_LT(msg.size(), 400u) << msg;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "escaped as a bare " << typeid(e).name() << ": " << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Table, MalformedScene, ::testing::ValuesIn(bad_scenes()),
                         [](const ::testing::TestParamInfo<BadScene>& i) { return std::string(i.param.name); });

TEST(SceneLoader, EveryShippedSceneLoads) {
    size_t n = 0;
    for (const auto& entry : std::filesystem::directory_iterator(PF_TEST_SCENES_DIR)) {
        if (entry.path().extension() != ".json") continue;
        ++n;
        EXPECT_NO_THROW({
            const pfs::Scene s = pfs::load_scene(entry.path().string());
            EXPECT_FALSE(s.name.empty());
            EXPECT_TRUE(!s.boxes.empty() || !s.emitters.empty()) << entry.path() << ": no liquid and no emitter";
        }) << entry.path();
    }
    EXPECT_GE(n, 1u) << "no scenes in " << PF_TEST_SCENES_DIR;
}

// The combined effects scene names every effect and carries one object of each, read into the
// pf_* structs with defaults where the file is silent; the preset applies before "params".
TEST(SceneLoader, EffectsSceneCarriesEveryEffectsObjects) {
    const pfs::Scene s = pfs::load_scene(std::string(PF_TEST_SCENES_DIR) + "/fountain_pool.json");
    EXPECT_EQ(s.features, uint32_t(PF_FEATURE_FORCE_FIELDS | PF_FEATURE_OBSTACLES | PF_FEATURE_EMITTERS | PF_FEATURE_SINKS));
    ASSERT_EQ(s.force_fields.size(), 1u);
    ASSERT_EQ(s.obstacles.size(), 1u);
    ASSERT_EQ(s.emitters.size(), 1u);
    ASSERT_EQ(s.sinks.size(), 1u);
    EXPECT_EQ(s.force_fields[0].type, PF_FORCE_FIELD_DIRECTIONAL);
    EXPECT_FLOAT_EQ(s.force_fields[0].drag, 0.3f);
    EXPECT_EQ(s.obstacles[0].shape, PF_OBSTACLE_BOX);
    EXPECT_FLOAT_EQ(s.obstacles[0].half_extents[1], 0.1f);
    EXPECT_EQ(s.emitters[0].shape, PF_EMITTER_DISC);
    EXPECT_EQ(s.emitters[0].rate_unit, PF_RATE_VOLUME_PER_SECOND);
    EXPECT_FLOAT_EQ(s.emitters[0].velocity[1], 3.2f);
    EXPECT_FLOAT_EQ(s.emitters[0].rotation[3], 1.0f);  // pf_default_emitter's identity
    EXPECT_EQ(s.sinks[0].shape, PF_SINK_BOX);
    EXPECT_TRUE(s.has_preset);
    EXPECT_EQ(s.preset, PF_QUALITY_FAST);
    const pfs::Scene b = pfs::parse_scene(
        R"({"grid": {"size": [4, 4, 4], "cell_size": 0.1}, "max_particles": 10, "preset": "balanced",
            "params": {"pressure_tolerance": 0.01, "transfer": "apic", "advection": "leapfrog"}})", "preset.json");
    EXPECT_EQ(b.params.pressure_solver, PF_PRESSURE_SOLVER_MGPCG);
    EXPECT_FLOAT_EQ(b.params.pressure_tolerance, 0.01f);
    EXPECT_EQ(b.params.transfer, PF_TRANSFER_APIC);
    EXPECT_EQ(b.params.advection, PF_ADVECTION_LEAPFROG);
}

// The viscosity scene pours from its emitter with the viscosity it names; a viscosity object
// starts from pf_default_viscosity() and takes only the keys given (the ranges are the library's
// to check when the scene is created).
TEST(SceneLoader, ViscositySceneCarriesItsViscosity) {
    const pfs::Scene s = pfs::load_scene(std::string(PF_TEST_SCENES_DIR) + "/effects_viscosity.json");
    EXPECT_EQ(s.features, uint32_t(PF_FEATURE_EMITTERS | PF_FEATURE_VISCOSITY));
    ASSERT_EQ(s.emitters.size(), 1u);
    EXPECT_TRUE(s.has_viscosity);
    EXPECT_EQ(s.viscosity.struct_size, uint32_t(sizeof(pf_viscosity)));
    EXPECT_FLOAT_EQ(s.viscosity.viscosity, 200.0f);
    EXPECT_EQ(s.viscosity.iterations, 60u);
    EXPECT_FLOAT_EQ(s.viscosity.tolerance, 1e-3f);
    EXPECT_EQ(s.viscosity.free_slip, 0u);
    EXPECT_EQ(s.viscosity.coupling_rounds, 1u);
    const pfs::Scene b = pfs::parse_scene(
        with(R"("features": ["viscosity"], "viscosity": {"iterations": 5000, "free_slip": true, "coupling_rounds": 40})"),
        "v.json");
    const pf_viscosity d = pf_default_viscosity();
    EXPECT_TRUE(b.has_viscosity);
    EXPECT_EQ(b.viscosity.iterations, 5000u);  // out of range: refused later, by pf_set_viscosity
    EXPECT_EQ(b.viscosity.free_slip, 1u);
    EXPECT_EQ(b.viscosity.coupling_rounds, 40u);  // out of range: refused later, as iterations
    EXPECT_EQ(b.viscosity.viscosity, d.viscosity);
    EXPECT_EQ(b.viscosity.tolerance, d.tolerance);
    EXPECT_FALSE(pfs::parse_scene(kValid, "none.json").has_viscosity);
}

// The surface tension scene is a cube of liquid in zero gravity with the tension it names; a
// surface_tension object starts from pf_default_surface_tension() and takes only the keys given
// (the range, 0..1000 N/m, is the library's to check when the scene is created).
TEST(SceneLoader, SurfaceTensionSceneCarriesItsTension) {
    const pfs::Scene s = pfs::load_scene(std::string(PF_TEST_SCENES_DIR) + "/effects_surface_tension.json");
    EXPECT_EQ(s.features, uint32_t(PF_FEATURE_SURFACE_TENSION));
    ASSERT_EQ(s.boxes.size(), 1u);
    for (int a = 0; a < 3; ++a) EXPECT_EQ(s.params.gravity[a], 0.0f) << a;
    EXPECT_FLOAT_EQ(s.cell_size, 0.01f);
    EXPECT_TRUE(s.has_surface_tension);
    EXPECT_EQ(s.surface_tension.struct_size, uint32_t(sizeof(pf_surface_tension)));
    EXPECT_FLOAT_EQ(s.surface_tension.tension, 12.5f);
    const pfs::Scene b = pfs::parse_scene(
        with(R"("features": ["surface_tension"], "surface_tension": {"tension": 5000})"), "t.json");
    EXPECT_TRUE(b.has_surface_tension);
    EXPECT_EQ(b.surface_tension.tension, 5000.0f);  // out of range: refused later, by pf_set_surface_tension
    const pfs::Scene c = pfs::parse_scene(with(R"("features": ["surface_tension"], "surface_tension": {})"), "t.json");
    EXPECT_TRUE(c.has_surface_tension);
    EXPECT_EQ(c.surface_tension.tension, pf_default_surface_tension().tension);
    // The feature alone, without the object, leaves the library's default in place.
    const pfs::Scene d = pfs::parse_scene(with(R"("features": ["surface_tension"])"), "t.json");
    EXPECT_EQ(d.features, uint32_t(PF_FEATURE_SURFACE_TENSION));
    EXPECT_FALSE(d.has_surface_tension);
    EXPECT_FALSE(pfs::parse_scene(kValid, "none.json").has_surface_tension);
}

TEST(SceneLoader, EdgesOfFloatRangeLoadExactly) {
    // The largest float and a subnormal are representable: they load as themselves.
    const pfs::Scene s = pfs::parse_scene(
        R"({"grid": {"size": [4, 4, 4], "cell_size": 0.1, "origin": [3.4028234663852886e38, -3.4028234663852886e38, 1e-40]},
            "max_particles": 1})",
        "edges.json");
    EXPECT_EQ(s.origin[0], std::numeric_limits<float>::max());
    EXPECT_EQ(s.origin[1], -std::numeric_limits<float>::max());
    EXPECT_EQ(s.origin[2], 1e-40f);
    EXPECT_GT(s.origin[2], 0.0f);
}

TEST(SceneLoader, CommentsAndUnderscoreKeysAreAllowed) {
    const pfs::Scene s = pfs::parse_scene("// a comment\n" + with(R"("_note": [[[1]]], "frames": 7)"), "c.json");
    EXPECT_EQ(s.frames, 7u);
}

TEST(SceneLoader, MissingFileIsNamed) {
    try {
        pfs::load_scene("/nonexistent/dir/scene.json");
        ADD_FAILURE() << "accepted";
    } catch (const pfs::Error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scene.json: cannot open"), std::string::npos) << e.what();
    }
}

} // namespace
