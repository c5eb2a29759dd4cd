#include "cli.h"

#include "util.h"

#include <istream>
#include <ostream>

namespace pfs {

void init_app(CLI::App& app) { app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast); }

const Choices<bool>& render_choices() {
    static const Choices<bool> c = {{"ssf", true}, {"particles", false}};
    return c;
}

const Choices<pf_depth_convention>& depth_choices() {
    static const Choices<pf_depth_convention> c = {{"standard", PF_DEPTH_STANDARD},
                                                   {"zero_to_one", PF_DEPTH_ZERO_TO_ONE},
                                                   {"reversed_z", PF_DEPTH_REVERSED_Z},
                                                   {"zo", PF_DEPTH_ZERO_TO_ONE},
                                                   {"reversed", PF_DEPTH_REVERSED_Z}};
    return c;
}

const Choices<pf_quality>& preset_choices() {
    static const Choices<pf_quality> c = {
        {"fast", PF_QUALITY_FAST}, {"balanced", PF_QUALITY_BALANCED}, {"accurate", PF_QUALITY_ACCURATE}};
    return c;
}

namespace {
constexpr uint32_t kMinSide = 16, kMaxSide = 16384;

/// Decimal digits only (no sign, no spaces), within the side's range.
bool read_side(const std::string& text, uint32_t& out) {
    if (text.empty() || text.size() > 5 || text.find_first_not_of("0123456789") != std::string::npos) return false;
    out = uint32_t(std::stoul(text));
    return out >= kMinSide && out <= kMaxSide;
}
} // namespace

std::string read_size(const std::string& text, Size& out) {
    const size_t x = text.find_first_of("xX");
    Size s;
    if (x != std::string::npos && read_side(text.substr(0, x), s.width) && read_side(text.substr(x + 1), s.height)) {
        out = s;
        return {};
    }
    return "expected WxH with W and H in [" + std::to_string(kMinSide) + ", " + std::to_string(kMaxSide) +
           "], got '" + text + "'";
}

std::istream& operator>>(std::istream& in, Size& size) {
    std::string text;
    in >> text;
    if (!read_size(text, size).empty()) in.setstate(std::ios::failbit);
    return in;
}

std::ostream& operator<<(std::ostream& out, const Size& size) { return out << size.width << "x" << size.height; }

SizeValidator::SizeValidator() {
    func_ = [](std::string& input) {
        Size s;
        return read_size(input, s);
    };
}

void ParamOverrides::apply(pf_sim_params& p) const {
    if (has_preset) apply_preset(preset, p);
    if (has_solver) p.pressure_solver = solver;
    if (has_tolerance) p.pressure_tolerance = tolerance;
    if (has_transfer) p.transfer = transfer;
    if (has_advection) p.advection = advection;
    if (has_p2g) p.p2g = p2g;
    if (has_free_surface) p.free_surface = free_surface;
    if (has_cfl) p.cfl = cfl;
    if (has_volume_correction) p.volume_correction = volume_correction;
}

namespace {
/// An option that stores into value and records that it was given.
template <typename T>
CLI::Option* add_override(CLI::App& app, const std::string& name, T& value, bool& given, const std::string& help) {
    return app.add_option_function<T>(
        name,
        [&value, &given](const T& v) {
            value = v;
            given = true;
        },
        help);
}
} // namespace

void add_param_overrides(CLI::App& app, ParamOverrides& o) {
    const std::string group = "Accuracy knobs (docs/accuracy.md; default: the scene's)";
    add_override(app, "--preset", o.preset, o.has_preset,
                 "quality preset: replaces the scene's step parameters but gravity and max_substeps; the knobs "
                 "below apply on top of it")
        ->transform(NameMap(preset_choices(), "preset"))
        ->type_name("NAME")
        ->group(group);
    add_override(app, "--solver", o.solver, o.has_solver, "pressure solver")
        ->transform(NameMap(enum_choices(solver_name, PF_PRESSURE_SOLVER_COUNT), "pressure solver"))
        ->type_name("NAME")
        ->group(group);
    // The library takes (0, 1); the bounds keep a typo like "1e4" from passing.
    add_override(app, "--tolerance", o.tolerance, o.has_tolerance,
                 "relative residual at which a pressure solve stops")
        ->check(Range(1e-12f, 0.999f))
        ->group(group);
    add_override(app, "--transfer", o.transfer, o.has_transfer, "grid-particle transfer")
        ->transform(NameMap(enum_choices(transfer_name, PF_TRANSFER_COUNT), "transfer"))
        ->type_name("NAME")
        ->group(group);
    add_override(app, "--advection", o.advection, o.has_advection, "particle integrator")
        ->transform(NameMap(enum_choices(advection_name, PF_ADVECTION_COUNT), "advection"))
        ->type_name("NAME")
        ->group(group);
    add_override(app, "--p2g", o.p2g, o.has_p2g,
                 "particle-to-grid scheme: fixed-point atomics, float atomics, the sorted gather "
                 "(PF_P2G_SORTED_GATHER) or fixed point summed per tile in shared memory (PF_P2G_TILED)")
        ->transform(NameMap(enum_choices(p2g_name, PF_P2G_COUNT), "particle-to-grid scheme"))
        ->type_name("NAME")
        ->group(group);
    add_override(app, "--free-surface", o.free_surface, o.has_free_surface,
                 "where the pressure's free surface sits")
        ->transform(NameMap(enum_choices(free_surface_name, PF_FREE_SURFACE_COUNT), "free surface"))
        ->type_name("NAME")
        ->group(group);
    add_override(app, "--cfl", o.cfl, o.has_cfl,
                 "projection CFL: most cells a particle may cross per substep (one pressure projection each)")
        ->check(Range(0.05f, 16.0f))
        ->group(group);
    add_override(app, "--volume-correction", o.volume_correction, o.has_volume_correction,
                 "share of the liquid's excess over its rest density moved out each step (0: off)")
        ->check(Range(0.0f, 1.0f))
        ->group(group);
}

} // namespace pfs
