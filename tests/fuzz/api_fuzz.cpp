// Seeded random-API fuzzer: thousands of random public-API calls on small grids, as a careless
// engine would make them, each checked against a model of what the header promises:
//  - every result is a documented pf_result, and the one the documented rules predict
//    (valid arguments -> PF_OK on a working GL; a broken one -> the documented error);
//  - a failed call changes nothing (particles compared bit for bit before and after,
//    parameters too); a successful one changes exactly what it says (added particles appear
//    at the end as given, set_params reads back resolved, clear empties; a polled particle request
//    equals the blocking read; a snapshot restores what was saved, a damaged one changes nothing);
//  - the particle count always equals the model's, and stepping keeps every particle finite
//    and inside the domain;
//  - effect objects (force fields, obstacles, emitters, sinks) and features: a hostile field is
//    refused, a plausible object accepted up to each list's capacity, ids kept by the model
//    accepted by set/remove and unknown ones refused, and none of it touches particles.
// Run under ASan/UBSan too (scripts/test.sh), where "no crash" includes "no sanitizer report".
//
//   pf_api_fuzz [--seed S] [--seconds T] [--calls N] [--verbose]
// stops after T seconds or N calls (whichever first); the call sequence depends only on S, so
// a failure at call K is replayed with --seed S --calls K (--verbose prints every call).
#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdarg>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "pf/pf.h"
#include "support/render_scene.h"
#include "support/test_context.h"

