// pf_vdb_check — reads the .vdb files of pflip's OpenVDB export (samples/common/vdb_write.h,
// pf_headless --export-vdb) back with OpenVDB's reader, the way Blender and Houdini do, and checks
// them against the particles they came from (a PLY written in the same run, read here with this
// file's own reader).
//
//   pf_vdb_check volume FILE.vdb --cell H [--particles-per-cell K] (--particles N | --ply FILE.ply)
//       the grids "surface" (FloatGrid, level set), "density" (FloatGrid, fog volume) and
//       "velocity" (Vec3SGrid), each once; the liquid volume, from the level set's interior
//       (voxels < 0) and from the density's sum, within --volume-tolerance (default 0.15) of the
//       particles' own N / K × H³; density within 0..1. With --ply also: at least
//       --inside-fraction (default 0.9) of the particles inside the surface, and every velocity
//       voxel the mean of the particles in it (so its particle-weighted mean is theirs).
//   pf_vdb_check points FILE.vdb --ply FILE.ply
//       one PointDataGrid "points" with a position "P" (32-bit floats, no quantisation) and a
//       Vec3f "v"; as many points as the PLY has vertices, each matching a distinct vertex:
//       position within 1e-5 of a voxel, velocity within 1e-6 (relative).
//   pf_vdb_check selftest --dir DIR
//       writes a known particle set (a 0.4 m cube, 8 particles a cell on a lattice, a known
//       velocity field) with the export into DIR, checks it as above, and checks that the checks
//       fail on wrong data and that the export and the reader fail cleanly on bad paths and files.
// Exit status 0 when everything passes; otherwise 1 with the reason on stderr.

#include "ply_write.h"
#include "vdb_write.h"

#include <CLI/CLI.hpp>
#include <openvdb/openvdb.h>
#include <openvdb/points/PointCount.h>
#include <openvdb/points/PointDataGrid.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetMeasure.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Particles {
    std::vector<float> xyz, vel; // 3n each
    size_t size() const { return xyz.size() / 3; }
    openvdb::Vec3d pos(size_t i) const { return openvdb::Vec3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); }
    openvdb::Vec3d v(size_t i) const { return openvdb::Vec3d(vel[3 * i], vel[3 * i + 1], vel[3 * i + 2]); }
};

// ---- PLY (x y z vx vy vz floats, binary_little_endian or ascii, as ply_write.h writes) ------

std::string read_ply(const std::string& path, Particles& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "cannot open " + path;
    std::string line;
    if (!std::getline(in, line) || line != "ply") return path + ": first line is not 'ply'";
    bool binary = false, have_format = false, ended = false;
    uint64_t count = 0;
    std::vector<std::string> properties;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string key;
        words >> key;
        if (key == "end_header") {
            ended = true;
            break;
        } else if (key == "format") {
            std::string fmt, version;
            words >> fmt >> version;
            if (fmt == "binary_little_endian") binary = true;
            else if (fmt != "ascii") return path + ": format '" + fmt + "' is neither binary_little_endian nor ascii";
            have_format = true;
        } else if (key == "element") {
            std::string name;
            words >> name >> count;
            if (name != "vertex") return path + ": element '" + name + "', expected only vertex";
        } else if (key == "property") {
            std::string type, name;
            words >> type >> name;
            if (type != "float" && type != "float32") return path + ": property " + name + " is not a float";
            properties.push_back(name);
        } else if (key != "comment" && key != "obj_info") {
            return path + ": unknown header line '" + line + "'";
        }
    }
    if (!ended || !have_format) return path + ": incomplete header";
    if (properties != std::vector<std::string>{"x", "y", "z", "vx", "vy", "vz"})
        return path + ": vertex properties are not x y z vx vy vz";
    std::vector<float> values(6 * size_t(count));
    if (binary) {
        std::vector<unsigned char> bytes(values.size() * 4);
        in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
        if (size_t(in.gcount()) != bytes.size()) return path + ": binary data shorter than the header says";
        for (size_t i = 0; i < values.size(); ++i) {
            const unsigned char* b = &bytes[4 * i];
            const uint32_t bits = uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
            std::memcpy(&values[i], &bits, 4);
        }
    } else {
        for (float& v : values)
            if (!(in >> v)) return path + ": ascii data shorter than the header says";
    }
    out.xyz.resize(3 * size_t(count));
    out.vel.resize(3 * size_t(count));
    for (size_t i = 0; i < count; ++i)
        for (int k = 0; k < 3; ++k) {
            out.xyz[3 * i + k] = values[6 * i + k];
            out.vel[3 * i + k] = values[6 * i + 3 + k];
        }
    return "";
}

