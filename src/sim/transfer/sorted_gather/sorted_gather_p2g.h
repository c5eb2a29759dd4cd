// PF_P2G_SORTED_GATHER: the particles are counting-sorted by half cell (2 x 2 x 2 per cell)
// every substep, then one invocation per face sample sums its particles in a fixed order
// (shaders/transfer/sorted_gather/): bit-identical float sums without atomics on the
// accumulators, at the price of the sort.
#pragma once
#include "sim/transfer/common/prefix_sum.h"
#include "sim/transfer/p2g_scheme.h"

namespace pf {

class SortedGatherP2g final : public P2gScheme {
public:
    // Builds its programs (APIC's or not), adds its statistics entries ("p2g_sort",
    // "p2g_gather") and allocates its buffers (first use only).
    pf_result prepare(const gl::Api& gl, PassRunner& runner, const P2gGrid& grid, bool apic, const Log& log,
                      const char* fn) override;
    // Count per cell and half cell, prefix sum, scatter, rank, gather.
    void run(PassRunner& runner, const P2gBuffers& in) override;
    bool float_sums() const override { return true; }  // the gather writes floats, as the float atomics do

private:
    P2gGrid grid_{};
    // Per particle slot its half cell and its slot in it (uvec2); particle indices grouped by
    // half cell in counting-atomic order; in the fixed order, the particles' grid coordinates
    // (vec4) and velocities with indices (vec3 + uint).
    gl::Buffer cell_slot_, unsorted_, sorted_grid_, sorted_particles_;
    PrefixSum halves_;  // per half cell the particle count and its start in the sorted order
    StatId stat_sort_ = 0, stat_gather_ = 0;
};

}  // namespace pf