namespace {

using pf::test::get_proc;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kMax = std::numeric_limits<float>::max();

struct Failure {
    std::string what;
};
uint64_t g_call = 0;
bool g_verbose = false;

#define CHECK(cond, ...)                                                                  \
    do {                                                                                  \
        if (!(cond)) {                                                                    \
            char buf_[512];                                                               \
            std::snprintf(buf_, sizeof buf_, __VA_ARGS__);                                \
            throw Failure{std::string(#cond) + ": " + buf_ + " (log: " + pf::test::last_log() + ")"}; \
        }                                                                                 \
    } while (0)

bool documented(pf_result r) { return r >= PF_OK && r <= PF_ERROR_GL; }

// ---- enum fields as the C ABI sees them --------------------------------------------------------
// An engine written in C may store any int in an enum field. In C++ such a value is outside
// the enum's range, and reading it as the enum type is undefined (UBSan: -fsanitize=enum), so
// the fuzzer writes and reads these fields as raw 32-bit integers.
template <class E>
void set_raw(E& field, int32_t v) {
    static_assert(sizeof(E) == 4, "pf_* enums are 32-bit (FORCE32)");
    std::memcpy(&field, &v, 4);
}
template <class E>
uint32_t raw(const E& field) {
    uint32_t v;
    std::memcpy(&v, &field, 4);
    return v;
}

// ---- random values: mostly plausible, sometimes hostile -------------------------------------
struct Rng {
    std::mt19937_64 e;
    explicit Rng(uint64_t seed) : e(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(e); }
    uint32_t below(uint32_t n) { return uint32_t(e() % n); }
    bool chance(double p) { return uniform(0, 1) < p; }
    // A float in [lo, hi], or with probability `hostile` one of the values that break code.
    float real(double lo, double hi, double hostile = 0.1) {
        static const float special[] = {0.0f, -0.0f, kNaN, kInf, -kInf, kMax, -kMax, 1e20f, -1e20f,
                                        std::numeric_limits<float>::denorm_min(), -1.0f, 1e-30f};
        if (chance(hostile)) return special[below(sizeof special / sizeof special[0])];
        return float(uniform(lo, hi));
    }
    uint32_t u32(uint32_t lo, uint32_t hi, double hostile = 0.1) {
        static const uint32_t special[] = {0u, 1u, 0x7fffffffu, 0x80000000u, 0xffffffffu, 1025u, 65u, 17u};
        if (chance(hostile)) return special[below(sizeof special / sizeof special[0])];
        return lo + below(hi - lo + 1);
    }
    // A valid enumerator, or (hostile) a value a C caller may store but no enumerator has.
    template <class E>
    void enumeration(E& field, uint32_t count) {
        static const int32_t bad[] = {-1, 0x7fffffff, int32_t(0x80000000), 99};
        set_raw(field, chance(0.1) ? bad[below(4)] : int32_t(below(count)));
    }
};

// ---- the documented rules (include/pf/pf.h), as the model predicts them ----------------------
bool finite3(const float v[3]) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

// A zero-initialised struct (struct_size 0) takes the default for each zero 4-byte field; then
// the "0 = default" fields take their default; the rest are literal (pf.h ABI rules).
// Fields beyond the caller's struct_size (0: the first layout, which ended before free_surface)
// were never passed and take their defaults.
constexpr size_t kFirstParamsLayout = offsetof(pf_sim_params, free_surface);
pf_sim_params resolve(pf_sim_params p) {
    const pf_sim_params d = pf_default_sim_params();
    const size_t passed = std::min(p.struct_size ? size_t(p.struct_size) : kFirstParamsLayout, sizeof p);
    std::memcpy(reinterpret_cast<uint8_t*>(&p) + passed, reinterpret_cast<const uint8_t*>(&d) + passed, sizeof p - passed);
    if (p.struct_size == 0) {
        static_assert(sizeof(pf_sim_params) % 4 == 0, "4-byte fields");
        uint32_t words[sizeof(pf_sim_params) / 4], defaults[sizeof(pf_sim_params) / 4];
        std::memcpy(words, &p, sizeof p);
        std::memcpy(defaults, &d, sizeof d);
        for (size_t w = 1; w < sizeof(pf_sim_params) / 4; ++w)
            if (words[w] == 0) words[w] = defaults[w];
        std::memcpy(&p, words, sizeof p);
    }
    p.struct_size = uint32_t(sizeof p);
    // pressure_iterations and pressure_tolerance are not "0 = default" once struct_size is set:
    // a zero there is invalid (params_valid refuses it).
    if (p.jacobi_omega == 0.0f) p.jacobi_omega = d.jacobi_omega;
    if (p.cfl == 0.0f) p.cfl = d.cfl;
    if (p.max_substeps == 0) p.max_substeps = d.max_substeps;
    if (p.extrapolation_layers == 0) p.extrapolation_layers = d.extrapolation_layers;
    if (p.sor_omega == 0.0f) p.sor_omega = d.sor_omega;
    if (p.volume_loss_limit == 0.0f) p.volume_loss_limit = d.volume_loss_limit;
    if (p.energy_gain_limit == 0.0f) p.energy_gain_limit = d.energy_gain_limit;
    return p;
}

bool params_valid(const pf_sim_params& r) {  // r resolved
    return finite3(r.gravity) && r.flip_ratio >= 0 && r.flip_ratio <= 1 && r.pressure_iterations >= 1 &&
           r.pressure_iterations <= 10000 && r.jacobi_omega > 0 && r.jacobi_omega <= 1 && r.cfl > 0 && r.cfl <= 16 &&
           r.max_substeps >= 1 && r.max_substeps <= 64 && r.extrapolation_layers >= 1 && r.extrapolation_layers <= 16 &&
           r.separation <= 1 && raw(r.pressure_solver) < PF_PRESSURE_SOLVER_COUNT && r.pressure_tolerance > 0 &&
           r.pressure_tolerance < 1 && r.sor_omega > 0 && r.sor_omega < 2 && raw(r.transfer) < PF_TRANSFER_COUNT &&
           raw(r.advection) < PF_ADVECTION_COUNT && r.volume_correction >= 0 && r.volume_correction <= 1 &&
           raw(r.p2g) < PF_P2G_COUNT && r.volume_loss_limit > 0 && r.volume_loss_limit <= 1 &&
           r.energy_gain_limit > 0 && r.energy_gain_limit <= 100 && raw(r.free_surface) < PF_FREE_SURFACE_COUNT;
}

bool desc_valid(const pf_sim_desc& d) {
    for (int a = 0; a < 3; ++a)
        if (d.grid_size[a] < 1 || d.grid_size[a] > 1024) return false;
    if (uint64_t(d.grid_size[0]) * d.grid_size[1] * d.grid_size[2] > (uint64_t(1) << 26)) return false;
    const uint32_t ppc = d.fill_particles_per_cell;
    if (!(d.cell_size >= 1e-5f && d.cell_size <= 1e5f) || !finite3(d.origin)) return false;
    for (int a = 0; a < 3; ++a) {  // the domain within 2^16 cells of the world origin
        const double lo = d.origin[a], hi = lo + double(d.cell_size) * d.grid_size[a];
        if (std::max(std::abs(lo), std::abs(hi)) / d.cell_size > 65536.0) return false;
    }
    return d.gl_get_proc_address && d.max_particles >= 1 && d.max_particles <= (1u << 28) &&
           (d.max_speed == 0 || (d.max_speed > 0 && d.max_speed <= 1e4f)) &&
           (d.density == 0 || (std::isfinite(d.density) && d.density > 0)) &&
           (ppc == 0 || ppc == 1 || ppc == 8 || ppc == 27 || ppc == 64) && d.fill_jitter >= 0 && d.fill_jitter <= 1 &&
           params_valid(resolve(d.params));
}

// Plausible values keep the run fast (small iteration counts); hostile ones are refused anyway.
pf_sim_params random_params(Rng& g) {
    pf_sim_params p = g.chance(0.3) ? pf_default_sim_params() : pf_sim_params{};
    if (g.chance(0.5)) pf_quality_params(pf_quality(g.below(PF_QUALITY_COUNT)), &p);
    const double h = g.chance(0.3) ? 0.15 : 0.0;  // a third of the sets carry hostile values
    if (g.chance(0.5)) for (float& c : p.gravity) c = g.real(-30, 30, h);
    if (g.chance(0.3)) p.flip_ratio = g.real(0, 1, h);
    if (g.chance(0.3)) p.pressure_iterations = g.u32(0, 60, h);
    if (g.chance(0.3)) p.jacobi_omega = g.real(0, 1, h);
    if (g.chance(0.3)) p.cfl = g.real(0.25, 16, h);
    if (g.chance(0.3)) p.max_substeps = g.u32(0, 12, h);
    if (g.chance(0.3)) p.extrapolation_layers = g.u32(0, 16, h);
    if (g.chance(0.3)) p.separation = g.u32(0, 1, h);
    if (g.chance(0.3)) g.enumeration(p.pressure_solver, PF_PRESSURE_SOLVER_COUNT);
    if (g.chance(0.3)) p.pressure_tolerance = g.real(1e-5, 0.5, h);
    if (g.chance(0.3)) p.sor_omega = g.real(0, 2, h);
    if (g.chance(0.3)) g.enumeration(p.transfer, PF_TRANSFER_COUNT);
    if (g.chance(0.3)) g.enumeration(p.advection, PF_ADVECTION_COUNT);
    if (g.chance(0.3)) p.volume_correction = g.real(0, 1, h);
    if (g.chance(0.3)) g.enumeration(p.p2g, PF_P2G_COUNT);
    if (g.chance(0.1)) p.volume_loss_limit = g.real(0, 1, h);
    if (g.chance(0.1)) p.energy_gain_limit = g.real(0, 100, h);
    if (g.chance(0.3)) g.enumeration(p.free_surface, PF_FREE_SURFACE_COUNT);
    return p;
}

// Grid sizes and capacities stay small when valid (the run is about calls, not cells); a
// hostile value is always one the rules refuse.
pf_sim_desc random_desc(Rng& g) {
    pf_sim_desc d = pf::test::test_desc(2, 2, 2);
    const double h = g.chance(0.3) ? 0.1 : 0.0;
    for (uint32_t& n : d.grid_size) n = g.chance(h) ? (g.chance(0.5) ? 1u : 1025u) : g.u32(2, 12, 0);
    d.cell_size = g.chance(h) ? (g.chance(0.5) ? kNaN : g.real(-0.1, 1e37, 1.0)) : float(g.uniform(0.01, 2.0));
    for (float& o : d.origin) o = g.chance(h) ? (g.chance(0.5) ? kInf : g.real(-3e38, 3e38, 0.5)) : float(g.uniform(-100, 100));
    d.max_particles = g.chance(h) ? (g.chance(0.5) ? 0u : (1u << 28) + 1) : g.u32(1, 6000, 0);
    d.max_speed = g.chance(0.5) ? 0.0f : g.real(1, 200, h);
    d.density = g.chance(0.5) ? 0.0f : g.real(1, 3000, h);
    static const uint32_t ppc[] = {0, 1, 8, 27, 64, 2, 9};
    d.fill_particles_per_cell = ppc[g.below(h > 0 ? 7 : 5)];
    d.fill_jitter = g.real(0, 1, h);
    d.seed = uint32_t(g.e());
    d.params = random_params(g);
    if (g.chance(0.02)) d.gl_get_proc_address = nullptr;
    return d;
}

// ---- one simulation and what the model knows about it ------------------------------------------
// Bit-for-bit equality of n floats (an empty vector's data() may be NULL, which memcmp must not see).
bool same_floats(const float* a, const float* b, size_t n) { return n == 0 || std::memcmp(a, b, n * 4) == 0; }

pf_sim_params sized_params() {
    pf_sim_params p{};
    p.struct_size = sizeof p;
    return p;
}

struct Snapshot {
    std::vector<float> pos, vel;
    pf_sim_params params = sized_params();  // read back with every field of this header
    bool operator==(const Snapshot& o) const {
        return pos.size() == o.pos.size() && same_floats(pos.data(), o.pos.data(), pos.size()) &&
               same_floats(vel.data(), o.vel.data(), vel.size()) &&
               std::memcmp(&params, &o.params, sizeof params) == 0;
    }
};

struct Sim {
    pf_sim* sim = nullptr;
    pf_sim_desc desc{};     // as created, max_speed resolved
    pf_sim_params params{}; // resolved, as the library must report them
    uint32_t count = 0;     // the model's particle count
    std::vector<uint32_t> ids[4];  // live object ids: force fields, obstacles, emitters, sinks

    double lo(int a) const { return desc.origin[a]; }
    double hi(int a) const { return desc.origin[a] + double(desc.cell_size) * desc.grid_size[a]; }

    uint32_t live_count() const {
        pf_stats st{};
        CHECK(pf_get_stats(sim, &st) == PF_OK, "pf_get_stats");
        return st.particle_count;
    }
    Snapshot snapshot() const {
        Snapshot s;
        const uint32_t n = live_count();
        CHECK(n == count, "particle count %u, model says %u", n, count);
        s.pos.resize(size_t(n) * 3);
        s.vel.resize(size_t(n) * 3);
        CHECK(pf_read_particles(sim, 0, n, s.pos.data(), s.vel.data()) == PF_OK, "read %u", n);
        CHECK(pf_get_params(sim, &s.params) == PF_OK, "get_params");
        return s;
    }
    void expect_inside(const Snapshot& s) const {
        for (size_t i = 0; i < s.pos.size(); ++i) {
            const int a = int(i % 3);
            CHECK(std::isfinite(s.pos[i]) && std::isfinite(s.vel[i]), "particle %zu not finite", i / 3);
            CHECK(s.pos[i] >= lo(a) && s.pos[i] <= hi(a), "particle %zu axis %d at %g outside [%g, %g]", i / 3, a,
                  double(s.pos[i]), lo(a), hi(a));
        }
    }
};

// Calls that fail must leave everything as it was; those that succeed are checked by the caller.
void expect_unchanged_on_failure(pf_result r, const Sim& s, const Snapshot& before, const char* call) {
    CHECK(documented(r), "%s returned undocumented %d", call, int(r));
    if (r != PF_OK) CHECK(s.snapshot() == before, "%s failed (%s) but changed the simulation", call, pf_result_string(r));
}

class Fuzzer {
public:
    explicit Fuzzer(uint64_t seed) : g_(seed), target_(96, 64, GL_RGBA8) {}
    ~Fuzzer() {
        for (Sim& s : sims_) pf_destroy(s.sim);
    }

    void one_call() {
        if (sims_.empty() || g_.chance(0.01)) return create();
        Sim& s = sims_[g_.below(uint32_t(sims_.size()))];
        switch (g_.below(17)) {
        case 0: case 1: case 2: return add(s);
        case 3: case 4: return fill(s);
        case 5: case 6: case 7: return step(s);
        case 8: return set_params(s);
        case 9: return push(s);
        case 10: return g_.chance(0.5) ? read(s) : g_.chance(0.5) ? request(s) : checkpoint(s);
        case 11: return render(s);
        case 12: return queries(s);
        case 13: return g_.chance(0.2) ? clear(s) : add(s);
        case 14: return null_sim();
        case 15: return effects(s);
        default: return g_.chance(0.15) ? destroy(s) : step(s);
        }
    }

private:
    void trace(const char* fmt, ...) __attribute__((format(printf, 2, 3))) {
        if (!g_verbose) return;
        va_list ap;
        va_start(ap, fmt);
        std::printf("[%llu] ", (unsigned long long)g_call);
        std::vprintf(fmt, ap);
        std::printf("\n");
        va_end(ap);
    }

    void create() {
        if (sims_.size() >= 2) return destroy(sims_.front());
        pf_sim_desc d = random_desc(g_);
        if (g_.chance(0.2)) d.logger.fn = nullptr;  // no logger must be fine too
        pf_sim* out = nullptr;
        const bool null_desc = g_.chance(0.02);
        trace("pf_create grid %ux%ux%u cell %g cap %u%s", d.grid_size[0], d.grid_size[1], d.grid_size[2],
              double(d.cell_size), d.max_particles, null_desc ? " (NULL desc)" : "");
        const pf_result r = pf_create(null_desc ? nullptr : &d, &out);
        const bool valid = !null_desc && desc_valid(d);
        CHECK(r == (valid ? PF_OK : PF_ERROR_INVALID_ARGUMENT), "pf_create -> %s, model says %s", pf_result_string(r),
              valid ? "valid" : "invalid");
        CHECK((r == PF_OK) == (out != nullptr), "out set on failure / not set on success");
        if (!out) return;
        Sim s;
        s.sim = out;
        s.desc = d;
        if (s.desc.max_speed == 0) s.desc.max_speed = pf_default_sim_desc().max_speed;
        s.params = resolve(d.params);
        sims_.push_back(s);
        const Snapshot now = s.snapshot();
        CHECK(now.pos.empty(), "new simulation holds particles");
        CHECK(std::memcmp(&now.params, &s.params, sizeof now.params) == 0, "params not the resolved desc.params");
    }

    void destroy(Sim& s) {
        trace("pf_destroy");
        pf_destroy(s.sim);
        sims_.erase(sims_.begin() + (&s - sims_.data()));
    }

    void add(Sim& s) {
        const uint32_t n = g_.chance(0.05) ? 0 : 1 + g_.below(g_.chance(0.1) ? 4000 : 200);
        std::vector<float> xyz(size_t(n) * 3), vel(size_t(n) * 3);
        const double hostile = g_.chance(0.2) ? 0.002 : 0.0;
        for (uint32_t i = 0; i < n; ++i) {
            for (int a = 0; a < 3; ++a) {
                // Inside, on the walls, or (hostile) anywhere.
                const double u = g_.uniform(-0.05, 1.05);
                xyz[i * 3 + a] = g_.chance(hostile) ? g_.real(-1e3, 1e3, 0.5)
                                                    : float(s.lo(a) + std::clamp(u, 0.0, 1.0) * (s.hi(a) - s.lo(a)));
                vel[i * 3 + a] = g_.real(-0.5, 0.5, hostile) * s.desc.max_speed;
            }
        }
        const bool with_vel = g_.chance(0.7), null_xyz = n && g_.chance(0.02);
        // The rules: all inside the domain, finite, |v| <= max_speed, and room for all of them.
        bool valid = !null_xyz;
        const double max2 = double(s.desc.max_speed) * s.desc.max_speed;
        for (uint32_t i = 0; i < n && valid; ++i) {
            const float* p = &xyz[i * 3];
            const float* v = &vel[i * 3];
            for (int a = 0; a < 3; ++a) valid = valid && std::isfinite(p[a]) && p[a] >= s.lo(a) && p[a] <= s.hi(a);
            if (with_vel)
                valid = valid && finite3(v) && double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2] <= max2;
        }
        const bool fits = uint64_t(s.count) + n <= s.desc.max_particles;
        const Snapshot before = s.snapshot();
        trace("pf_add_particles n=%u (model: %s, %s)", n, valid ? "valid" : "invalid", fits ? "fits" : "full");
        const pf_result r =
            pf_add_particles(s.sim, null_xyz ? nullptr : xyz.data(), with_vel ? vel.data() : nullptr, n);
        expect_unchanged_on_failure(r, s, before, "pf_add_particles");
        if (n == 0) {
            CHECK(r == PF_OK, "n = 0 -> %s", pf_result_string(r));
            return;
        }
        if (valid && fits) CHECK(r == PF_OK, "valid batch that fits -> %s", pf_result_string(r));
        if (!valid && fits) CHECK(r == PF_ERROR_INVALID_ARGUMENT, "invalid batch -> %s", pf_result_string(r));
        if (valid && !fits) CHECK(r == PF_ERROR_CAPACITY, "too many -> %s", pf_result_string(r));
        if (!valid && !fits) CHECK(r == PF_ERROR_INVALID_ARGUMENT || r == PF_ERROR_CAPACITY, "-> %s", pf_result_string(r));
        if (r != PF_OK) return;
        s.count += n;
        const Snapshot after = s.snapshot();
        // The batch is appended as given: the old particles untouched, the new ones exact.
        CHECK(same_floats(after.pos.data(), before.pos.data(), before.pos.size()), "old particles moved");
        CHECK(same_floats(after.pos.data() + before.pos.size(), xyz.data(), xyz.size()), "added positions differ");
        for (size_t i = 0; i < vel.size(); ++i)
            CHECK(after.vel[before.vel.size() + i] == (with_vel ? vel[i] : 0.0f), "added velocity %zu differs", i / 3);
    }

    void fill(Sim& s) {
        float lo[3], hi[3], vel[3];
        for (int a = 0; a < 3; ++a) {
            // Mostly within a few domain sizes; sometimes far outside (|x| up to FLT_MAX: the
            // lattice range must not be converted from beyond int64's range).
            const double ext = s.hi(a) - s.lo(a);
            lo[a] = float(s.lo(a) + g_.uniform(-0.3, 1.0) * ext);
            hi[a] = float(lo[a] + g_.uniform(-0.1, 0.4) * ext);
            if (g_.chance(0.05)) lo[a] = g_.chance(0.5) ? -kMax : float(g_.uniform(1e19, 1e21));
            if (g_.chance(0.05)) hi[a] = g_.chance(0.5) ? kMax : float(-g_.uniform(1e19, 1e21));
            vel[a] = float(g_.uniform(-0.5, 0.5) * s.desc.max_speed);
        }
        if (g_.chance(0.05)) (g_.chance(0.5) ? lo : hi)[g_.below(3)] = g_.chance(0.5) ? kNaN : -kInf;
        if (g_.chance(0.05)) vel[g_.below(3)] = g_.chance(0.5) ? kNaN : 2 * s.desc.max_speed;
        const bool with_vel = g_.chance(0.5);
        bool valid = finite3(lo) && finite3(hi);
        if (with_vel)
            valid = valid && finite3(vel) &&
                    std::sqrt(double(vel[0]) * vel[0] + double(vel[1]) * vel[1] + double(vel[2]) * vel[2]) <=
                        s.desc.max_speed;
        // Clipped box; a lattice point per axis is certain when it spans a whole sub-cell spacing.
        const uint32_t ppc = s.desc.fill_particles_per_cell ? s.desc.fill_particles_per_cell : 8;
        const double spacing = s.desc.cell_size / std::round(std::cbrt(double(ppc)));
        bool surely_nonempty = valid;
        double clo[3], chi[3];
        for (int a = 0; a < 3; ++a) {
            clo[a] = std::max<double>(lo[a], s.lo(a));
            chi[a] = std::min<double>(hi[a], s.hi(a));
            surely_nonempty = surely_nonempty && chi[a] - clo[a] >= spacing;
        }
        const Snapshot before = s.snapshot();
        trace("pf_fill_box (model: %s)", valid ? "valid" : "invalid");
        const pf_result r = pf_fill_box(s.sim, lo, hi, with_vel ? vel : nullptr);
        expect_unchanged_on_failure(r, s, before, "pf_fill_box");
        if (!valid) {
            CHECK(r == PF_ERROR_INVALID_ARGUMENT, "invalid box -> %s", pf_result_string(r));
            return;
        }
        if (surely_nonempty) CHECK(r != PF_ERROR_INVALID_ARGUMENT, "a box spanning a sub-cell was refused as empty");
        CHECK(r == PF_OK || r == PF_ERROR_CAPACITY || r == PF_ERROR_INVALID_ARGUMENT, "-> %s", pf_result_string(r));
        if (r != PF_OK) return;
        const uint32_t n = s.live_count();
        CHECK(n > s.count && n <= s.desc.max_particles, "fill: %u -> %u particles (capacity %u)", s.count, n,
              s.desc.max_particles);
        s.count = n;
        const Snapshot after = s.snapshot();
        s.expect_inside(after);
        CHECK(same_floats(after.pos.data(), before.pos.data(), before.pos.size()), "old particles moved");
        for (size_t i = before.pos.size(); i < after.pos.size(); ++i) {
            const int a = int(i % 3);
            CHECK(after.pos[i] >= clo[a] - spacing && after.pos[i] <= chi[a] + spacing, "filled particle outside box");
            CHECK(after.vel[i] == (with_vel ? vel[a] : 0.0f), "filled velocity differs");
        }
    }

    void step(Sim& s) {
        static const float bad[] = {0.0f, -0.01f, kNaN, kInf, 1.0001f, -kInf};
        const float dt = g_.chance(0.1) ? bad[g_.below(6)] : float(g_.uniform(1e-4, g_.chance(0.1) ? 1.0 : 0.05));
        const bool valid = std::isfinite(dt) && dt > 0 && dt <= 1;
        const Snapshot before = s.snapshot();
        trace("pf_step %g", double(dt));
        const pf_result r = pf_step(s.sim, dt);
        expect_unchanged_on_failure(r, s, before, "pf_step");
        CHECK(r == (valid ? PF_OK : PF_ERROR_INVALID_ARGUMENT), "pf_step(%g) -> %s", double(dt), pf_result_string(r));
        if (r == PF_OK) s.expect_inside(s.snapshot());  // also checks the count: no particle lost
    }

    void set_params(Sim& s) {
        const pf_sim_params p = random_params(g_);
        const bool null_params = g_.chance(0.03);
        const bool valid = !null_params && params_valid(resolve(p));
        const Snapshot before = s.snapshot();
        trace("pf_set_params (model: %s)", valid ? "valid" : "invalid");
        const pf_result r = pf_set_params(s.sim, null_params ? nullptr : &p);
        expect_unchanged_on_failure(r, s, before, "pf_set_params");
        CHECK(r == (valid ? PF_OK : PF_ERROR_INVALID_ARGUMENT), "pf_set_params -> %s", pf_result_string(r));
        if (r != PF_OK) return;
        s.params = resolve(p);
        const Snapshot after = s.snapshot();
        CHECK(std::memcmp(&after.params, &s.params, sizeof s.params) == 0, "params do not read back resolved");
        CHECK(after.pos == before.pos && after.vel == before.vel, "pf_set_params moved particles");
    }

    void push(Sim& s) {
        float c[3], dv[3];
        for (int a = 0; a < 3; ++a) {
            // Mostly near the domain; sometimes far away with a radius as large (|offset|^2 and r^2
            // beyond float range), and impulses far beyond max_speed (clamped along dv).
            const double ext = s.hi(a) - s.lo(a);
            c[a] = g_.chance(0.05) ? (g_.chance(0.5) ? kNaN : -kInf) : float(g_.uniform(s.lo(a) - ext, s.hi(a) + ext));
            if (g_.chance(0.05)) c[a] = g_.chance(0.5) ? kMax : float(g_.uniform(-1e21, 1e21));
            dv[a] = float(g_.uniform(-1, 1) * s.desc.max_speed);
            if (g_.chance(0.05)) dv[a] = g_.chance(0.5) ? kMax : float(g_.uniform(-1e21, 1e21));
        }
        if (g_.chance(0.05)) dv[g_.below(3)] = g_.chance(0.5) ? kNaN : kInf;
        const float radius = g_.chance(0.05) ? (g_.chance(0.5) ? kMax : 1e20f) : g_.real(0.01, 2.0, 0.1);
        const bool valid = finite3(c) && finite3(dv) && std::isfinite(radius) && radius > 0;
        const Snapshot before = s.snapshot();
        trace("pf_push r=%g (model: %s)", double(radius), valid ? "valid" : "invalid");
        const pf_result r = pf_push(s.sim, c, radius, dv);
        expect_unchanged_on_failure(r, s, before, "pf_push");
        CHECK(r == (valid ? PF_OK : PF_ERROR_INVALID_ARGUMENT), "pf_push -> %s", pf_result_string(r));
        if (r == PF_OK) s.expect_inside(s.snapshot());
    }

    void read(Sim& s) {
        const uint32_t first = g_.chance(0.1) ? uint32_t(g_.e()) : g_.below(s.count + 2);
        const uint32_t count = g_.chance(0.1) ? uint32_t(g_.e()) : g_.below(s.count + 2);
        const bool valid = uint64_t(first) + count <= s.count;
        std::vector<float> xyz(valid ? size_t(count) * 3 : 0);
        trace("pf_read_particles %u %u", first, count);
        const pf_result r = pf_read_particles(s.sim, first, count, valid ? xyz.data() : nullptr, nullptr);
        CHECK(r == (valid ? PF_OK : PF_ERROR_INVALID_ARGUMENT), "pf_read_particles(%u, %u) of %u -> %s", first, count,
              s.count, pf_result_string(r));
    }

    // pf_request_particles / pf_poll_particles: a valid request polled to completion equals the
    // blocking read; an invalid range or ticket is refused.
    void request(Sim& s) {
        const uint32_t first = g_.chance(0.1) ? uint32_t(g_.e()) : g_.below(s.count + 2);
        const uint32_t count = g_.chance(0.1) ? uint32_t(g_.e()) : g_.below(s.count + 2);
        const bool valid = uint64_t(first) + count <= s.count;
        uint32_t ticket = 0;
        trace("pf_request_particles %u %u", first, count);
        const pf_result r = pf_request_particles(s.sim, first, count, &ticket);
        CHECK(r == (valid ? PF_OK : PF_ERROR_INVALID_ARGUMENT), "pf_request_particles(%u, %u) of %u -> %s", first,
              count, s.count, pf_result_string(r));
        float dummy[3];
        CHECK(pf_poll_particles(s.sim, ticket + (r == PF_OK ? 1000000u : 0u), dummy, dummy) == PF_ERROR_INVALID_ARGUMENT,
              "a ticket never issued was accepted");
        if (r != PF_OK) return;
        std::vector<float> want(size_t(count) * 3), got(size_t(count) * 3, -1.0f);
        CHECK(pf_read_particles(s.sim, first, count, want.data(), nullptr) == PF_OK, "read");
        pf_result polled = PF_NOT_READY;
        for (int i = 0; i < 1000000 && polled == PF_NOT_READY; ++i) {
            polled = pf_poll_particles(s.sim, ticket, got.data(), nullptr);
            if (i == 100) glFinish();
        }
        CHECK(polled == PF_OK, "pf_poll_particles -> %s", pf_result_string(polled));
        CHECK(same_floats(want.data(), got.data(), want.size()), "the polled particles differ from the blocking read");
    }

    // Snapshots: a restore brings back the particles and parameters of the save; a damaged
    // snapshot is refused and changes nothing.
    void checkpoint(Sim& s) {
        size_t size = 0;
        CHECK(pf_snapshot_size(s.sim, &size) == PF_OK, "pf_snapshot_size");
        std::vector<uint8_t> bytes(size);
        trace("pf_save_snapshot %zu bytes", size);
        CHECK(pf_save_snapshot(s.sim, bytes.data(), size) == PF_OK, "pf_save_snapshot");
        const Snapshot saved = s.snapshot();
        const uint32_t saved_count = s.count;
        const pf_sim_params saved_params = s.params;
        if (g_.chance(0.3)) {
            const Snapshot before = s.snapshot();
            size_t n = size;
            if (g_.chance(0.5)) n = g_.below(uint32_t(size));  // truncated
            else bytes[g_.below(uint32_t(size))] ^= uint8_t(1u << g_.below(8));  // one bit flipped
            trace("pf_restore_snapshot damaged (%zu of %zu bytes)", n, size);
            const pf_result r = pf_restore_snapshot(s.sim, bytes.data(), n);
            expect_unchanged_on_failure(r, s, before, "pf_restore_snapshot");
            CHECK(r == PF_ERROR_INVALID_ARGUMENT, "a damaged snapshot -> %s", pf_result_string(r));
            return;
        }
        if (g_.chance(0.5)) step(s);
        if (g_.chance(0.5)) add(s);
        trace("pf_restore_snapshot");
        const pf_result r = pf_restore_snapshot(s.sim, bytes.data(), size);
        CHECK(r == PF_OK, "pf_restore_snapshot -> %s", pf_result_string(r));
        s.count = saved_count;
        s.params = saved_params;
        CHECK(s.snapshot() == saved, "the restored simulation differs from the saved one");
    }

    void render(Sim& s) {
        // Mostly inside the target; sometimes past its edge, which pf_render_ssf refuses (the
        // scene_color texture must cover the viewport) and pf_render_particles may draw clipped.
        const int x = int(g_.below(40)), y = int(g_.below(30));
        const bool oversize = g_.chance(0.1);
        const int vp[4] = {x, y, int(1 + g_.below(oversize ? 200 : uint32_t(target_.width - x))),
                           int(1 + g_.below(oversize ? 200 : uint32_t(target_.height - y)))};
        const bool fits = vp[0] + vp[2] <= target_.width && vp[1] + vp[3] <= target_.height;
        glm::dvec3 at(0), eye;
        for (int a = 0; a < 3; ++a) at[a] = 0.5 * (s.lo(a) + s.hi(a));
        for (int a = 0; a < 3; ++a) eye[a] = at[a] + g_.uniform(-3, 3) * (s.hi(a) - s.lo(a));
        const auto conv = pf_depth_convention(g_.below(3));
        pf::test::TestCamera tc = pf::test::make_camera(eye, at, g_.uniform(20, 90), vp, 0.05, 500.0, conv);
        pf_camera cam = tc.cam;
        bool valid = true;  // with one broken field (the rules of pf_camera), or none
        switch (g_.chance(0.3) ? g_.below(6) : 6) {
        case 0: cam.view[g_.below(16)] = kNaN; valid = false; break;
        case 1: std::memset(cam.proj, 0, sizeof cam.proj); valid = false; break;
        case 2: cam.viewport[2 + g_.below(2)] = g_.chance(0.5) ? 0 : 16385; valid = false; break;
        case 3: cam.near_plane = g_.chance(0.5) ? -1.0f : kNaN; valid = false; break;
        case 4: cam.far_plane = cam.near_plane; valid = false; break;
        case 5: set_raw(cam.depth_convention, g_.chance(0.5) ? -1 : int32_t(3 + g_.below(5))); valid = false; break;
        default: break;
        }
        pf_render_target t{target_.fbo, target_.color, g_.chance(0.5) ? target_.depth : 0u, 0u};
        const bool ssf = g_.chance(0.5);
        pf_ssf_params sp = pf_default_ssf_params();
        pf_particle_params pp = pf_default_particle_params();
        switch (g_.chance(0.3) ? g_.below(8) : 8) {  // one broken parameter, or a valid variation
        case 0: sp.particle_radius = pp.particle_radius = -1.0f; valid = false; break;
        case 1: set_raw(sp.filter, 7); set_raw(pp.color_by, -2); valid = false; break;
        case 2: sp.filter_radius = 65; pp.range[1] = pp.range[0]; valid = false; break;
        case 3: sp.shininess = 0.5f; pp.color_low[1] = kNaN; valid = false; break;
        case 4: sp.light_direction[0] = sp.light_direction[1] = sp.light_direction[2] = 0; pp.range[0] = kInf; valid = false; break;
        case 5: sp.fresnel_f0 = kNaN; pp.particle_radius = kNaN; valid = false; break;
        default:
            sp.filter = pf_ssf_filter(g_.below(3));
            sp.path = pf_ssf_path(g_.below(2));
            sp.filter_radius = g_.below(9);
            pp.color_by = pf_particle_color(g_.below(6));
        }
        const bool defaults = valid && g_.chance(0.3);
        const Snapshot before = s.snapshot();
        trace("pf_render_%s vp %dx%d (model: %s)", ssf ? "ssf" : "particles", vp[2], vp[3], valid ? "valid" : "invalid");
        const pf_result r = ssf ? pf_render_ssf(s.sim, &cam, &t, defaults ? nullptr : &sp)
                                : pf_render_particles(s.sim, &cam, &t, defaults ? nullptr : &pp);
        if (valid && !fits && (ssf || r != PF_OK)) valid = false;  // see the viewport above
        CHECK(r == (valid ? PF_OK : PF_ERROR_INVALID_ARGUMENT), "render -> %s", pf_result_string(r));
        CHECK(s.snapshot() == before, "rendering changed the simulation");
    }

    void queries(Sim& s) {
        uint32_t n = 0;
        CHECK(pf_get_pass_count(s.sim, &n) == PF_OK && n > 0, "pass count %u", n);
        const uint32_t i = g_.below(n + 3);
        pf_pass_stats ps{};
        const pf_result r = pf_get_pass_stats(s.sim, i, &ps);
        CHECK(r == (i < n ? PF_OK : PF_ERROR_INVALID_ARGUMENT), "pass %u of %u -> %s", i, n, pf_result_string(r));
        if (r == PF_OK) CHECK(ps.name && ps.name[0], "pass %u has no name", i);
        pf_gl_buffers b{};
        CHECK(pf_get_gl_buffers(s.sim, &b) == PF_OK && b.count == s.count && b.stride == 16, "gl buffers");
        CHECK(pf_get_stats(s.sim, nullptr) == PF_ERROR_INVALID_ARGUMENT, "NULL stats out");
        CHECK(pf_clear_flags(s.sim) == PF_OK, "clear flags");
    }

    // Effect objects: random ones (sometimes with one hostile field) added, replaced or removed,
    // and features toggled. Emitters and sinks stay off (the count model predicts neither
    // emission nor drains), so these calls never change particles or parameters; a hostile
    // field must be refused with PF_ERROR_INVALID_ARGUMENT, a plausible object accepted (or
    // PF_ERROR_CAPACITY when the list is full), and ids the model holds accepted by set/remove.
    void effects(Sim& s) {
        const uint32_t kind = g_.below(5);
        if (kind == 4) return features(s);
        static const char* const kKinds[] = {"force_field", "obstacle", "emitter", "sink"};
        static const uint32_t kCapacity[] = {PF_MAX_FORCE_FIELDS, PF_MAX_OBSTACLES, PF_MAX_EMITTERS, PF_MAX_SINKS};
        const Snapshot before = s.snapshot();
        std::vector<uint32_t>& ids = s.ids[kind];
        const bool hostile = g_.chance(0.3);
        const uint32_t op = g_.below(3);  // add, set, remove
        const bool known = !ids.empty() && g_.chance(0.8);
        const uint32_t id = known ? ids[g_.below(uint32_t(ids.size()))] : 1000000u + g_.below(10);
        pf_result r = PF_OK;
        if (op == 2) {
            trace("pf_remove_%s %u", kKinds[kind], id);
            r = kind == 0 ? pf_remove_force_field(s.sim, id) : kind == 1 ? pf_remove_obstacle(s.sim, id)
                : kind == 2 ? pf_remove_emitter(s.sim, id) : pf_remove_sink(s.sim, id);
            CHECK(r == (known ? PF_OK : PF_ERROR_INVALID_ARGUMENT), "remove %s %u -> %s", kKinds[kind], id, pf_result_string(r));
            if (known) ids.erase(std::find(ids.begin(), ids.end(), id));
        } else {
            uint32_t out = 0;
            trace("pf_%s_%s%s", op == 0 ? "add" : "set", kKinds[kind], hostile ? " (hostile)" : "");
            if (kind == 0) {
                const pf_force_field f = random_field(s, hostile);
                r = op == 0 ? pf_add_force_field(s.sim, &f, &out) : pf_set_force_field(s.sim, id, &f);
            } else if (kind == 1) {
                const pf_obstacle o = random_obstacle(s, hostile);
                r = op == 0 ? pf_add_obstacle(s.sim, &o, &out) : pf_set_obstacle(s.sim, id, &o);
            } else if (kind == 2) {
                const pf_emitter e = random_emitter(s, hostile);
                r = op == 0 ? pf_add_emitter(s.sim, &e, &out) : pf_set_emitter(s.sim, id, &e);
            } else {
                const pf_sink k = random_sink(s, hostile);
                r = op == 0 ? pf_add_sink(s.sim, &k, &out) : pf_set_sink(s.sim, id, &k);
            }
            const pf_result expected = hostile ? PF_ERROR_INVALID_ARGUMENT
                                       : op == 0 ? (ids.size() >= kCapacity[kind] ? PF_ERROR_CAPACITY : PF_OK)
                                                 : (known ? PF_OK : PF_ERROR_INVALID_ARGUMENT);
            CHECK(r == expected, "%s %s -> %s, model says %s", op == 0 ? "add" : "set", kKinds[kind], pf_result_string(r),
                  pf_result_string(expected));
            if (op == 0 && r == PF_OK) {
                CHECK(std::find(ids.begin(), ids.end(), out) == ids.end(), "id %u given twice", out);
                ids.push_back(out);
            }
        }
        CHECK(s.snapshot() == before, "an effects call changed particles or parameters");
    }

    // Features the count model can follow (force fields, obstacles), or unknown bits.
    void features(Sim& s) {
        const bool unknown = g_.chance(0.1);
        uint32_t f = g_.below(4);  // force fields and obstacles in any combination
        if (unknown) {
            do f = 1u << g_.below(32);
            while (f & uint32_t(PF_FEATURE_ALL));
        }
        uint32_t was = 0;
        CHECK(pf_get_features(s.sim, &was) == PF_OK, "get features");
        trace("pf_set_features %#x", f);
        const Snapshot before = s.snapshot();
        const pf_result r = pf_set_features(s.sim, f);
        CHECK(r == (unknown ? PF_ERROR_INVALID_ARGUMENT : PF_OK), "set_features %#x -> %s", f, pf_result_string(r));
        uint32_t now = 0;
        CHECK(pf_get_features(s.sim, &now) == PF_OK && now == (unknown ? was : f), "features %#x after setting %#x", now, f);
        CHECK(s.snapshot() == before, "pf_set_features changed particles or parameters");
    }

    // A point well inside the domain, and a size that keeps a turned shape around it inside.
    void inner(const Sim& s, float p[3], double& size) {
        double extent = 1e30;
        for (int a = 0; a < 3; ++a) extent = std::min(extent, s.hi(a) - s.lo(a));
        for (int a = 0; a < 3; ++a) p[a] = float(s.lo(a) + (s.hi(a) - s.lo(a)) * g_.uniform(0.4, 0.6));
        size = extent * g_.uniform(0.02, 0.1);
    }
    void rotation(float q[4]) {
        for (int i = 0; i < 4; ++i) q[i] = float(g_.uniform(-1, 1));
    }
    // One hostile value in `slot`: NaN, infinity or a huge number.
    float poison() { return g_.chance(0.5) ? kNaN : (g_.chance(0.5) ? kInf : -kInf); }

    pf_force_field random_field(const Sim& s, bool hostile) {
        pf_force_field f = pf_default_force_field();
        double size = 0;
        inner(s, f.position, size);
        g_.enumeration(f.type, PF_FORCE_FIELD_TYPE_COUNT);
        if (raw(f.type) >= PF_FORCE_FIELD_TYPE_COUNT && !hostile) set_raw(f.type, 0);
        for (float& v : f.vector) v = float(g_.uniform(-5, 5));
        f.vector[1] = 1.0f;  // a vortex needs a non-zero axis
        f.strength = float(g_.uniform(-5, 5));
        f.radius = float(size * 4);
        f.drag = float(g_.uniform(0, 2));
        if (hostile) {
            switch (g_.below(3)) {
                case 0: set_raw(f.type, 3 + int32_t(g_.below(5))); break;
                case 1: f.position[g_.below(3)] = poison(); break;
                default: f.drag = -1.0f, set_raw(f.type, PF_FORCE_FIELD_DIRECTIONAL); break;
            }
        }
        return f;
    }
    pf_obstacle random_obstacle(const Sim& s, bool hostile) {
        pf_obstacle o = pf_default_obstacle();
        double size = 0;
        inner(s, o.position, size);
        rotation(o.rotation);
        set_raw(o.shape, int32_t(g_.below(PF_OBSTACLE_SDF)));  // primitives (an SDF needs an engine texture)
        for (float& h : o.half_extents) h = float(size);
        o.radius = float(size), o.half_height = float(size);
        if (hostile) {
            switch (g_.below(3)) {
                case 0: set_raw(o.shape, -1 - int32_t(g_.below(5))); break;
                case 1: o.rotation[g_.below(4)] = poison(); break;
                default: o.radius = -float(size), set_raw(o.shape, PF_OBSTACLE_SPHERE); break;
            }
        }
        return o;
    }
    pf_emitter random_emitter(const Sim& s, bool hostile) {
        pf_emitter e = pf_default_emitter();
        double size = 0;
        inner(s, e.position, size);
        rotation(e.rotation);
        set_raw(e.shape, int32_t(g_.below(PF_EMITTER_SHAPE_COUNT)));
        set_raw(e.rate_unit, int32_t(g_.below(PF_RATE_UNIT_COUNT)));
        for (float& h : e.half_extents) h = float(size);
        e.radius = float(size);
        for (float& v : e.velocity) v = float(g_.uniform(-0.5, 0.5)) * s.desc.max_speed;
        e.rate = float(g_.uniform(0, 1000));
        if (hostile) {
            switch (g_.below(4)) {
                case 0: set_raw(e.rate_unit, 2 + int32_t(g_.below(5))); break;
                case 1: e.rate = g_.chance(0.5) ? -1.0f : poison(); break;
                case 2: e.velocity[0] = 2.0f * s.desc.max_speed; break;
                default: e.position[g_.below(3)] = float(s.hi(0) + s.hi(1) + s.hi(2)) + 1e3f; break;  // outside
            }
        }
        return e;
    }
    pf_sink random_sink(const Sim& s, bool hostile) {
        pf_sink k = pf_default_sink();
        double size = 0;
        inner(s, k.position, size);
        rotation(k.rotation);
        set_raw(k.shape, int32_t(g_.below(PF_SINK_SHAPE_COUNT)));
        for (float& h : k.half_extents) h = float(size);
        k.radius = float(size);
        if (hostile) {
            switch (g_.below(3)) {
                case 0: set_raw(k.shape, 2 + int32_t(g_.below(5))); break;
                case 1: k.half_extents[g_.below(3)] = poison(); break;
                default: k.half_extents[g_.below(3)] = 0.0f, set_raw(k.shape, PF_SINK_BOX); break;
            }
        }
        return k;
    }

    void clear(Sim& s) {
        trace("pf_clear_particles");
        const pf_sim_params before = s.snapshot().params;
        CHECK(pf_clear_particles(s.sim) == PF_OK, "clear");
        s.count = 0;  // snapshot() checks the count is 0 now
        const pf_sim_params after = s.snapshot().params;
        CHECK(std::memcmp(&after, &before, sizeof after) == 0, "pf_clear_particles changed the parameters");
    }

    void null_sim() {
        const float v[3] = {0, 0, 0};
        pf_stats st;
        CHECK(pf_step(nullptr, 0.01f) == PF_ERROR_INVALID_ARGUMENT, "step NULL");
        CHECK(pf_add_particles(nullptr, v, nullptr, 1) == PF_ERROR_INVALID_ARGUMENT, "add NULL");
        CHECK(pf_fill_box(nullptr, v, v, nullptr) == PF_ERROR_INVALID_ARGUMENT, "fill NULL");
        CHECK(pf_push(nullptr, v, 1.0f, v) == PF_ERROR_INVALID_ARGUMENT, "push NULL");
        CHECK(pf_get_stats(nullptr, &st) == PF_ERROR_INVALID_ARGUMENT, "stats NULL");
        pf_destroy(nullptr);
    }

    Rng g_;
    pf::test::EngineTarget target_;
    std::vector<Sim> sims_;
};

} // namespace

int main(int argc, char** argv) {
    uint64_t seed = 1, max_calls = UINT64_MAX;
    double seconds = 30;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 0);
        else if (a == "--seconds" && i + 1 < argc) seconds = std::atof(argv[++i]);
        else if (a == "--calls" && i + 1 < argc) max_calls = std::strtoull(argv[++i], nullptr, 0);
        else if (a == "--verbose") g_verbose = true;
        else {
            std::fprintf(stderr, "usage: %s [--seed S] [--seconds T] [--calls N] [--verbose]\n", argv[0]);
            return 2;
        }
    }
    if (!pf::test::ensure_context() || !gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc))) {
        std::fprintf(stderr, "pf_api_fuzz: no OpenGL 4.3 context\n");
        return 1;
    }
    std::printf("pf_api_fuzz: seed %llu, up to %g s\n", (unsigned long long)seed, seconds);
    std::fflush(stdout);
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    try {
        Fuzzer f(seed);
        for (g_call = 0; g_call < max_calls && elapsed() < seconds; ++g_call) f.one_call();
    } catch (const Failure& e) {
        std::printf("pf_api_fuzz: FAILED at call %llu: %s\n  replay: %s --seed %llu --calls %llu --verbose\n",
                    (unsigned long long)g_call, e.what.c_str(), argv[0], (unsigned long long)seed,
                    (unsigned long long)g_call + 1);
        return 1;
    }
    if (g_call < 1000 && max_calls == UINT64_MAX) {
        // A run this short proves little; say so rather than pass quietly.
        std::printf("pf_api_fuzz: only %llu calls in %g s (need 1000)\n", (unsigned long long)g_call, seconds);
        return 1;
    }
    std::printf("pf_api_fuzz: %llu calls, all as documented (%.1f s)\n", (unsigned long long)g_call, elapsed());
    return 0;
}