// ---- reading a .vdb ------------------------------------------------------------------------

// Every grid of the file, read in full (no delayed loading), or why not.
std::string read_vdb(const std::string& path, openvdb::GridPtrVec& grids) {
    try {
        openvdb::io::File file(path);
        file.open(/*delayLoad=*/false);
        grids = *file.getGrids();
        file.close();
    } catch (const std::exception& e) {
        // A damaged file can put its garbage into the message (a grid type name): keep it short.
        std::string what;
        for (const char* c = e.what(); *c && what.size() < 160; ++c)
            if (!(*c == ' ' && !what.empty() && what.back() == ' ')) what += std::isprint((unsigned char)*c) ? *c : '?';
        return path + ": cannot read: " + what;
    }
    return "";
}

// The one grid called name, of type GridT, or why not.
template <typename GridT>
std::string find_grid(const openvdb::GridPtrVec& grids, const std::string& name, typename GridT::Ptr& out) {
    int found = 0;
    for (const openvdb::GridBase::Ptr& g : grids)
        if (g && g->getName() == name) {
            ++found;
            out = openvdb::gridPtrCast<GridT>(g);
            if (!out)
                return "grid '" + name + "' is a " + g->valueType() + " grid, expected " +
                       openvdb::typeNameAsString<typename GridT::ValueType>();
        }
    if (found != 1) return std::to_string(found) + " grids named '" + name + "', expected 1";
    if (!out->hasUniformVoxels()) return "grid '" + name + "' has non-uniform voxels";
    return "";
}

std::string grid_names(const openvdb::GridPtrVec& grids) {
    std::string s;
    for (const openvdb::GridBase::Ptr& g : grids)
        s += (s.empty() ? "" : ", ") + g->getName() + " (" + g->valueType() + ", " +
             openvdb::GridBase::gridClassToString(g->getGridClass()) + ")";
    return s;
}

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

std::string str(const openvdb::Coord& c) {
    std::ostringstream os;
    os << c;
    return os.str();
}

struct CoordLess {
    bool operator()(const openvdb::Coord& a, const openvdb::Coord& b) const { return a < b; }
};

// ---- volume --------------------------------------------------------------------------------

struct VolumeExpect {
    uint64_t particles = 0;
    double cell = 0, particles_per_cell = 8;
    double volume_tolerance = 0.15, inside_fraction = 0.9;
    const Particles* ply = nullptr; // optional
};

