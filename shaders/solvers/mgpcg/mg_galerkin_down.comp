// Multigrid (Galerkin levels), a Galerkin level's way down in one pass: its pre-smoothing, one
// damped Jacobi step from zero, e = omega r / diag (galerkin.glsl), the residual r - A e with the
// level's stored stencil, and its restriction to the next level by aggregation (the sum over a
// coarse cell's children). e is not stored: each term recomputes it from r and the neighbour's
// diagonal. Eight invocations make one coarse cell, one per child; the workgroup adds the
// children's residuals in a mirror-exact order.
// A pair solve (PF_PAIR 1, solver_value.glsl) does both problems: vec2 values.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_R) readonly buffer R { value_t r[]; };
layout(std430, binding = PF_SLOT_MG_STENCIL) readonly buffer LevelStencil { float stencil[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_R) writeonly buffer CoarseR { value_t coarse_r[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/mgpcg/multigrid.glsl"
#include "solvers/mgpcg/galerkin.glsl"

shared value_t s_res[PF_WORKGROUP_SIZE];

int g_cell;
ivec3 g_coord;

float coefficient(int k, int c) { return stencil[k * u_dims.w + c]; }

// The pre-smoothed e at q (0 outside the level or where q is not FLUID: its diagonal is 0).
value_t smoothed(ivec3 q) {
    if (!level_inside(q)) return value_t(0.0);
    int qi = level_index(q);
    float diag = coefficient(kCentre, qi);
    return diag > 0.0 ? (kGalerkinOmega / diag) * r[qi] : value_t(0.0);
}

value_t term(ivec3 o) {
    float a = coefficient(stencil_slot(o), g_cell);
    return a != 0.0 ? a * smoothed(g_coord + o) : value_t(0.0);
}
#include "solvers/mgpcg/galerkin_sum.glsl"

void main() {
    int id = int(flat_id());
    int coarse = id >> 3;
    int child = id & 7;
    ivec3 coarsened = ivec3(lessThan(u_coarse_dims.xyz, u_dims.xyz));
    ivec3 d = ivec3(child & 1, (child >> 1) & 1, child >> 2);
    value_t res = value_t(0.0);
    if (coarse < u_coarse_dims.w && all(lessThanEqual(d, coarsened))) {
        g_coord = (lattice_coord(u_coarse_dims.xyz, coarse) << coarsened) + d;
        if (level_inside(g_coord)) {
            g_cell = level_index(g_coord);
            if (PF_CELL_KIND(cell_type[g_cell]) == PF_CELL_FLUID) res = r[g_cell] - galerkin_sum();
        }
    }
    uint local = gl_LocalInvocationID.x;
    s_res[local] = res;
    barrier();
    if (child != 0 || coarse >= u_coarse_dims.w) return;
    // ((x pairs) + (their z mirrors)) for each y, children indexed x + 2 y + 4 z.
    value_t low = (s_res[local + 0u] + s_res[local + 1u]) + (s_res[local + 4u] + s_res[local + 5u]);
    value_t high = (s_res[local + 2u] + s_res[local + 3u]) + (s_res[local + 6u] + s_res[local + 7u]);
    coarse_r[coarse] = low + high;
}
