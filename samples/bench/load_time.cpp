// pf_load_time — how long pf_create takes, with an engine-side program-binary cache kept as
// files (docs/integration.md "Program-binary cache").
//
// It creates (and destroys) a scene's simulation --creates times, timing each pf_create with
// glFinish before and after, and counts what the cache callbacks did. With --program-cache DIR
// the blobs live in DIR, one file per key, so a second run of this tool (a new process: a game's
// next level load) finds them. To see what a driver without a cache of its own costs, give Mesa
// an empty cache directory each run (MESA_SHADER_CACHE_DIR=$(mktemp -d)): with
// MESA_SHADER_CACHE_DISABLE=true Mesa offers no program binary format, and pflip then compiles
// from source and calls no callback (it logs so once).

#include <glad/gl.h>

#include <pf/pf.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cli.h"
#include "egl_context.h"
#include "scene.h"
#include "scene_effects.h"
#include "util.h"

namespace {

using pfs::Error;

// The engine's side of pf_program_cache: one file per key in a directory.
struct FileCache {
    std::string dir;
    uint32_t loads = 0, hits = 0, stores = 0;

    std::string path(const char* key) const { return dir + "/" + key + ".bin"; }

    static size_t load(void* user, const char* key, void* data, size_t capacity) {
        auto& c = *static_cast<FileCache*>(user);
        ++c.loads;
        std::ifstream in(c.path(key), std::ios::binary | std::ios::ate);
        if (!in) return 0;
        const std::streamoff size = in.tellg();
        if (size <= 0) return 0;
        if (size_t(size) > capacity) return size_t(size);  // pflip calls again with room for it
        in.seekg(0);
        if (!in.read(static_cast<char*>(data), size)) return 0;
        ++c.hits;
        return size_t(size);
    }
    static void store(void* user, const char* key, const void* data, size_t size) {
        auto& c = *static_cast<FileCache*>(user);
        ++c.stores;
        // Written beside and renamed over: a reader never sees half a blob.
        const std::string final_path = c.path(key), temp = final_path + ".tmp";
        {
            std::ofstream out(temp, std::ios::binary | std::ios::trunc);
            out.write(static_cast<const char*>(data), std::streamsize(size));
            if (!out) return;
        }
        std::rename(temp.c_str(), final_path.c_str());
    }
};

struct Options {
    std::string scene = "dam_break_1m";
    std::string cache_dir;  // empty: no cache
    uint32_t prepared = 0;  // PF_FEATURE_* bits
    uint32_t creates = 1;
    bool enable_each = false;
    bool verbose = false;
};

// The effects in PF_FEATURE_* bit order, by their scene-file names.
constexpr const char* kEffectNames[] = {"force_fields", "obstacles", "emitters", "sinks", "domain_motion",
                                        "vorticity_confinement", "whitewater", "viscosity", "surface_tension"};

int run(int argc, char** argv) {
    Options o;
    CLI::App app{"pf_load_time: pf_create's time with a program-binary cache kept as files", "pf_load_time"};
    app.add_option("scene", o.scene, "scene name or file")->capture_default_str();
    app.add_option("--program-cache", o.cache_dir, "directory of the program-binary cache (created if missing)")
        ->type_name("DIR");
    app.add_option("--prepare", o.prepared,
                   "effects whose programs pf_create builds while they stay off (pf_sim_desc.prepared_features: "
                   "comma-separated names, or all)")
        ->transform(CLI::Validator(
            [](std::string& input) -> std::string {
                try {
                    input = std::to_string(pfs::parse_feature_list(input, "--prepare"));
                    return {};
                } catch (const Error& e) {
                    return e.what();
                }
            },
            "LIST"));
    app.add_option("--creates", o.creates, "pf_create / pf_destroy rounds in this process")
        ->check(CLI::Range(1u, 100u))
        ->capture_default_str();
    app.add_flag("--enable-each", o.enable_each,
                 "after each pf_create, turn the effects on one at a time and time each first pf_set_features");
    app.add_flag("-v,--verbose", o.verbose, "print pflip's info messages");
    CLI11_PARSE(app, argc, argv);

    pfs::EglContext ctx;
    if (!gladLoadGL(pfs::get_proc)) throw Error("gladLoadGL failed");
    GLint formats = 0;
    glGetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &formats);
    std::printf("%s\nprogram binary formats: %d\n", ctx.describe().c_str(), formats);

    FileCache cache;
    cache.dir = o.cache_dir;
    if (!cache.dir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(cache.dir, ec);
        if (ec) throw Error("cannot create " + cache.dir + ": " + ec.message());
    }
    const pfs::Scene scene = pfs::load_scene(pfs::resolve_scene_path(o.scene));
    for (uint32_t i = 0; i < o.creates; ++i) {
        pf_sim_desc desc = pfs::make_sim_desc(scene, pfs::get_proc, pfs::stderr_logger(o.verbose));
        desc.prepared_features = o.prepared;
        if (!cache.dir.empty()) desc.program_cache = pf_program_cache{&cache, &FileCache::load, &FileCache::store};
        cache.loads = cache.hits = cache.stores = 0;
        glFinish();
        const double t0 = pfs::now_ms();
        pf_sim* sim = nullptr;
        pfs::check(pf_create(&desc, &sim), "pf_create");
        glFinish();
        const double ms = pfs::now_ms() - t0;
        std::printf("pf_create %u: %.1f ms (%s; cache: %u loads, %u hits, %u stores)\n", i + 1, ms,
                    scene.name.c_str(), cache.loads, cache.hits, cache.stores);
        if (o.enable_each) {
            uint32_t on = 0;
            pfs::check(pf_get_features(sim, &on), "pf_get_features");
            for (const char* name : kEffectNames) {
                const uint32_t bit = pfs::parse_feature_list(name, "--enable-each");
                if (on & bit) continue;
                cache.loads = cache.hits = cache.stores = 0;
                glFinish();
                const double e0 = pfs::now_ms();
                pfs::check(pf_set_features(sim, on | bit), "pf_set_features");
                glFinish();
                std::printf("  enable %s: %.1f ms (cache: %u loads, %u hits, %u stores)\n", name,
                            pfs::now_ms() - e0, cache.loads, cache.hits, cache.stores);
                on |= bit;
            }
        }
        pf_destroy(sim);
        std::fflush(stdout);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) { return pfs::run_tool("pf_load_time", run, argc, argv); }
