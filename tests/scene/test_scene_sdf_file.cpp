// SDF obstacles' .npy files in scene files (samples/common/sdf_file.h): the shipped bowl loads
// with its size and the distances its generator computes (axis order included: the grid is not
// a cube and the bowl is not symmetric in y), a float32 file written here loads exactly, and
// each malformed file is refused with a message naming the scene, the obstacle's JSON Pointer,
// the .npy file and the reason. The files are written in the test's temporary folder. No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "scene.h"
#include "sdf_file.h"
#include "util.h"

namespace {

namespace fs = std::filesystem;

// The bowl of samples/tools/make_sdf_bowl.py, in double precision.
double bowl_distance(double x, double y, double z) {
    const double rho = std::hypot(x, z), yc = y - 0.08;
    if (yc <= 0) return std::abs(std::hypot(rho, yc) - 0.23) - 0.04;
    return std::hypot(std::max(std::abs(rho - 0.23) - 0.04, 0.0), yc);
}

// An .npy file as numpy.save writes it: magic, version, little-endian header length, the dict
// padded with spaces to a multiple of 64 bytes and ended by '\n', then `data`.
std::string npy(const std::string& dict, const std::string& data, int major = 1) {
    const size_t prefix = major == 1 ? 10 : 12;
    std::string header = dict;
    while ((prefix + header.size() + 1) % 64) header += ' ';
    header += '\n';
    std::string out = std::string("\x93NUMPY", 6) + char(major) + char(0);
    for (size_t b = 0; b < prefix - 8; ++b) out += char((header.size() >> (8 * b)) & 0xff);
    return out + header + data;
}

std::string dict(const std::string& descr, const std::string& shape, const char* fortran = "False") {
    return "{'descr': '" + descr + "', 'fortran_order': " + fortran + ", 'shape': " + shape + ", }";
}

std::string floats(const std::vector<float>& v) {
    std::string s(v.size() * 4, '\0');
    std::memcpy(s.data(), v.data(), s.size());  // the tests run on little-endian hosts (x86, arm)
    return s;
}

// A 4 x 3 x 2 float32 grid whose value tells its index: a[i, j, k] = 100 i + 10 j + k.
std::vector<float> indexed_grid() {
    std::vector<float> v;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 2; ++k) v.push_back(float(100 * i + 10 * j + k));
    return v;
}

class SdfFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(::testing::TempDir()) / ("pf_scene_sdf_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    // Writes `bytes` as `name` in the folder and a scene there whose one obstacle loads it.
    std::string scene_with(const std::string& name, const std::string& bytes) {
        std::ofstream(dir_ / name, std::ios::binary) << bytes;
        const fs::path scene = dir_ / "scene.json";
        std::ofstream(scene) << R"({"grid": {"size": [4, 4, 4], "cell_size": 0.1}, "max_particles": 10,
            "features": ["obstacles"], "obstacles": [{"shape": "sphere"},
              {"shape": "sdf", "file": ")" + name + R"(", "half_extents": [0.2, 0.15, 0.1]}]})";
        return scene.string();
    }

    fs::path dir_;
};

TEST(SceneSdf, ShippedBowlLoadsWithItsSizeAndDistances) {
    const pfs::Scene s = pfs::load_scene(std::string(PF_TEST_SCENES_DIR) + "/effects_sdf.json");
    ASSERT_EQ(s.obstacles.size(), 1u);
    ASSERT_EQ(s.obstacle_sdf.size(), 1u);
    EXPECT_EQ(s.obstacles[0].shape, PF_OBSTACLE_SDF);
    EXPECT_FLOAT_EQ(s.obstacles[0].sdf_scale, 1.0f);
    EXPECT_EQ(s.obstacles[0].sdf_texture, 0u) << "no GL name before add_scene_effects";
    const double h[3] = {0.32, 0.2, 0.32};
    for (int a = 0; a < 3; ++a) EXPECT_FLOAT_EQ(s.obstacles[0].half_extents[a], float(h[a]));
    ASSERT_TRUE(s.obstacle_sdf[0]);
    const pfs::SdfGrid& g = *s.obstacle_sdf[0];
    EXPECT_EQ(g.size[0], 32u);
    EXPECT_EQ(g.size[1], 20u);
    EXPECT_EQ(g.size[2], 32u);
    EXPECT_EQ(g.precision, pfs::SdfGrid::Precision::float16);
    ASSERT_EQ(g.values.size(), size_t(32) * 20 * 32);
    // Every sample against the generator's formula; float16 rounds these (|d| < 0.5 m) by at
    // most half a unit in the last place, 2^-13 m.
    double worst = 0;
    for (uint32_t k = 0; k < g.size[2]; ++k)
        for (uint32_t j = 0; j < g.size[1]; ++j)
            for (uint32_t i = 0; i < g.size[0]; ++i) {
                const double p[3] = {-h[0] + (i + 0.5) * 0.02, -h[1] + (j + 0.5) * 0.02, -h[2] + (k + 0.5) * 0.02};
                worst = std::max(worst, std::abs(g.at(i, j, k) - bowl_distance(p[0], p[1], p[2])));
            }
    EXPECT_LE(worst, 1.23e-4) << "largest difference from the bowl's distance, m";
    // Inside the wall at the bottom (i, k central; j = 2: y = -0.15), open air above the rim.
    EXPECT_LT(g.at(16, 2, 16), -0.02f);
    EXPECT_GT(g.at(16, 19, 16), 0.1f);
}

