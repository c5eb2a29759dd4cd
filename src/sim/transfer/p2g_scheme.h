// The interface every particle-to-grid scheme implements, and the one factory that maps pf_p2g
// to an implementation. Each substep a scheme writes every face sample's two accumulator words
// (the weighted momentum and the weight, docs/design.md §4.2) and every cell's particle count;
// it owns its programs, buffers and any statistics entries beyond the shared "p2g" one. Adding a
// scheme: a folder src/sim/transfer/<name>/ (the class), its kernels in shaders/transfer/<name>/
// (+ lines in shaders/permutations.inc), a pf_p2g value, and one case in make_p2g_scheme
// (docs/design.md, "Adding a P2G scheme").
#pragma once
#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

#include "api/log.h"
#include "gl/buffer.h"
#include "gl/gl.h"
#include "pf/pf.h"
#include "sim/grid_layout.h"
#include "sim/pass_runner.h"

namespace pf {

// The grid and capacity a scheme serves (fixed for the simulation's lifetime).
struct P2gGrid {
    GridLayout layout{};
    uint32_t max_particles = 0;
};

// One substep's transfer: what it reads, what it writes, and the statistics entries it counts
// under (the buffer clears under `clear`, the transfer itself under `p2g`).
struct P2gBuffers {
    const gl::Buffer& positions;
    const gl::Buffer& velocities;
    const gl::Buffer& affine;      // APIC's affine vectors (read with `apic` only)
    const gl::Buffer& face_accum;  // out: two words per face sample
    const gl::Buffer& cell_count;  // out: particles per cell
    const gl::Buffer& status;      // the fixed-point overflow flag
    uint32_t particles = 0;        // live particles (an upper bound while the GPU counts)
    bool apic = false;
    StatId clear = 0, p2g = 0;
};

class P2gScheme {
public:
    virtual ~P2gScheme() = default;
    // Builds its programs (APIC's with `apic`) and allocates its buffers on first use, so that a
    // failure leaves the running simulation untouched. Errors are logged (prefixed with `fn`)
    // and returned.
    virtual pf_result prepare(const gl::Api& gl, PassRunner& runner, const P2gGrid& grid, bool apic, const Log& log,
                              const char* fn) = 0;
    // Records one substep's transfer into the GL command stream (no CPU wait).
    virtual void run(PassRunner& runner, const P2gBuffers& in) = 0;
    // Whether its accumulators hold floats (read by grid_forces' float permutation) rather than
    // fixed-point integers at FixedPointRange's scale.
    virtual bool float_sums() const = 0;
    // Particle slots in a spatially coherent order (a permutation of the slots live at the last
    // run), if the scheme sorts them; the screen-space splat walks them in it.
    virtual const gl::Buffer* particle_order() const { return nullptr; }
};

// A new, unprepared scheme of `kind`, or nullptr for an unknown kind.
std::unique_ptr<P2gScheme> make_p2g_scheme(pf_p2g kind);

}  // namespace pf
