// The effects part of a scene file: "features", "preset" and the object lists (force fields,
// obstacles with their SDF files, emitters, sinks), parsed into pf_* structs that start from
// pf_default_*(). (scene_sim.cpp adds them to a simulation: GL code, kept out of the loader.)
#include "scene_effects.h"

#include "floating.h"
#include "scene_parser.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pfs {

namespace {

// name -> value for one enum field.
template <typename E>
using Names = std::vector<std::pair<const char*, E>>;

template <typename E>
E enum_value(const Parser& p, const json& j, const std::string& path, const Names<E>& names) {
    const std::string name = p.string(j, path);
    std::string list;
    for (const auto& [n, v] : names) {
        if (name == n) return v;
        list += std::string(list.empty() ? "" : ", ") + n;
    }
    p.fail(path, "unknown \"" + name + "\" (one of " + list + ")");
}

void copy3(const vec3f& v, float out[3]) {
    for (int a = 0; a < 3; ++a) out[a] = v[a];
}

void quaternion(const Parser& p, const json& j, const std::string& path, float out[4]) {
    if (!j.is_array() || j.size() != 4) p.fail(path, "must be an array of 4 numbers (x, y, z, w), found " + Parser::describe(j));
    for (size_t i = 0; i < 4; ++i) out[i] = p.real(j[i], Parser::join(path, i));
}

// Reads the members an object may have, each by key; unknown keys are refused.
struct ObjectReader {
    const Parser& p;
    const json& obj;
    std::string path;
    const json* find(const char* key) const {
        auto it = obj.find(key);
        return it == obj.end() ? nullptr : &*it;
    }
    std::string at(const char* key) const { return Parser::join(path, key); }
    void vec3(const char* key, float out[3]) const {
        if (const json* j = find(key)) copy3(p.vec3(*j, at(key)), out);
    }
    void real(const char* key, float& out) const {
        if (const json* j = find(key)) out = p.real(*j, at(key));
    }
    void pair(const char* key, float out[2]) const {
        const json* j = find(key);
        if (!j) return;
        if (!j->is_array() || j->size() != 2) p.fail(at(key), "must be an array of 2 numbers, found " + Parser::describe(*j));
        for (size_t i = 0; i < 2; ++i) out[i] = p.real((*j)[i], Parser::join(at(key), i));
    }
    void rotation(float out[4]) const {
        if (const json* j = find("rotation")) quaternion(p, *j, at("rotation"), out);
    }
};

const Names<pf_force_field_type> kFieldTypes = {
    {"directional", PF_FORCE_FIELD_DIRECTIONAL}, {"point", PF_FORCE_FIELD_POINT}, {"vortex", PF_FORCE_FIELD_VORTEX}};
const Names<pf_obstacle_shape> kObstacleShapes = {
    {"box", PF_OBSTACLE_BOX}, {"sphere", PF_OBSTACLE_SPHERE}, {"capsule", PF_OBSTACLE_CAPSULE}, {"sdf", PF_OBSTACLE_SDF}};
const Names<pf_emitter_shape> kEmitterShapes = {
    {"box", PF_EMITTER_BOX}, {"sphere", PF_EMITTER_SPHERE}, {"disc", PF_EMITTER_DISC}};
const Names<pf_rate_unit> kRateUnits = {
    {"particles_per_second", PF_RATE_PARTICLES_PER_SECOND}, {"volume_per_second", PF_RATE_VOLUME_PER_SECOND}};
const Names<pf_sink_shape> kSinkShapes = {{"box", PF_SINK_BOX}, {"sphere", PF_SINK_SPHERE}};
const Names<uint32_t> kFeatures = {{"force_fields", PF_FEATURE_FORCE_FIELDS},
                                   {"obstacles", PF_FEATURE_OBSTACLES},
                                   {"emitters", PF_FEATURE_EMITTERS},
                                   {"sinks", PF_FEATURE_SINKS},
                                   {"domain_motion", PF_FEATURE_DOMAIN_MOTION},
                                   {"vorticity_confinement", PF_FEATURE_VORTICITY_CONFINEMENT},
                                   {"whitewater", PF_FEATURE_WHITEWATER},
                                   {"viscosity", PF_FEATURE_VISCOSITY},
                                   {"surface_tension", PF_FEATURE_SURFACE_TENSION}};

pf_force_field read_field(const ObjectReader& r) {
    r.p.check_keys(r.obj, r.path, {"type", "position", "vector", "strength", "radius", "drag"});
    pf_force_field f = pf_default_force_field();
    if (const json* j = r.find("type")) f.type = enum_value(r.p, *j, r.at("type"), kFieldTypes);
    r.vec3("position", f.position);
    r.vec3("vector", f.vector);
    r.real("strength", f.strength);
    r.real("radius", f.radius);
    r.real("drag", f.drag);
    return f;
}

// An obstacle's "oscillation": {"amplitude": [x, y, z] (m), "period": s}, which the samples move
// it along (driven.h); none: not driven.
Oscillation read_oscillation(const Parser& p, const json& obstacle, const std::string& obstacle_path) {
    Oscillation m;
    auto it = obstacle.find("oscillation");
    if (it == obstacle.end()) return m;
    const std::string path = Parser::join(obstacle_path, "oscillation");
    const ObjectReader r{p, p.object(*it, path), path};
    p.check_keys(r.obj, path, {"amplitude", "period"});
    p.required(r.obj, path, "amplitude");
    m.period = p.real(p.required(r.obj, path, "period"), r.at("period"), 1e-3, 1e6);
    r.vec3("amplitude", m.amplitude);
    for (float a : m.amplitude)
        if (std::fabs(a) > 1e6f) p.fail(r.at("amplitude"), "must be within 1e6 m on every axis");
    return m;
}

pf_obstacle read_obstacle(const ObjectReader& r) {
    r.p.check_keys(r.obj, r.path, {"shape", "position", "rotation", "half_extents", "radius", "half_height",
                                   "float_density", "oscillation", "file", "sdf_scale"});
    pf_obstacle o = pf_default_obstacle();
    if (const json* j = r.find("shape")) o.shape = enum_value(r.p, *j, r.at("shape"), kObstacleShapes);
    r.vec3("position", o.position);
    r.rotation(o.rotation);
    r.vec3("half_extents", o.half_extents);
    r.real("radius", o.radius);
    r.real("half_height", o.half_height);
    if (o.shape == PF_OBSTACLE_SDF) {
        // The box the grid tiles has no sensible default size: the file's author chose it.
        if (!r.find("half_extents")) r.p.fail(r.at("half_extents"), "is required for shape \"sdf\" (the box the grid tiles)");
        r.p.required(r.obj, r.path, "file");  // loaded by load_obstacle_sdfs
        if (const json* j = r.find("sdf_scale")) o.sdf_scale = r.p.real(*j, r.at("sdf_scale"), 0.0, 1e6, true);
    } else {
        for (const char* key : {"file", "sdf_scale"})
            if (r.find(key)) r.p.fail(r.at(key), "is only for shape \"sdf\"");
    }
    return o;
}

// The grid file of each "sdf" obstacle, its path relative to the scene file's folder unless
// absolute; an error names the obstacle's "file" and the file as opened.
void load_obstacle_sdfs(const Parser& p, const json& root, Scene& s) {
    const std::filesystem::path folder = std::filesystem::path(s.path).parent_path();
    for (size_t i = 0; i < s.obstacles.size(); ++i) {
        s.obstacle_sdf.emplace_back();
        if (s.obstacles[i].shape != PF_OBSTACLE_SDF) continue;
        const std::string at = Parser::join(Parser::join("/obstacles", i), "file");
        const std::string name = p.string(root.at("obstacles")[i].at("file"), at);
        if (name.empty()) p.fail(at, "must name an .npy file, found an empty string");
        const std::filesystem::path file = folder / std::filesystem::path(name);  // an absolute name replaces folder
        try {
            s.obstacle_sdf.back() = std::make_shared<const SdfGrid>(load_npy_sdf(file.string()));
        } catch (const SdfFileError& e) {
            p.fail(at, file.string() + ": " + e.what());
        }
    }
}

pf_emitter read_emitter(const ObjectReader& r) {
    r.p.check_keys(r.obj, r.path, {"shape", "position", "rotation", "half_extents", "radius", "velocity", "rate", "rate_unit"});
    pf_emitter e = pf_default_emitter();
    if (const json* j = r.find("shape")) e.shape = enum_value(r.p, *j, r.at("shape"), kEmitterShapes);
    r.vec3("position", e.position);
    r.rotation(e.rotation);
    r.vec3("half_extents", e.half_extents);
    r.real("radius", e.radius);
    r.vec3("velocity", e.velocity);
    r.real("rate", e.rate);
    if (const json* j = r.find("rate_unit")) e.rate_unit = enum_value(r.p, *j, r.at("rate_unit"), kRateUnits);
    return e;
}

pf_sink read_sink(const ObjectReader& r) {
    r.p.check_keys(r.obj, r.path, {"shape", "position", "rotation", "half_extents", "radius"});
    pf_sink k = pf_default_sink();
    if (const json* j = r.find("shape")) k.shape = enum_value(r.p, *j, r.at("shape"), kSinkShapes);
    r.vec3("position", k.position);
    r.rotation(k.rotation);
    r.vec3("half_extents", k.half_extents);
    r.real("radius", k.radius);
    return k;
}

// Parses the list `key` (if present) with `read`; the scene must name `feature`.
template <typename T, typename Read>
void read_list(const Parser& p, const json& root, const char* key, uint32_t feature, const Scene& s,
               std::vector<T>& out, Read read) {
    auto it = root.find(key);
    if (it == root.end()) return;
    const std::string path = Parser::join("", key);
    if (!it->is_array()) p.fail(path, "must be an array of objects, found " + Parser::describe(*it));
    if (!(s.features & feature)) p.fail(path, std::string("has objects but \"") + key + "\" is not listed in /features");
    for (size_t i = 0; i < it->size(); ++i) {
        const std::string at = Parser::join(path, i);
        out.push_back(read(ObjectReader{p, p.object((*it)[i], at), at}));
    }
}

pf_domain_motion read_motion(const ObjectReader& r) {
    r.p.check_keys(r.obj, r.path, {"position", "rotation", "velocity", "angular_velocity"});
    pf_domain_motion m = pf_default_domain_motion();
    r.vec3("position", m.position);
    r.rotation(m.rotation);
    r.vec3("velocity", m.velocity);
    r.vec3("angular_velocity", m.angular_velocity);
    return m;
}

pf_vorticity_confinement read_confinement(const ObjectReader& r) {
    r.p.check_keys(r.obj, r.path, {"strength"});
    pf_vorticity_confinement c = pf_default_vorticity_confinement();
    r.real("strength", c.strength);
    return c;
}

pf_whitewater read_whitewater(const ObjectReader& r) {
    r.p.check_keys(r.obj, r.path, {"capacity", "trapped_air_rate", "wave_crest_rate", "trapped_air_range",
                                   "wave_crest_range", "energy_range", "lifetime", "bubble_buoyancy", "bubble_drag",
                                   "spray_drag"});
    pf_whitewater w = pf_default_whitewater();
    if (const json* j = r.find("capacity")) w.capacity = uint32_t(r.p.real(*j, r.at("capacity"), 1.0, double(1u << 23), true));
    r.real("trapped_air_rate", w.trapped_air_rate);
    r.real("wave_crest_rate", w.wave_crest_rate);
    r.pair("trapped_air_range", w.trapped_air_range);
    r.pair("wave_crest_range", w.wave_crest_range);
    r.pair("energy_range", w.energy_range);
    r.pair("lifetime", w.lifetime);
    r.real("bubble_buoyancy", w.bubble_buoyancy);
    r.real("bubble_drag", w.bubble_drag);
    r.real("spray_drag", w.spray_drag);
    return w;
}

pf_viscosity read_viscosity(const ObjectReader& r) {
    r.p.check_keys(r.obj, r.path, {"viscosity", "iterations", "tolerance", "free_slip", "coupling_rounds"});
    pf_viscosity v = pf_default_viscosity();
    r.real("viscosity", v.viscosity);
    // Any uint32: the library checks the range (1..1000) when the scene is created.
    if (const json* j = r.find("iterations")) v.iterations = r.p.u32(*j, r.at("iterations"), 0, 0xffffffffu);
    r.real("tolerance", v.tolerance);
    if (const json* j = r.find("free_slip")) {
        if (!j->is_boolean()) r.p.fail(r.at("free_slip"), "must be true or false, found " + Parser::describe(*j));
        v.free_slip = j->get<bool>() ? 1u : 0u;
    }
    // Any uint32: the library checks the range (1..16).
    if (const json* j = r.find("coupling_rounds"))
        v.coupling_rounds = r.p.u32(*j, r.at("coupling_rounds"), 0, 0xffffffffu);
    return v;
}

pf_surface_tension read_surface_tension(const ObjectReader& r) {
    r.p.check_keys(r.obj, r.path, {"tension"});
    pf_surface_tension t = pf_default_surface_tension();
    r.real("tension", t.tension);
    return t;
}

} // namespace