TEST_F(SdfFiles, Float32FileLoadsInItsAxisOrder) {
    const std::string scene = scene_with("grid.npy", npy(dict("<f4", "(4, 3, 2)"), floats(indexed_grid())));
    const pfs::Scene s = pfs::load_scene(scene);
    ASSERT_EQ(s.obstacle_sdf.size(), 2u);
    EXPECT_FALSE(s.obstacle_sdf[0]) << "a sphere has no grid";
    ASSERT_TRUE(s.obstacle_sdf[1]);
    const pfs::SdfGrid& g = *s.obstacle_sdf[1];
    EXPECT_EQ(g.precision, pfs::SdfGrid::Precision::float32);
    ASSERT_EQ(g.size[0], 4u);
    ASSERT_EQ(g.size[1], 3u);
    ASSERT_EQ(g.size[2], 2u);
    for (uint32_t i = 0; i < 4; ++i)
        for (uint32_t j = 0; j < 3; ++j)
            for (uint32_t k = 0; k < 2; ++k) EXPECT_EQ(g.at(i, j, k), float(100 * i + 10 * j + k)) << i << j << k;
    EXPECT_EQ(g.values[1], 100.0f) << "x varies fastest in memory (a GL texture's order)";
    // Format 2.0 (a 4-byte header length) reads the same.
    const pfs::Scene v2 = pfs::load_scene(scene_with("v2.npy", npy(dict("<f4", "(4, 3, 2)"), floats(indexed_grid()), 2)));
    EXPECT_EQ(v2.obstacle_sdf[1]->values, g.values);
}

TEST_F(SdfFiles, AbsolutePathsAreTakenAsGiven) {
    const fs::path file = dir_ / "absolute.npy";
    std::ofstream(file, std::ios::binary) << npy(dict("<f4", "(4, 3, 2)"), floats(indexed_grid()));
    const pfs::Scene s = pfs::parse_scene(
        R"({"grid": {"size": [4, 4, 4], "cell_size": 0.1}, "max_particles": 10, "features": ["obstacles"],
            "obstacles": [{"shape": "sdf", "file": ")" + file.string() + R"(", "half_extents": [1, 1, 1]}]})",
        "elsewhere/scene.json");
    ASSERT_TRUE(s.obstacle_sdf[0]);
    EXPECT_EQ(s.obstacle_sdf[0]->size[0], 4u);
}

struct BadFile {
    const char* name;
    std::string bytes;
    std::string reason;  // a piece of the message
};

