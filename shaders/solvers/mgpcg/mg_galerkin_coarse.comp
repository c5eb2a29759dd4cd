// Multigrid (Galerkin levels), the coarsest level in one workgroup: e = 0, then symmetric
// Gauss-Seidel sweeps with the level's stored 3^3 stencil (galerkin.glsl), its cells coloured by
// the parity of each coordinate (8 colours: no two cells of a colour are neighbours), the
// colours forward then backward, PF_MG_GALERKIN_COARSE_PAIRS times — palindromic, so the V-cycle stays
// symmetric. Each invocation owns two cells (2i, 2i + 1); e lives in shared memory. Skipped once
// the solve has converged.
// A pair solve (PF_PAIR 1, solver_value.glsl) does both problems: vec2 values.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
#include "solvers/mgpcg/multigrid_limits.h"
layout(local_size_x = PF_MG_COARSE_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_R) readonly buffer R { value_t r[]; };
layout(std430, binding = PF_SLOT_MG_STENCIL) readonly buffer LevelStencil { float stencil[]; };
layout(std430, binding = PF_SLOT_MG_TMP) writeonly buffer E { value_t e[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/state.glsl"
#include "solvers/mgpcg/galerkin.glsl"

shared value_t s_e[PF_MG_COARSE_CELLS];

int g_cell;
ivec3 g_coord;

value_t term(ivec3 o) {
    float a = stencil[stencil_slot(o) * u_dims.w + g_cell];
    ivec3 q = g_coord + o;
    return a != 0.0 && level_inside(q) ? a * s_e[level_index(q)] : value_t(0.0);
}
#include "solvers/mgpcg/galerkin_sum.glsl"

void relax(int c, uint color) {
    if (c >= u_dims.w) return;
    ivec3 ijk = level_coord(c);
    if (uint((ijk.x & 1) + 2 * (ijk.y & 1) + 4 * (ijk.z & 1)) != color) return;
    float diag = stencil[kCentre * u_dims.w + c];
    if (PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID || diag <= 0.0) return;
    g_cell = c;
    g_coord = ijk;
    s_e[c] += (r[c] - galerkin_sum()) / diag;
}

void colour_step(int first, uint color) {
    relax(first, color);
    relax(first + 1, color);
    barrier();
}

void main() {
    if (solve_converged()) return;  // uniform across the workgroup
    int first = 2 * int(gl_LocalInvocationIndex);
    s_e[first] = value_t(0.0);
    s_e[first + 1] = value_t(0.0);
    barrier();
    for (int k = 0; k < PF_MG_GALERKIN_COARSE_PAIRS; ++k) {
        for (uint color = 0u; color < 8u; ++color) colour_step(first, color);
        for (uint color = 8u; color-- > 0u;) colour_step(first, color);
    }
    if (first < u_dims.w) e[first] = s_e[first];
    if (first + 1 < u_dims.w) e[first + 1] = s_e[first + 1];
}