void parse_scene_effects(const json& root, const std::string& path, Scene& s) {
    const Parser p{path};
    if (auto it = root.find("preset"); it != root.end()) {
        try {
            s.preset = parse_preset(p.string(*it, "/preset"), "value");
        } catch (const Error& e) {
            p.fail("/preset", e.what());
        }
        s.has_preset = true;
    }
    if (auto it = root.find("features"); it != root.end()) {
        if (!it->is_array()) p.fail("/features", "must be an array of feature names, found " + Parser::describe(*it));
        for (size_t i = 0; i < it->size(); ++i) s.features |= enum_value(p, (*it)[i], Parser::join("/features", i), kFeatures);
    }
    read_list(p, root, "force_fields", PF_FEATURE_FORCE_FIELDS, s, s.force_fields, read_field);
    read_list(p, root, "obstacles", PF_FEATURE_OBSTACLES, s, s.obstacles, read_obstacle);
    for (size_t i = 0; i < s.obstacles.size(); ++i) {
        const json& o = root.at("obstacles")[i];
        const std::string path = Parser::join("/obstacles", i);
        auto it = o.find("float_density");
        s.obstacle_float_density.push_back(
            it == o.end() ? 0.0f : p.real(*it, Parser::join(path, "float_density"), 0.0, 1e6, true));
        s.obstacle_oscillation.push_back(read_oscillation(p, o, path));
        if (s.obstacle_float_density.back() > 0.0f && s.obstacle_oscillation.back().period > 0.0f)
            p.fail(Parser::join(path, "oscillation"), "cannot move an obstacle that floats (float_density)");
    }
    load_obstacle_sdfs(p, root, s);
    read_list(p, root, "emitters", PF_FEATURE_EMITTERS, s, s.emitters, read_emitter);
    read_list(p, root, "sinks", PF_FEATURE_SINKS, s, s.sinks, read_sink);
    if (auto it = root.find("domain_motion"); it != root.end()) {
        if (!(s.features & PF_FEATURE_DOMAIN_MOTION))
            p.fail("/domain_motion", "is given but \"domain_motion\" is not listed in /features");
        s.domain_motion = read_motion(ObjectReader{p, p.object(*it, "/domain_motion"), "/domain_motion"});
        s.has_domain_motion = true;
    }
    if (auto it = root.find("vorticity_confinement"); it != root.end()) {
        if (!(s.features & PF_FEATURE_VORTICITY_CONFINEMENT))
            p.fail("/vorticity_confinement", "is given but \"vorticity_confinement\" is not listed in /features");
        s.vorticity_confinement =
            read_confinement(ObjectReader{p, p.object(*it, "/vorticity_confinement"), "/vorticity_confinement"});
        s.has_vorticity_confinement = true;
    }
    if (auto it = root.find("whitewater"); it != root.end()) {
        if (!(s.features & PF_FEATURE_WHITEWATER))
            p.fail("/whitewater", "is given but \"whitewater\" is not listed in /features");
        s.whitewater = read_whitewater(ObjectReader{p, p.object(*it, "/whitewater"), "/whitewater"});
        s.has_whitewater = true;
    }
    if (auto it = root.find("viscosity"); it != root.end()) {
        if (!(s.features & PF_FEATURE_VISCOSITY))
            p.fail("/viscosity", "is given but \"viscosity\" is not listed in /features");
        s.viscosity = read_viscosity(ObjectReader{p, p.object(*it, "/viscosity"), "/viscosity"});
        s.has_viscosity = true;
    }
    if (auto it = root.find("surface_tension"); it != root.end()) {
        if (!(s.features & PF_FEATURE_SURFACE_TENSION))
            p.fail("/surface_tension", "is given but \"surface_tension\" is not listed in /features");
        s.surface_tension =
            read_surface_tension(ObjectReader{p, p.object(*it, "/surface_tension"), "/surface_tension"});
        s.has_surface_tension = true;
    }
}

