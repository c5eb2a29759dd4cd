// Small helpers shared by the pflip samples: error handling around pf_result, a stderr
// logger, the owner of a simulation, timing, statistics, command-line number parsing, scene lookup.
#pragma once

#include <pf/pf.h>

#include <cstdint>
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

/// Walks a command line option by option:
///     for (ArgCursor args(argc, argv); args.next();) { if (args.option() == "--x") x = args.value(); }
class ArgCursor {
public:
    ArgCursor(int argc, char** argv) : argc_(argc), argv_(argv) {}
    /// Moves to the next argument; false after the last.
    bool next() {
        if (++i_ >= argc_) return false;
        option_ = argv_[i_];
        return true;
    }
    const std::string& option() const { return option_; }
    /// The argument after the current option (consumed); throws Error if there is none.
    std::string value() {
        if (i_ + 1 >= argc_) throw Error(option_ + " needs a value (see --help)");
        return argv_[++i_];
    }

private:
    int argc_;
    char** argv_;
    int i_ = 0;
    std::string option_;
};

/// Strict number parsing for command-line options; throw Error naming the option.
uint32_t parse_u32(const std::string& text, const char* option, uint32_t lo, uint32_t hi);
float parse_float(const std::string& text, const char* option, float lo, float hi);
/// Pressure solver by name ("jacobi", "rbgs", "cg", "pcg", "mgpcg"); throws Error naming `what`.
pf_pressure_solver parse_solver(const std::string& name, const char* what);
/// The name parse_solver takes for `solver`.
const char* solver_name(pf_pressure_solver solver);
/// Grid-particle transfer by name ("pic_flip", "apic"); throws Error naming `what`.
pf_transfer parse_transfer(const std::string& name, const char* what);
/// The name parse_transfer takes for `transfer`.
const char* transfer_name(pf_transfer transfer);
/// Particle advection by name ("euler", "rk2", "rk3"); throws Error naming `what`.
pf_advection parse_advection(const std::string& name, const char* what);
/// The name parse_advection takes for `advection`.
const char* advection_name(pf_advection advection);
/// Particle-to-grid scheme by name ("fixed", "float", "gather", "tiled": PF_P2G_FIXED_POINT,
/// PF_P2G_FLOAT_ATOMIC, PF_P2G_SORTED_GATHER, PF_P2G_TILED); throws Error naming `what`.
pf_p2g parse_p2g(const std::string& name, const char* what);
/// "marker_cell" or "ghost_fluid" (pf_free_surface); throws Error naming `what` otherwise.
pf_free_surface parse_free_surface(const std::string& name, const char* what);
/// The name parse_free_surface takes for `surface`.
const char* free_surface_name(pf_free_surface surface);
/// The name parse_p2g takes for `p2g`.
const char* p2g_name(pf_p2g p2g);

/// The accuracy knobs the interactive samples take on the command line (--solver, --tolerance,
/// --transfer, --advection, --p2g, --free-surface). Each overrides the scene's value only when given, so a scene file
/// stays the single source of everything else.
struct ParamOverrides {
    bool has_preset = false, has_solver = false, has_tolerance = false, has_transfer = false, has_advection = false,
         has_p2g = false, has_free_surface = false;
    pf_quality preset = PF_QUALITY_FAST;
    pf_pressure_solver solver = PF_PRESSURE_SOLVER_JACOBI;
    float tolerance = 0;
    pf_transfer transfer = PF_TRANSFER_PIC_FLIP;
    pf_advection advection = PF_ADVECTION_EULER;
    pf_p2g p2g = PF_P2G_FIXED_POINT;
    pf_free_surface free_surface = PF_FREE_SURFACE_MARKER_CELL;

    /// If args.option() is one of the seven, consumes its value (strictly parsed) and returns
    /// true; false leaves args untouched for the caller's own options.
    bool parse(ArgCursor& args);
    /// Writes the given overrides into p: a preset first (keeping p's gravity and max_substeps,
    /// which are the scene's physics), then the single knobs.
    void apply(pf_sim_params& p) const;
    /// The --help lines of the seven options.
    static const char* usage();
};

/// The runtime per-pass statistics list (pf_get_pass_count / pf_get_pass_stats), in the
/// library's order. Names stay valid until pf_destroy.
pf_result get_pass_list(const pf_sim* sim, std::vector<pf_pass_stats>& out);
/// Quality preset by name ("fast", "balanced", "accurate"); throws Error naming `what`.
pf_quality parse_preset(const std::string& name, const char* what);
/// Replaces p by the preset's parameters, keeping p's gravity and max_substeps (the scene's
/// physics and substep budget, not a quality choice).
void apply_preset(pf_quality quality, pf_sim_params& p);
/// "WxH" -> w, h (each 16..16384).
void parse_size(const std::string& text, const char* option, uint32_t& w, uint32_t& h);

/// "0.1.0" from pf_version().
std::string pf_version_string();

} // namespace pfs
