// A parsed scene put into a simulation: its objects added with the library's ids, each SDF
// obstacle's grid uploaded first as the engine's GL texture. GL code: kept out of the scene
// loader's sources (PF_SCENE_LOADER_SOURCES), which the GL-free fuzzer compiles.
#include "scene.h"

#include "json_read.h"
#include "util.h"

#include <string>
#include <utility>
#include <vector>

namespace pfs {

namespace {

std::string object_pointer(const char* list, size_t i) { return pointer_join(pointer_join("", list), std::to_string(i)); }

// Adds every object of a list, their ids into `ids`; on failure names the object (the library
// logged its reason).
template <typename T, typename Add>
void add_list(pf_sim* sim, const Scene& s, const char* key, const std::vector<T>& list, Add add,
              std::vector<uint32_t>& ids) {
    for (size_t i = 0; i < list.size(); ++i) {
        uint32_t id = 0;
        const pf_result r = add(sim, &list[i], &id);
        ids.push_back(id);
        if (r != PF_OK) {
            throw Error(s.path + ": " + object_pointer(key, i) + ": refused by the library: " + pf_result_string(r) +
                        " (the log says why)");
        }
    }
}

} // namespace

SceneEffectIds add_scene_effects(pf_sim* sim, const Scene& s) {
    SceneEffectIds ids;
    std::vector<pf_obstacle> obstacles = s.obstacles;
    for (size_t i = 0; i < obstacles.size(); ++i) {
        if (obstacles[i].shape == PF_OBSTACLE_SDF && i < s.obstacle_sdf.size() && s.obstacle_sdf[i])
            obstacles[i].sdf_texture = ids.sdf_textures.add(*s.obstacle_sdf[i], s.path + ": " + object_pointer("obstacles", i));
        ids.obstacle_textures.push_back(obstacles[i].sdf_texture);
    }
    add_list(sim, s, "force_fields", s.force_fields, pf_add_force_field, ids.force_fields);
    add_list(sim, s, "obstacles", obstacles, pf_add_obstacle, ids.obstacles);
    add_list(sim, s, "emitters", s.emitters, pf_add_emitter, ids.emitters);
    add_list(sim, s, "sinks", s.sinks, pf_add_sink, ids.sinks);
    if (s.has_domain_motion && pf_set_domain_motion(sim, &s.domain_motion) != PF_OK)
        throw Error(s.path + ": /domain_motion: refused by the library (the log says why)");
    if (s.has_vorticity_confinement && pf_set_vorticity_confinement(sim, &s.vorticity_confinement) != PF_OK)
        throw Error(s.path + ": /vorticity_confinement: refused by the library (the log says why)");
    if (s.has_whitewater && pf_set_whitewater(sim, &s.whitewater) != PF_OK)
        throw Error(s.path + ": /whitewater: refused by the library (the log says why)");
    if (s.has_viscosity && pf_set_viscosity(sim, &s.viscosity) != PF_OK)
        throw Error(s.path + ": /viscosity: refused by the library (the log says why)");
    if (s.has_surface_tension && pf_set_surface_tension(sim, &s.surface_tension) != PF_OK)
        throw Error(s.path + ": /surface_tension: refused by the library (the log says why)");
    return ids;
}

pf_sim* create_scene_sim(const Scene& s, pf_gl_get_proc_address_fn get_proc, pf_logger logger, SceneEffectIds* ids) {
    for (const auto& grid : s.obstacle_sdf) {
        // Its textures would be deleted on return, under the new sim's feet.
        if (grid && !ids) throw Error(s.path + ": create_scene_sim: a scene with SDF obstacles needs ids to own their textures");
    }
    const pf_sim_desc d = make_sim_desc(s, get_proc, logger);
    pf_sim* sim = nullptr;
    check(pf_create(&d, &sim), (s.path + ": pf_create").c_str());
    try {
        fill_scene(sim, s);
        SceneEffectIds made = add_scene_effects(sim, s);
        if (ids) *ids = std::move(made);
    } catch (...) {
        pf_destroy(sim);
        throw;
    }
    return sim;
}

} // namespace pfs
