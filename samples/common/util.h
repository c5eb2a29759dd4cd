// Small helpers shared by the pflip samples: error handling around pf_result, a stderr
// logger, the owner of a simulation, timing, statistics, names of the enums, scene lookup.
// (The command lines themselves: cli.h.)
#pragma once

#include <pf/pf.h>

#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace pfs {

/// Owns a simulation: pf_destroy when it goes.
struct SimDeleter {
    void operator()(pf_sim* s) const { pf_destroy(s); }
};
using SimPtr = std::unique_ptr<pf_sim, SimDeleter>;

/// Thrown by the samples for any fatal error; main() prints what() and exits non-zero.
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Every sample's main(): returns run(argc, argv); an exception that escapes it is printed as
/// "<tool>: error: <what()>" on stderr (after stdout is flushed) and gives exit code 1.
int run_tool(const char* tool, int (*run)(int, char**), int argc, char** argv);

/// Throws Error("<what>: <pf_result_string> (code N)") unless r == PF_OK.
void check(pf_result r, const char* what);

/// A logger that prints pflip's messages to stderr. Errors and warnings always; info
/// messages only when verbose.
pf_logger stderr_logger(bool verbose);

/// Monotonic wall clock in milliseconds.
double now_ms();

/// Current UTC time as ISO 8601, e.g. "2024-05-01T12:34:56Z".
std::string utc_timestamp();

/// Host name, or "unknown".
std::string host_name();

/// Scenes directory: $PF_SCENES_DIR if set, else the one compiled in (PF_SCENES_DIR in CMake).
std::string scenes_dir();

/// Finds a scene file: arg as a path, arg + ".json", then both inside scenes_dir().
/// Throws Error listing the places tried when none exists.
std::string resolve_scene_path(const std::string& arg);

/// Descriptive statistics of a sample; all 0 for an empty one.
struct Summary {
    size_t n = 0;
    double mean = 0, median = 0, min = 0, max = 0, stddev = 0;
};
Summary summarize(std::vector<double> values);

/// GPU times of render calls as pf_get_stats reports them, a few calls late: add() the stats
/// after every call; summary() is each pass's and the total's statistics over the newest `keep`
/// distinct calls (pf_stats.render_frame), so the first calls (program builds) drop out.
class RenderTimings {
public:
    void add(const pf_stats& stats);
    struct Result {
        Summary pass[PF_RENDER_PASS_COUNT];
        Summary whitewater;  // the whitewater layer (pf_stats.render_whitewater_gpu_ms)
        Summary total;
    };
    Result summary(size_t keep) const;

private:
    std::map<uint64_t, pf_stats> by_call_;
};

/// Strict decimal parsing of an integer setting (environment variables); throws Error naming `option`.
uint32_t parse_u32(const std::string& text, const char* option, uint32_t lo, uint32_t hi);
/// Pressure solver by name ("jacobi", "rbgs", "cg", "pcg", "mgpcg", "mgpcg_galerkin"); throws Error naming `what`.
pf_pressure_solver parse_solver(const std::string& name, const char* what);
/// The name parse_solver takes for `solver`.
const char* solver_name(pf_pressure_solver solver);
/// The name of a grid-particle transfer ("pic_flip", "apic").
const char* transfer_name(pf_transfer transfer);
/// The transfer transfer_name names; throws Error naming `what` otherwise.
pf_transfer parse_transfer(const std::string& name, const char* what);
/// The name of a particle advection ("euler", "rk2", "rk3", "leapfrog", "rk2_offset").
const char* advection_name(pf_advection advection);
/// The advection advection_name names; throws Error naming `what` otherwise.
pf_advection parse_advection(const std::string& name, const char* what);
/// "marker_cell" or "ghost_fluid" (pf_free_surface); throws Error naming `what` otherwise.
pf_free_surface parse_free_surface(const std::string& name, const char* what);
/// The name parse_free_surface takes for `surface`.
const char* free_surface_name(pf_free_surface surface);
/// The name of a particle-to-grid scheme ("fixed", "float", "gather", "tiled": PF_P2G_FIXED_POINT,
/// PF_P2G_FLOAT_ATOMIC, PF_P2G_SORTED_GATHER, PF_P2G_TILED).
const char* p2g_name(pf_p2g p2g);

/// The runtime per-pass statistics list (pf_get_pass_count / pf_get_pass_stats), in the
/// library's order. Names stay valid until pf_destroy.
pf_result get_pass_list(const pf_sim* sim, std::vector<pf_pass_stats>& out);
/// Quality preset by name ("fast", "balanced", "accurate"); throws Error naming `what`.
pf_quality parse_preset(const std::string& name, const char* what);
/// Replaces p by the preset's parameters, keeping p's gravity and max_substeps (the scene's
/// physics and substep budget, not a quality choice).
void apply_preset(pf_quality quality, pf_sim_params& p);

/// "0.1.0" from pf_version().
std::string pf_version_string();

} // namespace pfs