std::vector<BadFile> bad_files() {
    const std::string good = floats(indexed_grid());
    std::string nan = good, inf16(2 * 8, '\0');
    const float not_a_number = NAN;
    std::memcpy(&nan[4 * 7], &not_a_number, 4);
    inf16[2 * 5] = '\x00', inf16[2 * 5 + 1] = '\x7c';  // float16 +Inf: 0x7c00
    const std::string g3 = dict("<f4", "(4, 3, 2)");
    std::string no_newline = npy(g3, good);
    no_newline[no_newline.find('\n')] = ' ';
    return {
        {"empty", "", "is not a NumPy .npy file"},
        {"wrong_magic", "\x93NUMPZ" + npy(g3, good).substr(6), "is not a NumPy .npy file"},
        {"text_file", "{\"shape\": [4, 3, 2]}", "is not a NumPy .npy file"},
        {"version_3", npy(g3, good, 3), "format version 3.0"},
        {"truncated_length", std::string("\x93NUMPY\x01\x00\x46", 9), "truncated inside its header length"},
        {"truncated_header", npy(g3, good).substr(0, 40), "truncated inside its header"},
        {"header_without_newline", no_newline, "does not end in a newline"},
        {"dtype_float64", npy(dict("<f8", "(4, 3, 2)"), good + good), "dtype '<f8'"},
        {"dtype_int32", npy(dict("<i4", "(4, 3, 2)"), good), "dtype '<i4'"},
        {"big_endian", npy(dict(">f4", "(4, 3, 2)"), good), "big-endian"},
        {"fortran_order", npy(dict("<f4", "(4, 3, 2)", "True"), good), "Fortran order"},
        {"two_dimensional", npy(dict("<f4", "(6, 4)"), good), "has shape (6, 4); an SDF grid is a 3-D array"},
        {"four_dimensional", npy(dict("<f4", "(2, 2, 3, 2)"), good), "a 3-D array"},
        {"size_zero", npy(dict("<f4", "(0, 3, 2)"), ""), "each size must be in [2, 256]"},
        {"size_one", npy(dict("<f4", "(1, 3, 2)"), good.substr(0, 24)), "each size must be in [2, 256]"},
        {"too_large", npy(dict("<f4", "(257, 2, 2)"), ""), "has shape (257, 2, 2); each size must be in [2, 256]"},
        {"size_beyond_any_grid", npy(dict("<f4", "(99999999999999999999, 2, 2)"), ""), "beyond any grid"},
        {"truncated_data", npy(g3, good.substr(0, 90)), "is truncated: shape (4, 3, 2) needs"},
        {"data_after_array", npy(g3, good + "xx"), "2 bytes after the array's data"},
        {"nan_value", npy(g3, nan), "non-finite value at [1, 0, 1]"},
        {"float16_infinity", npy(dict("<f2", "(2, 2, 2)"), inf16), "non-finite value at [1, 0, 1]"},
        {"header_unknown_key", npy("{'descr': '<f4', 'fortran_order': False, 'shape': (4, 3, 2), 'x': 1}", good),
         "unknown key 'x'"},
        {"header_missing_shape", npy("{'descr': '<f4', 'fortran_order': False}", good), "lacks 'shape'"},
        {"header_duplicate_key", npy("{'descr': '<f4', 'descr': '<f4', 'fortran_order': False, 'shape': (4, 3, 2)}", good),
         "'descr' twice"},
        {"header_not_a_dict", npy("[1, 2, 3]", good), "is not an .npy dictionary"},
        {"header_shape_not_integers", npy(dict("<f4", "(4.0, 3, 2)"), good), "expected ')'"},
    };
}

void PrintTo(const BadFile& c, std::ostream* os) { *os << c.name; }

class MalformedSdfFile : public SdfFiles, public ::testing::WithParamInterface<BadFile> {};

TEST_P(MalformedSdfFile, IsRefusedNamingSceneObstacleFileAndReason) {
    const BadFile& c = GetParam();
    const std::string file = std::string(c.name) + ".npy";
    const std::string scene = scene_with(file, c.bytes);
    try {
        pfs::load_scene(scene);
        ADD_FAILURE() << "accepted";
    } catch (const pfs::Error& e) {
        const std::string msg = e.what();
        const std::string expected_start = scene + ": /obstacles/1/file: " + (dir_ / file).string() + ": ";
        EXPECT_EQ(msg.rfind(expected_start, 0), 0u) << "does not start with scene, pointer and file: " << msg;
        EXPECT_NE(msg.find(c.reason), std::string::npos) << "no reason '" << c.reason << "': " << msg;
        EXPECT_LT(msg.size(), 400u + expected_start.size()) << msg;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "escaped as a bare " << typeid(e).name() << ": " << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Table, MalformedSdfFile, ::testing::ValuesIn(bad_files()),
                         [](const ::testing::TestParamInfo<BadFile>& i) { return std::string(i.param.name); });

TEST_F(SdfFiles, AFolderIsNotAFile) {
    fs::create_directories(dir_ / "folder.npy");
    const fs::path scene = dir_ / "scene.json";
    std::ofstream(scene) << R"({"grid": {"size": [4, 4, 4], "cell_size": 0.1}, "max_particles": 10,
        "features": ["obstacles"], "obstacles": [{"shape": "sdf", "file": "folder.npy", "half_extents": [1, 1, 1]}]})";
    try {
        pfs::load_scene(scene.string());
        ADD_FAILURE() << "accepted";
    } catch (const pfs::Error& e) {
        EXPECT_NE(std::string(e.what()).find("/obstacles/0/file: " + (dir_ / "folder.npy").string() + ": is not a regular file"),
                  std::string::npos)
            << e.what();
    }
}

} // namespace