uint32_t parse_feature_list(const std::string& list, const char* what) {
    uint32_t bits = 0;
    size_t start = 0;
    while (start <= list.size()) {
        const size_t comma = std::min(list.find(',', start), list.size());
        const std::string name = list.substr(start, comma - start);
        start = comma + 1;
        if (name.empty() || name == "none") continue;
        if (name == "all") {
            bits |= PF_FEATURE_ALL;
            continue;
        }
        bool known = false;
        for (const auto& [n, v] : kFeatures) {
            if (name == n) bits |= v, known = true;
        }
        if (!known) {
            throw Error(std::string(what) + ": unknown feature '" + name +
                        "' (force_fields, obstacles, emitters, sinks, domain_motion, vorticity_confinement, whitewater, "
                        "viscosity, surface_tension, all, none)");
        }
    }
    return bits;
}

// Obstacle i of the scene as added to the library: with its SDF texture, if any.
static pf_obstacle added_obstacle(const Scene& s, const SceneEffectIds& ids, size_t i) {
    pf_obstacle added = s.obstacles[i];
    if (i < ids.obstacle_textures.size()) added.sdf_texture = ids.obstacle_textures[i];
    return added;
}

void drive_scene_obstacles(const Scene& s, const SceneEffectIds& ids, DrivenObstacles& out) {
    for (size_t i = 0; i < s.obstacles.size() && i < ids.obstacles.size(); ++i) {
        if (i >= s.obstacle_oscillation.size() || s.obstacle_oscillation[i].period <= 0.0f) continue;
        out.add(ids.obstacles[i], added_obstacle(s, ids, i), s.obstacle_oscillation[i]);
    }
}

void float_scene_obstacles(const Scene& s, const SceneEffectIds& ids, FloatingBodies& out) {
    for (size_t i = 0; i < s.obstacles.size() && i < ids.obstacles.size(); ++i) {
        if (s.obstacle_float_density[i] <= 0.0f) continue;
        out.add(ids.obstacles[i], added_obstacle(s, ids, i), s.obstacle_float_density[i]);
    }
}

} // namespace pfs
