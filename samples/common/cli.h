// The samples' command lines (CLI11): validators whose refusals name what they expected, the
// names of the enum options, "WxH" sizes, and the accuracy knobs every interactive tool takes.
#pragma once

#include <pf/pf.h>

#include <CLI/CLI.hpp>

#include <cstdint>
#include <iosfwd>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace pfs {

/// Settings every sample's app shares, to call before adding options: an option given twice
/// keeps its last value (scripts append their own overrides to defaults they pass first).
void init_app(CLI::App& app);

/// CLI::Range whose refusal reads "expected a number in [1e-12, 0.999], got '2'": CLI11 2.1
/// prints the bounds with std::to_string, which shows 1e-12 as 0.000000.
class Range : public CLI::Range {
public:
    template <typename T>
    Range(T lo, T hi) : CLI::Range(lo, hi) {
        std::ostringstream d;
        d << "[" << lo << ", " << hi << "]";
        description(d.str());
        func_ = [lo, hi](std::string& input) -> std::string {
            T value{};
            if (CLI::detail::lexical_cast(input, value) && value >= lo && value <= hi) return {};
            std::ostringstream m;
            m << "expected " << (std::is_integral<T>::value ? "an integer" : "a number") << " in [" << lo << ", "
              << hi << "], got '" << input << "'";
            return m.str();
        };
    }
};

/// The command-line names of an enum's values, in the order --help lists them; several names
/// may share a value (aliases).
template <typename T>
using Choices = std::vector<std::pair<std::string, T>>;

/// name(T(0)) .. name(T(count - 1)): the names the library's own tables give.
template <typename T>
Choices<T> enum_choices(const char* (*name)(T), int count) {
    Choices<T> out;
    for (int i = 0; i < count; ++i) out.emplace_back(name(T(i)), T(i));
    return out;
}

/// The first name of `value` in `choices`, or "unknown".
template <typename T>
std::string choice_name(const Choices<T>& choices, T value) {
    for (const auto& [name, v] : choices)
        if (v == value) return name;
    return "unknown";
}

/// CLI::CheckedTransformer from the names in `choices` to their values. Unlike CLI11's own it
/// takes the names only (not the values' numbers), its help lists the names, and its refusal
/// says "unknown <kind> 'x' (known: a, b, c)".
class NameMap : public CLI::CheckedTransformer {
public:
    template <typename T>
    NameMap(const Choices<T>& choices, const std::string& kind) : CLI::CheckedTransformer(choices) {
        std::string set, known;
        for (const auto& c : choices) {
            set += (set.empty() ? "" : ",") + c.first;
            known += (known.empty() ? "" : ", ") + c.first;
        }
        description("{" + set + "}");
        func_ = [convert = func_, choices, kind, known](std::string& input) -> std::string {
            for (const auto& c : choices)
                if (c.first == input) return convert(input);
            return "unknown " + kind + " '" + input + "' (known: " + known + ")";
        };
    }
};

/// --render: pflip's screen-space fluid (true) or its debug particles (false).
const Choices<bool>& render_choices();
/// --depth: the camera's depth convention (with the short aliases zo and reversed).
const Choices<pf_depth_convention>& depth_choices();
/// Quality presets: fast, balanced, accurate.
const Choices<pf_quality>& preset_choices();

/// An image or window size, "WxH" on the command line (each side 16..16384).
struct Size {
    uint32_t width = 0, height = 0;
};
/// "WxH" -> out; returns what was wrong with text ("" when it is a size).
std::string read_size(const std::string& text, Size& out);
/// CLI11 converts a Size through these (its validator has refused a bad one first).
std::istream& operator>>(std::istream& in, Size& size);
std::ostream& operator<<(std::ostream& out, const Size& size);
/// Checks "WxH" before CLI11 converts it: "expected WxH with W and H in [16, 16384], got '12x'".
class SizeValidator : public CLI::Validator {
public:
    SizeValidator();
};

/// The accuracy knobs the samples take on the command line (--preset, --solver, --tolerance,
/// --transfer, --advection, --p2g, --free-surface, --cfl). Each overrides the scene's value only when
/// given, so a scene file stays the single source of everything else.
struct ParamOverrides {
    bool has_preset = false, has_solver = false, has_tolerance = false, has_transfer = false, has_advection = false,
         has_p2g = false, has_free_surface = false, has_cfl = false, has_volume_correction = false;
    pf_quality preset = PF_QUALITY_FAST;
    pf_pressure_solver solver = PF_PRESSURE_SOLVER_JACOBI;
    float tolerance = 0;
    pf_transfer transfer = PF_TRANSFER_PIC_FLIP;
    pf_advection advection = PF_ADVECTION_EULER;
    pf_p2g p2g = PF_P2G_FIXED_POINT;
    pf_free_surface free_surface = PF_FREE_SURFACE_MARKER_CELL;
    float cfl = 0;
    float volume_correction = 0;

    /// Writes the given overrides into p: a preset first (keeping p's gravity and max_substeps,
    /// which are the scene's physics), then the single knobs.
    void apply(pf_sim_params& p) const;
};

/// Adds the knobs of ParamOverrides to app (in an "Accuracy knobs" group), each setting
/// its value and its has_ flag in o.
void add_param_overrides(CLI::App& app, ParamOverrides& o);

} // namespace pfs
