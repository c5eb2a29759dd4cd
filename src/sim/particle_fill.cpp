#include "sim/particle_fill.h"

#include <algorithm>
#include <cmath>

namespace pf {

namespace {
// 32-bit integer hash (lowbias32 by Chris Wellons): well mixed, cheap, portable.
uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

double unit(uint32_t h) { return double(h >> 8) * (1.0 / 16777216.0); }  // [0, 1)
}  // namespace

FillLattice::FillLattice(const pf_sim_desc& desc, const float lo[3], const float hi[3]) : desc_(desc) {
    m_ = int(std::lround(std::cbrt(double(desc.fill_particles_per_cell))));
    const double spacing = double(desc.cell_size) / m_;
    empty_ = false;
    for (int a = 0; a < 3; ++a) {
        const double d_lo = desc.origin[a];
        const double d_hi = desc.origin[a] + double(desc.cell_size) * desc.grid_size[a];
        lo_[a] = std::max(double(lo[a]), d_lo);
        hi_[a] = std::min(double(hi[a]), d_hi);
        // Samples sit at the centres of the sub-lattice: origin + (s + 0.5) * spacing.
        // The sample range is clamped in double before it becomes an integer: a box far outside
        // the domain (lo = 1e20) would otherwise convert a value beyond int64's range (undefined).
        const double samples = double(desc.grid_size[a]) * m_;
        const double first = std::clamp(std::ceil((lo_[a] - d_lo) / spacing - 0.5), 0.0, samples);
        const double last = std::clamp(std::floor((hi_[a] - d_lo) / spacing - 0.5) + 1.0, 0.0, samples);
        first_[a] = int64_t(first);
        last_[a] = int64_t(last);
        if (!(hi_[a] > lo_[a]) || last_[a] <= first_[a]) empty_ = true;
    }
}

uint64_t FillLattice::count() const {
    if (empty_) return 0;
    uint64_t n = 1;
    for (int a = 0; a < 3; ++a) n *= uint64_t(last_[a] - first_[a]);
    return n;
}

void FillLattice::generate(uint32_t seed, uint32_t call, std::vector<float>& xyz) const {
    if (empty_) return;
    xyz.reserve(xyz.size() + size_t(count()) * 3);
    const double spacing = double(desc_.cell_size) / m_;
    const double jitter = desc_.fill_jitter;
    const uint32_t stream = hash32(seed ^ hash32(call + 0x9e3779b9U));
    for (int64_t k = first_[2]; k < last_[2]; ++k) {
        for (int64_t j = first_[1]; j < last_[1]; ++j) {
            for (int64_t i = first_[0]; i < last_[0]; ++i) {
                const int64_t s[3] = {i, j, k};
                uint32_t h = hash32(stream ^ hash32(uint32_t(i) ^ hash32(uint32_t(j) ^ hash32(uint32_t(k)))));
                // The box's outermost cell of samples keeps the regular lattice, so its faces are
                // flat at the sub-cell scale: the ghost-fluid surface reads the particles' weights
                // there, and a jittered face is a rough surface that starts waves (docs/design.md §4.6a).
                bool shell = false;
                for (int a = 0; a < 3; ++a) shell = shell || s[a] - first_[a] < m_ || last_[a] - 1 - s[a] < m_;
                for (int a = 0; a < 3; ++a) {
                    h = hash32(h + uint32_t(a));
                    // Jitter stays within the sample's own sub-cell, so the sample never
                    // leaves [lo, hi] by more than half a sub-cell; clamp the rest.
                    const double offset = shell ? 0.0 : jitter * (unit(h) - 0.5);
                    const double x = desc_.origin[a] + (double(s[a]) + 0.5 + offset) * spacing;
                    xyz.push_back(float(std::min(std::max(x, lo_[a]), hi_[a])));
                }
            }
        }
    }
}

}  // namespace pf