std::string check_volume(const std::string& path, const VolumeExpect& e) {
    openvdb::GridPtrVec grids;
    std::string err = read_vdb(path, grids);
    if (!err.empty()) return err;
    std::printf("  %s: grids %s\n", path.c_str(), grid_names(grids).c_str());
    openvdb::FloatGrid::Ptr surface, density;
    openvdb::Vec3SGrid::Ptr velocity;
    if (!(err = find_grid<openvdb::FloatGrid>(grids, "surface", surface)).empty() ||
        !(err = find_grid<openvdb::FloatGrid>(grids, "density", density)).empty() ||
        !(err = find_grid<openvdb::Vec3SGrid>(grids, "velocity", velocity)).empty())
        return path + ": " + err;
    if (surface->getGridClass() != openvdb::GRID_LEVEL_SET) return path + ": 'surface' is not a level set";
    if (density->getGridClass() != openvdb::GRID_FOG_VOLUME) return path + ": 'density' is not a fog volume";
    if (!(surface->background() > 0)) return path + ": 'surface' has no narrow band (background <= 0)";

    // The liquid volume, twice: the level set's (OpenVDB's measure, which smooths the sign over
    // a voxel, where counting voxels < 0 is off by up to a voxel layer), the density's sum.
    const double dx = surface->voxelSize()[0], dd = density->voxelSize()[0];
    uint64_t inside = 0;
    for (auto it = surface->tree().cbeginValueAll(); it; ++it)
        if (*it < 0) inside += it.getVoxelCount();
    const double v_surface = surface->tree().empty() ? 0.0 : openvdb::tools::levelSetVolume(*surface);
    double fog = 0;
    for (auto it = density->tree().cbeginValueOn(); it; ++it) {
        if (!(*it >= 0 && *it <= 1)) return path + ": a density value outside 0..1: " + num(*it);
        fog += double(*it) * double(it.getVoxelCount());
    }
    const double expected = double(e.particles) / e.particles_per_cell * std::pow(e.cell, 3);
    const double v_density = fog * dd * dd * dd;
    auto off = [expected](double v) { return expected > 0 ? 100 * (v / expected - 1) : 0.0; };
    std::printf("  liquid volume: particles %.6g m3, surface %.6g m3 (%+.2f%%), density sum %.6g m3 (%+.2f%%), "
                "voxels < 0 %.6g m3 (%+.2f%%); voxels %.4g m\n",
                expected, v_surface, off(v_surface), v_density, off(v_density), double(inside) * dx * dx * dx,
                off(double(inside) * dx * dx * dx), dx);
    for (const auto& [what, v] : {std::pair<const char*, double>{"surface", v_surface}, {"density sum", v_density}}) {
        if (expected == 0 ? v != 0 : std::abs(v / expected - 1) > e.volume_tolerance)
            return path + ": the " + what + " volume " + num(v) + " m3 is not within " + num(100 * e.volume_tolerance) +
                   "% of the particles' " + num(expected) + " m3";
    }

    const uint64_t vel_voxels = velocity->activeVoxelCount();
    openvdb::Vec3d grid_mean(0.0);
    for (auto it = velocity->tree().cbeginValueOn(); it; ++it)
        grid_mean += openvdb::Vec3d(*it) * double(it.getVoxelCount());
    if (vel_voxels > 0) grid_mean /= double(vel_voxels);
    std::printf("  velocity: %llu voxels of %.4g m, mean over voxels (%.5g, %.5g, %.5g) m/s\n",
                static_cast<unsigned long long>(vel_voxels), velocity->voxelSize()[0], grid_mean.x(), grid_mean.y(),
                grid_mean.z());
    if ((vel_voxels == 0) != (e.particles == 0))
        return path + ": " + std::to_string(vel_voxels) + " velocity voxels for " + std::to_string(e.particles) +
               " particles";
    if (!e.ply) return "";

    // With the particles: where they are lies inside the surface (a misplaced or mis-scaled grid
    // would keep its volume but not this) ...
    const Particles& ply = *e.ply;
    const size_t n = ply.size();
    openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sampler(*surface);
    size_t in_liquid = 0;
    for (size_t i = 0; i < n; ++i)
        if (sampler.wsSample(ply.pos(i)) < 0) ++in_liquid;
    const double fraction = n ? double(in_liquid) / double(n) : 1.0;
    std::printf("  particles inside the surface: %zu of %zu (%.2f%%)\n", in_liquid, n, 100 * fraction);
    if (fraction < e.inside_fraction)
        return path + ": only " + num(100 * fraction) + "% of the particles lie inside the surface, expected " +
               num(100 * e.inside_fraction) + "%";

    // ... and every velocity voxel is the mean of the particles in it, binned here afresh.
    std::map<openvdb::Coord, std::pair<openvdb::Vec3d, uint64_t>, CoordLess> bins;
    openvdb::Vec3d particle_mean(0.0);
    double vmax = 0;
    for (size_t i = 0; i < n; ++i) {
        auto& bin = bins[velocity->transform().worldToIndexCellCentered(ply.pos(i))];
        bin.first += ply.v(i);
        ++bin.second;
        particle_mean += ply.v(i);
        vmax = std::max(vmax, ply.v(i).length());
    }
    if (n) particle_mean /= double(n);
    if (bins.size() != vel_voxels)
        return path + ": " + std::to_string(vel_voxels) + " velocity voxels, but the particles occupy " +
               std::to_string(bins.size());
    const double tol = 1e-5 * (1 + vmax);
    openvdb::Vec3d weighted(0.0);
    auto acc = velocity->getConstAccessor();
    for (const auto& [ijk, bin] : bins) {
        openvdb::Vec3s value;
        if (!acc.probeValue(ijk, value)) return path + ": no velocity at voxel " + str(ijk) + ", which holds particles";
        const openvdb::Vec3d mean = bin.first / double(bin.second);
        if ((openvdb::Vec3d(value) - mean).length() > tol)
            return path + ": velocity voxel " + str(ijk) + " holds " + value.str() + ", its particles' mean is " +
                   mean.str();
        weighted += openvdb::Vec3d(value) * double(bin.second);
    }
    if (n) weighted /= double(n);
    std::printf("  velocity weighted by particles (%.6g, %.6g, %.6g) m/s, particles' mean (%.6g, %.6g, %.6g) m/s\n",
                weighted.x(), weighted.y(), weighted.z(), particle_mean.x(), particle_mean.y(), particle_mean.z());
    if ((weighted - particle_mean).length() > tol) return path + ": the velocity grid's mean is not the particles'";
    return "";
}

