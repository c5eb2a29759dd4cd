// Multigrid, the coarsest level in one workgroup: e = 0, then red-black Gauss-Seidel half-sweeps
// in the palindromic order red, (black, red) x PF_MG_COARSE_SWEEPS — the same operator forwards
// and backwards, which keeps the V-cycle symmetric — then e is written out. One workgroup runs
// this, so it is pure latency: each invocation owns two cells (indices 2i and 2i+1), keeps their
// right-hand side, colour and stencil (a mask of FLUID neighbours and the diagonal) in registers,
// and every sweep touches only e in shared memory — no index arithmetic, no global memory, and
// an invocation with no cell of the sweep's colour just waits at the barrier. (Looping over the
// level in strides of the workgroup, recomputing each cell's colour by integer division, took
// ~75 us a solve on the H100; docs/accuracy.md.) Skipped once the solve has converged.
// A pair solve (PF_PAIR 1, solver_value.glsl) does both problems: vec2 values.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
#include "solvers/mgpcg/multigrid_limits.h"
layout(local_size_x = PF_MG_COARSE_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_R) readonly buffer R { value_t r[]; };
layout(std430, binding = PF_SLOT_MG_E) writeonly buffer E { value_t e[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/state.glsl"

shared value_t s_e[PF_MG_COARSE_CELLS];

// One owned cell: its index, right-hand side, 1/diag, FLUID-neighbour mask (bits 0-5) and
// colour; `live` is false for a cell past the level's end or not FLUID (its e stays 0).
struct OwnedCell {
    int c;
    value_t rhs;
    float diag;
    uint mask, color;
    bool live;
};

OwnedCell own(int c) {
    OwnedCell o;
    o.c = c;
    o.rhs = value_t(0.0);
    o.diag = 0.0;
    o.mask = 0u;
    o.color = 0u;
    o.live = false;
    if (c < u_dims.w && PF_CELL_KIND(cell_type[c]) == PF_CELL_FLUID) {
        ivec3 ijk = level_coord(c);
        PoissonStencil s = poisson_stencil_at(c, ijk);
        for (int n = 0; n < 6; ++n) o.mask |= s.nb[n] >= 0 ? 1u << n : 0u;
        o.diag = s.diag;
        o.rhs = r[c];
        o.color = cell_color_at(ijk);
        o.live = s.diag > 0.0;
    }
    return o;
}

void relax(OwnedCell o, uint color) {
    if (!o.live || o.color != color) return;
    const int step[6] = lattice_steps(u_dims.xyz);
    pairs_t pair_sum = pairs_t(0.0);
    for (int n = 0; n < 6; ++n) {
        if ((o.mask & (1u << n)) != 0u) pair_sum[n / 2] += s_e[o.c + step[n]];
    }
    s_e[o.c] = (o.rhs + pair_total(pair_sum)) / o.diag;
}

void half_sweep(OwnedCell a, OwnedCell b, uint color) {
    relax(a, color);
    relax(b, color);
    barrier();
}

void main() {
    if (solve_converged()) return;  // uniform across the workgroup
    int first = 2 * int(gl_LocalInvocationIndex);
    OwnedCell a = own(first), b = own(first + 1);
    s_e[first] = value_t(0.0);
    s_e[first + 1] = value_t(0.0);
    barrier();
    half_sweep(a, b, 0u);
    for (int k = 0; k < PF_MG_COARSE_SWEEPS; ++k) {
        half_sweep(a, b, 1u);
        half_sweep(a, b, 0u);
    }
    if (a.c < u_dims.w) e[a.c] = s_e[a.c];
    if (b.c < u_dims.w) e[b.c] = s_e[b.c];
}
