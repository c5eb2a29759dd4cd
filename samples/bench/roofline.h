// The GPU's own ceilings, measured by pf_bench at start-up through GL compute so that its
// ratios hold on any GPU, and the traffic model of the particle passes they are compared with.
#pragma once
#include <cstdint>
#include <string>

#include "pf/pf.h"

namespace pfb {

struct Ceilings {
    double copy_gbps = 0;     // a compute kernel copying vec4s (the best of three ways), bytes read + written per second / 1e9
    double read_gbps = 0;     // the same reading only (kernels that read more than they write can pass the copy's rate)
    double atomics_gops = 0;  // 32-bit atomicAdd to random addresses of a 64 MiB buffer, per second / 1e9
    // GPU microseconds per dispatch in a chain of dependent dispatches, each after a storage
    // barrier as pflip's passes are: of one workgroup (the least a pass can cost), of one
    // workgroup through an indirect record the previous dispatch wrote (a command barrier too,
    // as the solvers' stoppable passes), and of 4,096 workgroups of 256 doing nothing (a pass
    // over a 128x64x64 grid's cells).
    double dispatch_us = 0, indirect_dispatch_us = 0, wide_dispatch_us = 0;
    // The same through a record no pass wrote since the last command barrier (storage barriers
    // only, as the solvers' passes between their scalar steps): of one workgroup and of 4,096.
    double static_indirect_dispatch_us = 0, wide_static_indirect_dispatch_us = 0;
    // GPU microseconds per dispatch of a copy of 2 MiB (a float field of a 128x64x64 grid, each
    // way): each after a storage barrier, and in pairs of independent ones (different buffers)
    // with no barrier between them, which the GPU may overlap (two solves interleaved).
    double copy_dispatch_us = 0, paired_copy_dispatch_us = 0;
    bool measured() const { return copy_gbps > 0; }  // false where timer queries read 0 (llvmpipe)
};

// Runs the microbenchmarks on the current context (a few hundred MiB of buffers, freed after).
Ceilings measure_ceilings();

// What one pass group moves per substep by the model: every particle attribute and grid field it
// reads or writes, once (caches and repeated stencil reads not counted), and the global atomics
// it issues. bytes 0: no model for that group.
struct Traffic {
    double bytes = 0;
    double atomics = 0;
};
struct TrafficInputs {
    uint64_t particles = 0, cells = 0, faces = 0;
    pf_p2g p2g = PF_P2G_TILED;
    bool apic = false;
    bool rk_advection = false;
    bool volume_correction = false;  // its particle move is timed with advection (PF_PASS_ADVECT)
};
Traffic pass_traffic(pf_pass pass, const TrafficInputs& in);
// One line saying what pass_traffic counts (printed under the table, written to the JSON).
const char* traffic_model_note();

}  // namespace pfb