// ---- points --------------------------------------------------------------------------------

std::string check_points(const std::string& path, const Particles& ply) {
    openvdb::GridPtrVec grids;
    std::string err = read_vdb(path, grids);
    if (!err.empty()) return err;
    std::printf("  %s: grids %s\n", path.c_str(), grid_names(grids).c_str());
    openvdb::points::PointDataGrid::Ptr grid;
    if (!(err = find_grid<openvdb::points::PointDataGrid>(grids, "points", grid)).empty()) return path + ": " + err;
    const size_t n = ply.size();
    const openvdb::Index64 count = openvdb::points::pointCount(grid->tree());
    const double dx = grid->voxelSize()[0];
    std::printf("  %llu points (the PLY: %zu), voxels %.4g m\n", static_cast<unsigned long long>(count), n, dx);
    if (count != n) return path + ": " + std::to_string(count) + " points, the PLY has " + std::to_string(n);

    // The PLY's particles sorted by the bucket (a voxel-sized cube) they fall in, for the lookup.
    const double tol_p = 1e-5 * dx;
    using Key = std::array<int64_t, 3>;
    auto key_of = [dx](const openvdb::Vec3d& p) {
        return Key{int64_t(std::floor(p.x() / dx)), int64_t(std::floor(p.y() / dx)), int64_t(std::floor(p.z() / dx))};
    };
    std::vector<std::pair<Key, uint32_t>> sorted(n);
    for (size_t i = 0; i < n; ++i) sorted[i] = {key_of(ply.pos(i)), uint32_t(i)};
    std::sort(sorted.begin(), sorted.end());
    std::vector<bool> used(n, false);

    double worst_p = 0, worst_v = 0;
    for (auto leaf = grid->tree().cbeginLeaf(); leaf; ++leaf) {
        const openvdb::points::AttributeSet::Descriptor& desc = leaf->attributeSet().descriptor();
        const size_t ip = desc.find("P"), iv = desc.find("v");
        if (ip == openvdb::points::AttributeSet::INVALID_POS || iv == openvdb::points::AttributeSet::INVALID_POS)
            return path + ": the points lack the attribute P or v";
        const openvdb::points::AttributeArray &pa = leaf->constAttributeArray(ip), &va = leaf->constAttributeArray(iv);
        if (pa.valueType() != "vec3s" || pa.codecType() != "null")
            return path + ": P is " + pa.valueType() + " with codec " + pa.codecType() + ", expected vec3s, null";
        if (va.valueType() != "vec3s") return path + ": v is " + va.valueType() + ", expected vec3s";
        openvdb::points::AttributeHandle<openvdb::Vec3f> ph(pa), vh(va);
        for (auto idx = leaf->beginIndexOn(); idx; ++idx) {
            const openvdb::Vec3d p =
                grid->transform().indexToWorld(openvdb::Vec3d(ph.get(*idx)) + idx.getCoord().asVec3d());
            const openvdb::Vec3d v(vh.get(*idx));
            // A distinct PLY vertex within the tolerances: look in every bucket p ± tol touches.
            const Key lo = key_of(p - openvdb::Vec3d(tol_p)), hi = key_of(p + openvdb::Vec3d(tol_p));
            bool matched = false;
            for (int64_t x = lo[0]; x <= hi[0] && !matched; ++x)
                for (int64_t y = lo[1]; y <= hi[1] && !matched; ++y)
                    for (int64_t z = lo[2]; z <= hi[2] && !matched; ++z) {
                        const Key k{x, y, z};
                        auto it = std::lower_bound(sorted.begin(), sorted.end(), std::make_pair(k, uint32_t(0)));
                        for (; it != sorted.end() && it->first == k && !matched; ++it) {
                            const uint32_t j = it->second;
                            const double dp = (ply.pos(j) - p).length(), dv = (ply.v(j) - v).length();
                            if (used[j] || dp > tol_p || dv > 1e-6 * (1 + v.length())) continue;
                            used[j] = matched = true;
                            worst_p = std::max(worst_p, dp);
                            worst_v = std::max(worst_v, dv);
                        }
                    }
            if (!matched)
                return path + ": the point at " + p.str() + " with v " + v.str() +
                       " matches no particle of the PLY (positions within " + num(tol_p) + " m)";
        }
    }
    std::printf("  every point matches a distinct particle: largest differences %.3g m (%.3g voxels), %.3g m/s\n",
                worst_p, worst_p / dx, worst_v);
    return "";
}

