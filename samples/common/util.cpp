#include "util.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iterator>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

#ifndef PF_DEFAULT_SCENES_DIR
#define PF_DEFAULT_SCENES_DIR "scenes"
#endif

namespace pfs {

int run_tool(const char* tool, int (*run)(int, char**), int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "%s: error: %s\n", tool, e.what());
        return 1;
    }
}

void check(pf_result r, const char* what) {
    if (r == PF_OK) return;
    throw Error(std::string(what) + ": " + pf_result_string(r) + " (pf_result " +
                std::to_string(static_cast<int>(r)) + ")");
}

namespace {
void log_to_stderr(void* user, pf_log_level level, pf_result code, const char* message) {
    const bool verbose = user != nullptr;
    const char* tag = "info";
    switch (level) {
    case PF_LOG_ERROR: tag = "error"; break;
    case PF_LOG_WARNING: tag = "warning"; break;
    default:
        if (!verbose) return;
        break;
    }
    if (code != PF_OK)
        std::fprintf(stderr, "[pflip %s] %s (%s)\n", tag, message ? message : "", pf_result_string(code));
    else
        std::fprintf(stderr, "[pflip %s] %s\n", tag, message ? message : "");
}
int verbose_marker = 1;
} // namespace

pf_logger stderr_logger(bool verbose) {
    pf_logger l;
    l.fn = &log_to_stderr;
    l.user = verbose ? static_cast<void*>(&verbose_marker) : nullptr;
    return l;
}

double now_ms() {
    using clock = std::chrono::steady_clock;
    return std::chrono::duration<double, std::milli>(clock::now().time_since_epoch()).count();
}

std::string utc_timestamp() {
    std::time_t t = std::time(nullptr);
    std::tm tm{};
#if defined(_WIN32)
    gmtime_s(&tm, &t);
#else
    gmtime_r(&t, &tm);
#endif
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

std::string host_name() {
#if defined(__unix__) || defined(__APPLE__)
    char buf[256] = {};
    if (gethostname(buf, sizeof buf - 1) == 0 && buf[0]) return buf;
#endif
    return "unknown";
}

std::string scenes_dir() {
    const char* env = std::getenv("PF_SCENES_DIR");
    if (env && *env) return env;
    return PF_DEFAULT_SCENES_DIR;
}

static bool file_exists(const std::string& p) {
    std::ifstream f(p);
    return f.good();
}

std::string resolve_scene_path(const std::string& arg) {
    std::vector<std::string> tried;
    auto attempt = [&](const std::string& p) {
        tried.push_back(p);
        return file_exists(p);
    };
    const bool has_ext = arg.size() > 5 && arg.compare(arg.size() - 5, 5, ".json") == 0;
    if (attempt(arg)) return arg;
    if (!has_ext && attempt(arg + ".json")) return arg + ".json";
    const bool absolute = !arg.empty() && arg[0] == '/';
    if (!absolute) {
        const std::string dir = scenes_dir();
        const std::string p = dir + "/" + arg;
        if (attempt(p)) return p;
        if (!has_ext && attempt(p + ".json")) return p + ".json";
    }
    std::string msg = "scene '" + arg + "' not found; tried:";
    for (const auto& t : tried) msg += "\n  " + t;
    msg += "\n(set PF_SCENES_DIR or pass a path)";
    throw Error(msg);
}

void RenderTimings::add(const pf_stats& stats) {
    if (stats.render_frame != 0) by_call_[stats.render_frame] = stats;
}

RenderTimings::Result RenderTimings::summary(size_t keep) const {
    std::vector<double> pass[PF_RENDER_PASS_COUNT], whitewater, total;
    size_t skip = by_call_.size() > keep ? by_call_.size() - keep : 0;
    for (const auto& [call, s] : by_call_) {
        if (skip > 0) {
            --skip;
            continue;
        }
        for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p) pass[p].push_back(s.render_gpu_ms[p]);
        whitewater.push_back(s.render_whitewater_gpu_ms);
        total.push_back(s.render_gpu_total_ms);
    }
    Result r;
    for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p) r.pass[p] = summarize(pass[p]);
    r.whitewater = summarize(whitewater);
    r.total = summarize(total);
    return r;
}

Summary summarize(std::vector<double> v) {
    Summary s;
    s.n = v.size();
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    double sum = 0;
    for (double x : v) sum += x;
    s.mean = sum / double(v.size());
    const size_t n = v.size();
    s.median = (n % 2) ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    s.min = v.front();
    s.max = v.back();
    double var = 0;
    for (double x : v) var += (x - s.mean) * (x - s.mean);
    s.stddev = n > 1 ? std::sqrt(var / double(n - 1)) : 0.0;
    return s;
}

uint32_t parse_u32(const std::string& text, const char* option, uint32_t lo, uint32_t hi) {
    errno = 0;
    char* end = nullptr;
    const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || text[0] == '-' || errno != 0 || end == text.c_str() || *end != '\0' || v < lo || v > hi)
        throw Error(std::string(option) + ": expected an integer in [" + std::to_string(lo) + ", " +
                    std::to_string(hi) + "], got '" + text + "'");
    return static_cast<uint32_t>(v);
}

