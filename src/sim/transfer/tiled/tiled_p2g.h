// PF_P2G_TILED: the particles are counting-sorted by tile (PF_P2G_TILE^3 cells) every substep,
// then one workgroup per tile adds its particles' fixed-point terms in shared memory and each
// window sum to the face accumulators with one global atomic (shaders/transfer/tiled/): the
// fixed-point scheme's accumulators, bit for bit, with about 30 times fewer global atomics.
#pragma once
#include "sim/transfer/common/prefix_sum.h"
#include "sim/transfer/p2g_scheme.h"

namespace pf {

class TiledP2g final : public P2gScheme {
public:
    // Builds its programs (APIC's or not), adds its statistics entry for the sort
    // ("p2g_tile_sort"; the splat counts as "p2g") and allocates its buffers (first use only).
    pf_result prepare(const gl::Api& gl, PassRunner& runner, const P2gGrid& grid, bool apic, const Log& log,
                      const char* fn) override;
    // Count per tile, prefix sum, scatter, splat.
    void run(PassRunner& runner, const P2gBuffers& in) override;
    bool float_sums() const override { return false; }  // fixed point at FixedPointRange's scale
    const gl::Buffer* particle_order() const override { return &order_; }  // grouped by tile

private:
    P2gGrid grid_{};
    uint64_t tiles_ = 0;
    // Per particle slot its tile and its slot in it (uvec2); particle indices grouped by tile.
    gl::Buffer tile_slot_, order_;
    PrefixSum per_tile_;  // per tile the particle count and its start in the grouped order
    StatId stat_sort_ = 0;
};

}  // namespace pf