// ---- selftest ------------------------------------------------------------------------------

// A cube of side 0.4 m with its corner at lo, cells of h, 8 particles a cell on a lattice, the
// velocity (1, -2, 0.5) + 0.5 × (position - lo) m/s.
Particles lattice_cube(double h, const openvdb::Vec3d& lo) {
    Particles p;
    const double s = h / 2;
    const int per_side = int(std::lround(0.4 / s));
    for (int i = 0; i < per_side; ++i)
        for (int j = 0; j < per_side; ++j)
            for (int k = 0; k < per_side; ++k) {
                const openvdb::Vec3d x = lo + openvdb::Vec3d(i + 0.5, j + 0.5, k + 0.5) * s;
                const openvdb::Vec3d v = openvdb::Vec3d(1, -2, 0.5) + 0.5 * (x - lo);
                for (int c = 0; c < 3; ++c) {
                    p.xyz.push_back(float(x[c]));
                    p.vel.push_back(float(v[c]));
                }
            }
    return p;
}

int failures = 0;

void expect(bool ok, const std::string& what, const std::string& detail = "") {
    std::printf("%s %s%s%s\n", ok ? "ok  " : "FAIL", what.c_str(), detail.empty() ? "" : ": ", detail.c_str());
    if (!ok) ++failures;
}

// A check that must fail, and for the reason its message names.
void expect_fail(const std::string& err, const std::string& reason, const std::string& what) {
    expect(err.find(reason) != std::string::npos, what, err.empty() ? "it passed" : err);
}

