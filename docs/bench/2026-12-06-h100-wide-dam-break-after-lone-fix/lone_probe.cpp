// Scratch: run a scene, report the fastest particles each frame, save/restore snapshots.
#include <glad/gl.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>
#include <algorithm>
#include <unordered_map>
#include "egl_context.h"
#include "scene.h"
#include "scene_effects.h"
#include "util.h"
#include "pf/pf.h"

static void report(pf_sim* sim, uint32_t frame, float cell) {
    pf_stats st{}; st.struct_size = sizeof st;
    pf_get_stats(sim, &st);
    uint32_t n = st.particle_count;
    std::vector<float> x(3 * size_t(n)), v(3 * size_t(n));
    if (n) pf_read_particles(sim, 0, n, x.data(), v.data());
    std::vector<std::pair<float, uint32_t>> sp(n);
    uint32_t over20 = 0;
    for (uint32_t i = 0; i < n; ++i) {
        float s = std::sqrt(v[3*i]*v[3*i] + v[3*i+1]*v[3*i+1] + v[3*i+2]*v[3*i+2]);
        sp[i] = {s, i};
        over20 += s > 20.0f;
    }
    size_t k = std::min<size_t>(5, n);
    std::partial_sort(sp.begin(), sp.begin() + k, sp.end(), [](auto a, auto b) { return a.first > b.first; });
    auto key = [&](uint32_t i) {
        uint64_t c[3]; for (int a = 0; a < 3; ++a) c[a] = uint64_t(int64_t(std::floor(x[3*i+a] / cell)) + 4096);
        return c[0] | (c[1] << 20) | (c[2] << 40);
    };
    std::unordered_map<uint64_t, int> want;
    for (size_t j = 0; j < k; ++j) want[key(sp[j].second)] = 0;
    for (uint32_t i = 0; i < n; ++i) { auto it = want.find(key(i)); if (it != want.end()) ++it->second; }
    std::printf("frame %u substeps %u flags 0x%x over20 %u top:", frame, st.substeps, st.flags, over20);
    for (size_t j = 0; j < k; ++j) {
        uint32_t i = sp[j].second;
        std::printf(" [%.1f m/s at (%.2f %.2f %.2f) in-cell %d]", sp[j].first, x[3*i], x[3*i+1], x[3*i+2], want[key(i)]);
    }
    std::printf("\n");
    std::fflush(stdout);
}

int main(int argc, char** argv) {
    if (argc < 4) { std::fprintf(stderr, "lone_probe SCENE FRAMES [save F1,F2,..|restore FILE] [prefix]\n"); return 2; }
    std::string scene_path = pfs::resolve_scene_path(argv[1]);
    pfs::Scene scene = pfs::load_scene(scene_path);
    uint32_t frames = uint32_t(std::atoi(argv[2]));
    std::string mode = argv[3];
    std::string arg = argc > 4 ? argv[4] : "";
    std::string prefix = argc > 5 ? argv[5] : "snap";
    std::fprintf(stderr,"scene loaded\n");
    pfs::EglContext::Options copt;
    pfs::EglContext ctx(copt);
    std::fprintf(stderr,"ctx %s\n", ctx.describe().c_str());
    if (!gladLoadGL(pfs::get_proc)) { std::fprintf(stderr,"glad failed\n"); return 1; }
    pf_sim_desc desc = pfs::make_sim_desc(scene, pfs::get_proc, pfs::stderr_logger(false));
    if (const char* fr = std::getenv("PROBE_FLIP")) desc.params.flip_ratio = float(std::atof(fr));
    if (const char* preset = std::getenv("PROBE_PRESET")) pfs::apply_preset(pfs::parse_preset(preset, "PROBE_PRESET"), desc.params);
    const uint32_t from = std::getenv("PROBE_FROM") ? uint32_t(std::atoi(std::getenv("PROBE_FROM"))) : 0u;
    const uint32_t every = std::getenv("PROBE_EVERY") ? uint32_t(std::atoi(std::getenv("PROBE_EVERY"))) : 1u;
    pf_sim* sim = nullptr;
    if (pf_create(&desc, &sim) != PF_OK) return 1;
    std::fprintf(stderr,"created\n");
    pfs::fill_scene(sim, scene);
    std::fprintf(stderr,"filled\n");
    pfs::SceneEffectIds effects = pfs::add_scene_effects(sim, scene);
    std::vector<int> saves;
    uint32_t first = 1;
    if (mode == "save") {
        size_t p = 0;
        while (p < arg.size()) { size_t q = arg.find(',', p); if (q == std::string::npos) q = arg.size(); saves.push_back(std::atoi(arg.substr(p, q-p).c_str())); p = q + 1; }
    } else if (mode == "restore") {
        std::ifstream f(arg, std::ios::binary);
        std::vector<char> b((std::istreambuf_iterator<char>(f)), {});
        uint32_t at = 0; std::fread(&at, 0, 0, stdin);
        if (pf_restore_snapshot(sim, b.data(), b.size()) != PF_OK) { std::fprintf(stderr, "restore failed\n"); return 1; }
        first = uint32_t(std::atoi(prefix.c_str())) + 1;
        report(sim, first - 1, scene.cell_size);
    }
    for (uint32_t f = first; f < first + frames; ++f) {
        pf_step(sim, scene.frame_dt);
        if (f >= from && (f - from) % every == 0) report(sim, f, scene.cell_size);
        if (std::find(saves.begin(), saves.end(), int(f)) != saves.end()) {
            size_t sz = 0; pf_snapshot_size(sim, &sz);
            std::vector<char> b(sz);
            pf_save_snapshot(sim, b.data(), sz);
            std::ofstream o(prefix + "_" + std::to_string(f) + ".bin", std::ios::binary);
            o.write(b.data(), std::streamsize(sz));
        }
    }
    pf_destroy(sim);
    return 0;
}
