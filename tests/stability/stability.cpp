#include "stability/stability.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "api/handle.h"

namespace pf::test {

size_t LogRecord::warnings_with(const std::string& text) const {
    return size_t(std::count_if(warnings.begin(), warnings.end(),
                                [&](const std::string& w) { return w.find(text) != std::string::npos; }));
}

double particle_mass(const pf_sim_desc& d) {
    return double(d.density) * d.cell_size * d.cell_size * d.cell_size / d.fill_particles_per_cell;
}

Energy energy_of(const ParticleState& p, const pf_sim_desc& d) {
    const float* g = d.params.gravity;
    // The corner lowest along g: where -g . x is smallest.
    double floor_height = 0;
    {
        double best = 1e300;
        for (int corner = 0; corner < 8; ++corner) {
            double h = 0;
            for (int a = 0; a < 3; ++a) {
                const double x = d.origin[a] + ((corner >> a) & 1 ? double(d.cell_size) * d.grid_size[a] : 0.0);
                h -= double(g[a]) * x;
            }
            best = std::min(best, h);
        }
        floor_height = best;
    }
    const double m = particle_mass(d);
    Energy e;
    for (size_t i = 0; i < p.count(); ++i) {
        double v2 = 0, h = 0;
        for (int a = 0; a < 3; ++a) {
            v2 += double(p.vel[i * 3 + a]) * p.vel[i * 3 + a];
            h -= double(g[a]) * p.pos[i * 3 + a];
        }
        e.kinetic += 0.5 * m * v2;
        e.potential += m * (h - floor_height);
    }
    return e;
}

pf_sim_desc Stability::desc(uint32_t nx, uint32_t ny, uint32_t nz, float cell_size) {
    pf_sim_desc d = test_desc(nx, ny, nz, cell_size);
    EXPECT_EQ(pf_quality_params(GetParam(), &d.params), PF_OK);
    d.logger.user = &log_;
    d.logger.fn = [](void* user, pf_log_level level, pf_result, const char* message) {
        auto* log = static_cast<LogRecord*>(user);
        if (level == PF_LOG_WARNING) log->warnings.emplace_back(message);
        if (level == PF_LOG_ERROR) log->errors.emplace_back(message);
    };
    return d;
}

Soundness Stability::check(pf_sim* sim, const pf_sim_desc& d, size_t expected_count, const std::string& when) {
    Soundness s;
    const ParticleState p = read_all(sim);
    s.count = p.count();
    EXPECT_EQ(s.count, expected_count) << when << ": particles lost or duplicated";
    for (size_t i = 0; i < p.count(); ++i) {
        bool finite = true, inside = true;
        for (int a = 0; a < 3; ++a) {
            const float x = p.pos[i * 3 + a];
            finite = finite && std::isfinite(x) && std::isfinite(p.vel[i * 3 + a]);
            const double lo = d.origin[a], hi = lo + double(d.cell_size) * d.grid_size[a];
            inside = inside && x >= lo && x <= hi;
        }
        s.nonfinite_particles += !finite;
        s.outside += !inside;
    }
    const Simulation& impl = *pf::entry(sim)->impl;
    for (const GridBuffer which : {GridBuffer::face_vel, GridBuffer::pressure}) {
        for (const double v : words_as_floats(impl.read_grid(which))) s.nonfinite_grid += !std::isfinite(v);
    }
    EXPECT_EQ(s.nonfinite_particles, 0u) << when << ": non-finite particles";
    EXPECT_EQ(s.outside, 0u) << when << ": particles outside the domain";
    EXPECT_EQ(s.nonfinite_grid, 0u) << when << ": non-finite face velocities or pressures";
    s.energy = energy_of(p, d);
    const std::vector<uint32_t> count = cell_counts_of(p, d);
    s.volume = particle_volume_of(count, d);
    s.liquid = liquid_volume_of(count, d);
    s.max_speed = max_speed_of(p);
    return s;
}

void Stability::run(pf_sim* sim, float dt, int frames) {
    for (int f = 0; f < frames; ++f) {
        const pf_result r = pf_step(sim, dt);
        ASSERT_EQ(r, PF_OK) << "frame " << f << ": " << pf_result_string(r);
    }
}

pf_stats Stability::settled_stats(pf_sim* sim) {
    pf::entry(sim)->impl->api().Finish();
    pf_stats st{};
    EXPECT_EQ(pf_get_stats(sim, &st), PF_OK);
    return st;
}

void Stability::record(const std::string& key, double value) {
    RecordProperty(key, std::to_string(value));
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::fprintf(stderr, "[measured] %s.%s %s = %.6g\n", info->test_suite_name(), info->name(), key.c_str(), value);
}

void Stability::expect_usable(pf_sim* sim, const pf_sim_desc& d, const std::string& when) {
    const uint32_t before = live_count(sim);
    uint32_t expected = before;
    // One cell's worth of particles in the middle of the domain, if capacity allows.
    float lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        lo[a] = d.origin[a] + d.cell_size * float(d.grid_size[a] / 2);
        hi[a] = lo[a] + d.cell_size;
    }
    if (uint64_t(before) + 64 <= d.max_particles) {
        ASSERT_EQ(pf_fill_box(sim, lo, hi, nullptr), PF_OK) << when << ": " << last_log();
        expected = live_count(sim);
        ASSERT_GT(expected, before) << when;
    }
    ASSERT_EQ(pf_step(sim, 1.0f / 60.0f), PF_OK) << when;
    check(sim, d, expected, when + ", then used again");
}

std::string preset_name(const ::testing::TestParamInfo<pf_quality>& info) {
    switch (info.param) {
        case PF_QUALITY_FAST: return "fast";
        case PF_QUALITY_BALANCED: return "balanced";
        case PF_QUALITY_ACCURATE: return "accurate";
        default: return "unknown";
    }
}

}  // namespace pf::test
