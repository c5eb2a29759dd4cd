#include "scene.h"

#include "scene_effects.h"
#include "scene_parser.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <sstream>

namespace pfs {

vec3f Scene::domain_max() const {
    vec3f m{};
    for (int a = 0; a < 3; ++a) m[a] = origin[a] + float(grid_size[a]) * cell_size;
    return m;
}

double Scene::estimated_particles() const {
    const vec3f dmin = domain_min(), dmax = domain_max();
    const double ppc = particles_per_cell ? particles_per_cell : pf_default_sim_desc().fill_particles_per_cell;
    double total = 0;
    for (const FillBox& b : boxes) {
        double vol = 1;
        for (int a = 0; a < 3; ++a) {
            const double lo = std::max(b.lo[a], dmin[a]), hi = std::min(b.hi[a], dmax[a]);
            vol *= std::max(0.0, hi - lo);
        }
        total += vol / (double(cell_size) * cell_size * cell_size) * ppc;
    }
    return total;
}

SceneCamera Scene::default_camera() const {
    const vec3f lo = domain_min(), hi = domain_max();
    vec3f c{}, ext{};
    for (int a = 0; a < 3; ++a) {
        c[a] = 0.5f * (lo[a] + hi[a]);
        ext[a] = hi[a] - lo[a];
    }
    const float r = 0.5f * std::sqrt(ext[0] * ext[0] + ext[1] * ext[1] + ext[2] * ext[2]);
    SceneCamera cam;
    cam.fov_deg = 40.0f;
    const float dist = r / std::tan(0.5f * cam.fov_deg * 3.14159265f / 180.0f) * 1.05f;
    // From the +z side, a little to +x and above.
    const float dir[3] = {0.35f, 0.45f, 1.0f};
    const float len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    for (int a = 0; a < 3; ++a) cam.eye[a] = c[a] + dir[a] / len * dist;
    cam.target = c;
    cam.target[1] = lo[1] + 0.4f * ext[1];
    return cam;
}

Scene parse_scene(const std::string& text, const std::string& path) {
    Parser p{path};
    const json root = read_json(text, path);
    p.object(root, "");
    p.check_keys(root, "", {"name", "description", "grid", "max_particles", "particles_per_cell",
                            "fill_jitter", "seed", "max_speed", "density", "fill", "params", "frame_dt",
                            "frames", "camera", "preset", "features", "force_fields", "obstacles", "emitters",
                            "sinks", "domain_motion", "vorticity_confinement", "whitewater", "viscosity",
                            "surface_tension"});

    Scene s;
    s.path = path;
    s.params = pf_default_sim_params();
    {
        std::string base = path;
        const size_t slash = base.find_last_of("/\\");
        if (slash != std::string::npos) base = base.substr(slash + 1);
        if (base.size() > 5 && base.compare(base.size() - 5, 5, ".json") == 0) base.resize(base.size() - 5);
        s.name = base;
    }
    if (auto it = root.find("name"); it != root.end()) s.name = p.string(*it, "/name");
    if (auto it = root.find("description"); it != root.end()) s.description = p.string(*it, "/description");

    // grid
    const json& grid = p.object(p.required(root, "", "grid"), "/grid");
    p.check_keys(grid, "/grid", {"size", "cell_size", "origin"});
    {
        const json& size = p.required(grid, "/grid", "size");
        if (!size.is_array() || size.size() != 3)
            p.fail("/grid/size", "must be an array of 3 integers, found " + Parser::describe(size));
        for (size_t a = 0; a < 3; ++a) s.grid_size[a] = p.u32(size[a], Parser::join("/grid/size", a), 2, 1024);
        s.cell_size = p.real(p.required(grid, "/grid", "cell_size"), "/grid/cell_size", 0.0, 1e6, true);
        if (auto it = grid.find("origin"); it != grid.end()) s.origin = p.vec3(*it, "/grid/origin");
    }

    s.max_particles = p.u32(p.required(root, "", "max_particles"), "/max_particles", 1, 1u << 28);
    if (auto it = root.find("particles_per_cell"); it != root.end()) {
        s.particles_per_cell = p.u32(*it, "/particles_per_cell", 1, 64);
        const uint32_t ppc = s.particles_per_cell;
        if (ppc != 1 && ppc != 8 && ppc != 27 && ppc != 64)
            p.fail("/particles_per_cell", "must be 1, 8, 27 or 64, found " + std::to_string(ppc));
    }
    if (auto it = root.find("fill_jitter"); it != root.end()) {
        s.fill_jitter = p.real(*it, "/fill_jitter", 0.0, 1.0);
        s.has_fill_jitter = true;
    }
    if (auto it = root.find("seed"); it != root.end()) {
        s.seed = p.u32(*it, "/seed", 0, 0xffffffffu);
        s.has_seed = true;
    }
    if (auto it = root.find("max_speed"); it != root.end()) {
        s.max_speed = p.real(*it, "/max_speed", 0.0, 1e6, true);
        s.has_max_speed = true;
    }
    if (auto it = root.find("density"); it != root.end()) {
        s.density = p.real(*it, "/density", 0.0, 1e7, true);
        s.has_density = true;
    }

    // fill boxes
    if (auto it = root.find("fill"); it != root.end()) {
        if (!it->is_array()) p.fail("/fill", "must be an array of boxes, found " + Parser::describe(*it));
        for (size_t i = 0; i < it->size(); ++i) {
            const std::string bp = Parser::join("/fill", i);
            const json& b = p.object((*it)[i], bp);
            p.check_keys(b, bp, {"lo", "hi", "velocity"});
            FillBox box;
            box.lo = p.vec3(p.required(b, bp, "lo"), bp + "/lo");
            box.hi = p.vec3(p.required(b, bp, "hi"), bp + "/hi");
            if (auto v = b.find("velocity"); v != b.end()) box.velocity = p.vec3(*v, bp + "/velocity");
            for (int a = 0; a < 3; ++a)
                if (!(box.lo[a] < box.hi[a]))
                    p.fail(Parser::join(bp + "/hi", size_t(a)), "must be greater than lo[" + std::to_string(a) + "]");
            s.boxes.push_back(box);
        }
    }

    // effects and the preset (which the explicit params below then override)
    parse_scene_effects(root, path, s);
    if (s.has_preset) apply_preset(s.preset, s.params);

    // params
    if (auto it = root.find("params"); it != root.end()) {
        const json& pr = p.object(*it, "/params");
        // An enum by name: parse(name, what) throws the known names, reported at the key's path
        // (the string check stays outside, so its own report is not wrapped again).
        auto named = [&p, &pr](const char* key, auto parse, auto& field) {
            auto v = pr.find(key);
            if (v == pr.end()) return;
            const std::string path = std::string("/params/") + key;
            const std::string name = p.string(*v, path);
            try {
                field = parse(name, "value");
            } catch (const Error& e) {
                p.fail(path, e.what());
            }
        };
        p.check_keys(pr, "/params", {"gravity", "flip_ratio", "pressure_iterations", "jacobi_omega", "cfl",
                                     "max_substeps", "extrapolation_layers", "separation", "pressure_solver",
                                     "pressure_tolerance", "sor_omega", "free_surface", "transfer", "advection"});
        if (auto v = pr.find("gravity"); v != pr.end()) {
            const vec3f g = p.vec3(*v, "/params/gravity");
            for (int a = 0; a < 3; ++a) s.params.gravity[a] = g[a];
        }
        if (auto v = pr.find("flip_ratio"); v != pr.end()) s.params.flip_ratio = p.real(*v, "/params/flip_ratio", 0.0, 1.0);
        if (auto v = pr.find("pressure_iterations"); v != pr.end())
            s.params.pressure_iterations = p.u32(*v, "/params/pressure_iterations", 1, 10000);
        if (auto v = pr.find("jacobi_omega"); v != pr.end())
            s.params.jacobi_omega = p.real(*v, "/params/jacobi_omega", 0.0, 1.0, true);
        if (auto v = pr.find("cfl"); v != pr.end()) s.params.cfl = p.real(*v, "/params/cfl", 0.0, 16.0, true);
        if (auto v = pr.find("max_substeps"); v != pr.end()) s.params.max_substeps = p.u32(*v, "/params/max_substeps", 1, 64);
        if (auto v = pr.find("extrapolation_layers"); v != pr.end())
            s.params.extrapolation_layers = p.u32(*v, "/params/extrapolation_layers", 1, 16);
        if (auto v = pr.find("separation"); v != pr.end()) s.params.separation = p.u32(*v, "/params/separation", 0, 1);
        named("pressure_solver", parse_solver, s.params.pressure_solver);
        if (auto v = pr.find("pressure_tolerance"); v != pr.end())
            s.params.pressure_tolerance = p.real(*v, "/params/pressure_tolerance", 0.0, 1.0, true);
        if (auto v = pr.find("sor_omega"); v != pr.end()) s.params.sor_omega = p.real(*v, "/params/sor_omega", 0.0, 2.0, true);
        named("free_surface", parse_free_surface, s.params.free_surface);
        named("transfer", parse_transfer, s.params.transfer);
        named("advection", parse_advection, s.params.advection);
    }

    if (auto it = root.find("frame_dt"); it != root.end()) s.frame_dt = p.real(*it, "/frame_dt", 0.0, 1.0, true);
    if (auto it = root.find("frames"); it != root.end()) s.frames = p.u32(*it, "/frames", 0, 10000000);

    if (auto it = root.find("camera"); it != root.end()) {
        const json& c = p.object(*it, "/camera");
        p.check_keys(c, "/camera", {"eye", "target", "fov"});
        s.camera.eye = p.vec3(p.required(c, "/camera", "eye"), "/camera/eye");
        s.camera.target = p.vec3(p.required(c, "/camera", "target"), "/camera/target");
        if (auto v = c.find("fov"); v != c.end()) s.camera.fov_deg = p.real(*v, "/camera/fov", 1.0, 179.0);
        if (s.camera.eye == s.camera.target) p.fail("/camera/target", "coincides with /camera/eye");
        s.has_camera = true;
    }

    const double est = s.estimated_particles();
    if (est > double(s.max_particles) * 1.001)
        p.fail("/max_particles", "is " + std::to_string(s.max_particles) + " but the fill boxes need about " +
                                     std::to_string(uint64_t(est)));
    return s;
}

Scene load_scene(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw Error(path + ": cannot open scene file");
    std::ostringstream ss;
    ss << f.rdbuf();
    if (f.bad()) throw Error(path + ": read error");
    return parse_scene(ss.str(), path);
}

pf_sim_desc make_sim_desc(const Scene& s, pf_gl_get_proc_address_fn get_proc, pf_logger logger) {
    pf_sim_desc d = pf_default_sim_desc();
    for (int a = 0; a < 3; ++a) {
        d.grid_size[a] = s.grid_size[a];
        d.origin[a] = s.origin[a];
    }
    d.cell_size = s.cell_size;
    d.max_particles = s.max_particles;
    if (s.particles_per_cell) d.fill_particles_per_cell = s.particles_per_cell;
    if (s.has_fill_jitter) d.fill_jitter = s.fill_jitter;
    if (s.has_seed) d.seed = s.seed;
    if (s.has_max_speed) d.max_speed = s.max_speed;
    if (s.has_density) d.density = s.density;
    d.params = s.params;
    d.features = s.features;
    d.gl_get_proc_address = get_proc;
    d.logger = logger;
    return d;
}

void fill_scene(pf_sim* sim, const Scene& s) {
    for (size_t i = 0; i < s.boxes.size(); ++i) {
        const FillBox& b = s.boxes[i];
        const pf_result r = pf_fill_box(sim, b.lo.data(), b.hi.data(), b.velocity.data());
        if (r != PF_OK) {
            std::ostringstream what;
            what << s.path << ": pf_fill_box(/fill/" << i << " lo=(" << b.lo[0] << ", " << b.lo[1] << ", "
                 << b.lo[2] << ") hi=(" << b.hi[0] << ", " << b.hi[1] << ", " << b.hi[2] << "))";
            check(r, what.str().c_str());
        }
    }
}

} // namespace pfs