namespace {
const char* const kSolverNames[] = {"jacobi", "rbgs", "cg", "pcg", "mgpcg", "mgpcg_galerkin"};
static_assert(sizeof(kSolverNames) / sizeof(kSolverNames[0]) == PF_PRESSURE_SOLVER_COUNT,
              "a command-line name for every pf_pressure_solver");
}  // namespace

pf_quality parse_preset(const std::string& name, const char* what) {
    if (name == "fast") return PF_QUALITY_FAST;
    if (name == "balanced") return PF_QUALITY_BALANCED;
    if (name == "accurate") return PF_QUALITY_ACCURATE;
    throw Error(std::string(what) + ": unknown preset '" + name + "' (known: fast, balanced, accurate)");
}

void apply_preset(pf_quality quality, pf_sim_params& p) {
    pf_sim_params q{};
    q.struct_size = sizeof q;  // this header's fields, not the v1 layout a zero struct_size means
    check(pf_quality_params(quality, &q), "pf_quality_params");
    for (int a = 0; a < 3; ++a) q.gravity[a] = p.gravity[a];
    q.max_substeps = p.max_substeps;
    p = q;
}

pf_pressure_solver parse_solver(const std::string& name, const char* what) {
    for (int i = 0; i < PF_PRESSURE_SOLVER_COUNT; ++i)
        if (name == kSolverNames[i]) return pf_pressure_solver(i);
    std::string known;
    for (const char* n : kSolverNames) known += std::string(known.empty() ? "" : ", ") + n;
    throw Error(std::string(what) + ": unknown pressure solver '" + name + "' (known: " + known + ")");
}

const char* solver_name(pf_pressure_solver solver) {
    return solver >= 0 && solver < PF_PRESSURE_SOLVER_COUNT ? kSolverNames[solver] : "unknown";
}

namespace {
const char* const kTransferNames[PF_TRANSFER_COUNT] = {"pic_flip", "apic"};
const char* const kAdvectionNames[PF_ADVECTION_COUNT] = {"euler", "rk2", "rk3", "leapfrog", "rk2_offset"};
const char* const kP2gNames[] = {"fixed", "float", "gather", "tiled"};
static_assert(std::size(kP2gNames) == PF_P2G_COUNT, "a name per pf_p2g value");

/// Index of `name` in names[0..n); throws Error listing the known names otherwise.
template <size_t N>
int parse_name(const char* const (&names)[N], const std::string& name, const char* what, const char* kind) {
    for (size_t i = 0; i < N; ++i)
        if (name == names[i]) return int(i);
    std::string known;
    for (const char* n : names) known += std::string(known.empty() ? "" : ", ") + n;
    throw Error(std::string(what) + ": unknown " + kind + " '" + name + "' (known: " + known + ")");
}
}  // namespace

const char* transfer_name(pf_transfer transfer) {
    return transfer >= 0 && transfer < PF_TRANSFER_COUNT ? kTransferNames[transfer] : "unknown";
}

const char* advection_name(pf_advection advection) {
    return advection >= 0 && advection < PF_ADVECTION_COUNT ? kAdvectionNames[advection] : "unknown";
}

pf_transfer parse_transfer(const std::string& name, const char* what) {
    return pf_transfer(parse_name(kTransferNames, name, what, "transfer"));
}

pf_advection parse_advection(const std::string& name, const char* what) {
    return pf_advection(parse_name(kAdvectionNames, name, what, "advection"));
}

const char* const kFreeSurfaceNames[PF_FREE_SURFACE_COUNT] = {"marker_cell", "ghost_fluid"};

pf_free_surface parse_free_surface(const std::string& name, const char* what) {
    return pf_free_surface(parse_name(kFreeSurfaceNames, name, what, "free surface"));
}

const char* free_surface_name(pf_free_surface surface) {
    return surface >= 0 && surface < PF_FREE_SURFACE_COUNT ? kFreeSurfaceNames[surface] : "unknown";
}

const char* p2g_name(pf_p2g p2g) { return p2g >= 0 && p2g < PF_P2G_COUNT ? kP2gNames[p2g] : "unknown"; }

pf_result get_pass_list(const pf_sim* sim, std::vector<pf_pass_stats>& out) {
    out.clear();
    uint32_t n = 0;
    if (pf_result r = pf_get_pass_count(sim, &n); r != PF_OK) return r;
    out.resize(n);
    for (uint32_t i = 0; i < n; ++i)
        if (pf_result r = pf_get_pass_stats(sim, i, &out[i]); r != PF_OK) {
            out.clear();
            return r;
        }
    return PF_OK;
}

std::string pf_version_string() {
    const uint32_t v = pf_version();
    return std::to_string(v / 10000) + "." + std::to_string((v / 100) % 100) + "." + std::to_string(v % 100);
}

} // namespace pfs