int selftest(const std::string& dir_name) {
    namespace fs = std::filesystem;
    const fs::path dir(dir_name);
    std::error_code ec;
    fs::remove_all(dir, ec);
    fs::create_directories(dir);
    const double h = 0.05;
    const Particles cube = lattice_cube(h, openvdb::Vec3d(0.1, 0.2, 0.3));
    const uint32_t n = uint32_t(cube.size());
    std::string err;

    // The cube written as pf_headless writes a frame: PLY, volume, points.
    const std::string ply = (dir / "cube.ply").string(), volume = (dir / "cube_volume.vdb").string(),
                      points = (dir / "cube_points.vdb").string();
    pfs::VdbVolumeParams vp;
    vp.cell_size = float(h);
    expect(pfs::write_ply_particles(ply, cube.xyz.data(), cube.vel.data(), n, pfs::PlyFormat::binary_little_endian, ""),
           "write " + ply);
    expect(pfs::write_vdb_volume(volume, cube.xyz.data(), cube.vel.data(), n, vp, &err), "write " + volume, err);
    expect(pfs::write_vdb_points(points, cube.xyz.data(), cube.vel.data(), n, float(h), &err), "write " + points, err);
    Particles read;
    expect((err = read_ply(ply, read)).empty() && read.size() == n, "read " + ply + " back", err);

    VolumeExpect e;
    e.particles = n;
    e.cell = h;
    e.ply = &read;
    expect((err = check_volume(volume, e)).empty(), "the cube's volume file", err);
    expect((err = check_points(points, read)).empty(), "the cube's points file", err);
    // The known field's mean: (1, -2, 0.5) + 0.5 × the cube's half side.
    openvdb::Vec3d mean(0.0);
    for (size_t i = 0; i < n; ++i) mean += read.v(i);
    mean /= double(n);
    expect((mean - openvdb::Vec3d(1.1, -1.9, 0.6)).length() < 1e-5, "the particles' mean velocity is the field's",
           mean.str());

    // The checks can fail, each for its reason: a volume 40% off, a particle moved by 1e-3 of a
    // voxel, a changed velocity, a missing particle, particles away from the surface, wrong grids.
    VolumeExpect more = e;
    more.particles = n * 14 / 10;
    more.ply = nullptr;
    expect_fail(check_volume(volume, more), "is not within", "a 40% wrong particle count fails the volume check");
    Particles moved = read;
    moved.xyz[3 * 100 + 1] += float(1e-3 * h);
    expect_fail(check_points(points, moved), "matches no particle",
                "a particle moved by 1e-3 voxel fails the points check");
    Particles faster = read;
    faster.vel[3 * 7] += 1e-3f;
    expect_fail(check_points(points, faster), "matches no particle", "a velocity 1e-3 m/s off fails the points check");
    VolumeExpect faster_e = e;
    faster_e.ply = &faster;
    expect_fail(check_volume(volume, faster_e), "its particles' mean",
                "a velocity 1e-3 m/s off fails the volume check");
    Particles fewer = read;
    fewer.xyz.resize(fewer.xyz.size() - 3);
    fewer.vel.resize(fewer.vel.size() - 3);
    expect_fail(check_points(points, fewer), "the PLY has", "one particle fewer fails the points check");
    Particles shifted = read;
    for (size_t i = 0; i < n; ++i) shifted.xyz[3 * i] += 0.25f;
    VolumeExpect shifted_e = e;
    shifted_e.ply = &shifted;
    expect_fail(check_volume(volume, shifted_e), "lie inside the surface",
                "particles 0.25 m beside the surface fail the volume check");
    expect_fail(check_volume(points, e), "grids named 'surface'", "a points file fails the volume check");
    expect_fail(check_points(volume, read), "grids named 'points'", "a volume file fails the points check");

    // No particles: valid, empty files.
    const std::string empty_volume = (dir / "empty_volume.vdb").string(),
                      empty_points = (dir / "empty_points.vdb").string();
    expect(pfs::write_vdb_volume(empty_volume, nullptr, nullptr, 0, vp, &err), "write an empty volume", err);
    expect(pfs::write_vdb_points(empty_points, nullptr, nullptr, 0, float(h), &err), "write empty points", err);
    const Particles none;
    VolumeExpect empty_e;
    empty_e.cell = h;
    empty_e.ply = &none;
    expect((err = check_volume(empty_volume, empty_e)).empty(), "the empty volume file", err);
    expect((err = check_points(empty_points, none)).empty(), "the empty points file", err);

    // Failures are reported, never thrown: a missing directory, bad parameters, a full disk.
    const std::string missing = (dir / "no_such_dir" / "x.vdb").string();
    err.clear();
    expect(!pfs::write_vdb_volume(missing, cube.xyz.data(), cube.vel.data(), n, vp, &err) && !err.empty(),
           "a volume into a missing directory fails", err);
    err.clear();
    expect(!pfs::write_vdb_points(missing, cube.xyz.data(), cube.vel.data(), n, float(h), &err) && !err.empty(),
           "points into a missing directory fail", err);
    pfs::VdbVolumeParams bad;
    err.clear();
    expect(!pfs::write_vdb_volume(volume + ".bad", cube.xyz.data(), nullptr, n, bad, &err) && !err.empty(),
           "a volume without a cell size fails", err);
    Particles nan = read;
    nan.xyz[3 * 5 + 2] = std::nanf("");
    err.clear();
    expect(!pfs::write_vdb_volume(volume + ".nan", nan.xyz.data(), nan.vel.data(), n, vp, &err) &&
               err.find("particle 5 has a non-finite") != std::string::npos,
           "a NaN position fails the volume", err);
    err.clear();
    expect(!pfs::write_vdb_points(points + ".nan", nan.xyz.data(), nan.vel.data(), n, float(h), &err) &&
               err.find("particle 5 has a non-finite") != std::string::npos,
           "a NaN position fails the points", err);
    if (fs::exists("/dev/full")) {
        err.clear();
        expect(!pfs::write_vdb_points("/dev/full", cube.xyz.data(), cube.vel.data(), n, float(h), &err) && !err.empty(),
               "points onto a full disk (/dev/full) fail", err);
    }

    // Files that are not whole .vdb files are refused by the reader, not crashed on.
    const std::string garbage = (dir / "garbage.vdb").string(), truncated = (dir / "truncated.vdb").string();
    {
        std::ofstream(garbage, std::ios::binary) << "not a vdb file\n";
        std::ifstream in(volume, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ofstream(truncated, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 2));
    }
    expect_fail(check_volume(garbage, e), "cannot read", "a file that is no .vdb is refused");
    expect_fail(check_volume(truncated, e), "cannot read", "a truncated .vdb is refused");
    expect_fail(check_points(missing, read), "cannot read", "a missing .vdb is refused");

    std::printf("pf_vdb_check selftest: %s (%d failure%s)\n", failures ? "FAILED" : "passed", failures,
                failures == 1 ? "" : "s");
    return failures ? 1 : 0;
}

int fail(const std::string& why) {
    std::fprintf(stderr, "pf_vdb_check: %s\n", why.c_str());
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"pf_vdb_check: reads pflip's OpenVDB export back with OpenVDB and checks it against the particles"};
    app.require_subcommand(1);
    app.option_defaults()->always_capture_default(); // --help shows the defaults

    std::string volume_file, volume_ply;
    VolumeExpect expect_volume;
    CLI::App* volume = app.add_subcommand("volume", "check a volume file (surface, density, velocity)");
    volume->add_option("file", volume_file, "the .vdb file")->required();
    volume->add_option("--cell", expect_volume.cell, "the simulation's cell size, metres")->required()
        ->check(CLI::PositiveNumber);
    volume->add_option("--particles-per-cell", expect_volume.particles_per_cell, "the fill's particles per cell")
        ->check(CLI::PositiveNumber);
    CLI::Option* count_opt = volume->add_option("--particles", expect_volume.particles, "the particle count");
    CLI::Option* ply_opt = volume->add_option("--ply", volume_ply, "the same frame's particles (PLY): count, "
                                              "positions and velocities");
    volume->add_option("--volume-tolerance", expect_volume.volume_tolerance,
                       "largest relative error of the liquid volume")->check(CLI::PositiveNumber);
    volume->add_option("--inside-fraction", expect_volume.inside_fraction,
                       "smallest fraction of the particles inside the surface (with --ply)")
        ->check(CLI::Range(0.0, 1.0));

    std::string points_file, points_ply;
    CLI::App* points = app.add_subcommand("points", "check a points file against the same frame's PLY");
    points->add_option("file", points_file, "the .vdb file")->required();
    points->add_option("--ply", points_ply, "the same frame's particles (PLY)")->required();

    std::string dir;
    CLI::App* self = app.add_subcommand("selftest", "write a known particle set with the export and check it");
    self->add_option("--dir", dir, "directory for the files (emptied first)")->required();

    CLI11_PARSE(app, argc, argv);
    openvdb::initialize();

    if (*self) return selftest(dir);
    Particles particles;
    if (*points) {
        std::string err = read_ply(points_ply, particles);
        if (err.empty()) err = check_points(points_file, particles);
        if (!err.empty()) return fail(err);
        std::printf("pf_vdb_check: %s: passed\n", points_file.c_str());
        return 0;
    }
    if (!*count_opt && !*ply_opt) return fail("volume: give --particles N or --ply FILE");
    if (*ply_opt) {
        if (std::string err = read_ply(volume_ply, particles); !err.empty()) return fail(err);
        if (*count_opt && expect_volume.particles != particles.size())
            return fail("--particles " + std::to_string(expect_volume.particles) + " but " + volume_ply + " has " +
                        std::to_string(particles.size()));
        expect_volume.particles = particles.size();
        expect_volume.ply = &particles;
    }
    if (std::string err = check_volume(volume_file, expect_volume); !err.empty()) return fail(err);
    std::printf("pf_vdb_check: %s: passed\n", volume_file.c_str());
    return 0;
}
