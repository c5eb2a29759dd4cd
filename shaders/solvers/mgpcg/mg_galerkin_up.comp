// Multigrid (Galerkin levels), a Galerkin level's way up in one pass per cell: the coarse
// correction, e + alpha P e_coarse (P copies a parent's value to its children; galerkin.glsl), then
// one damped Jacobi step with the level's stored stencil, out = v + omega (r - A v) / diag. The
// pre-smoothed e = omega r / diag (mg_galerkin_down.comp) and v at each neighbour are recomputed
// here: nothing but r, the stencils and e_coarse is read. Cells that are not FLUID get 0.
// A pair solve (PF_PAIR 1, solver_value.glsl) does both problems: vec2 values.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_R) readonly buffer R { value_t r[]; };
layout(std430, binding = PF_SLOT_MG_STENCIL) readonly buffer LevelStencil { float stencil[]; };
layout(std430, binding = PF_SLOT_MG_TMP) writeonly buffer Out { value_t out_e[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_E) readonly buffer CoarseE { value_t coarse_e[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/mgpcg/multigrid.glsl"
#include "solvers/mgpcg/galerkin.glsl"

int g_cell;
ivec3 g_coord;
ivec3 g_coarsened;

float coefficient(int k, int c) { return stencil[k * u_dims.w + c]; }

// e + alpha P e_coarse at q (0 outside the level or where q is not FLUID: its diagonal is 0).
value_t corrected(ivec3 q) {
    if (!level_inside(q)) return value_t(0.0);
    int qi = level_index(q);
    float diag = coefficient(kCentre, qi);
    if (diag <= 0.0) return value_t(0.0);
    return (kGalerkinOmega / diag) * r[qi] + kGalerkinAlpha * coarse_e[coarse_index(parent_of(q, g_coarsened))];
}

value_t term(ivec3 o) {
    float a = coefficient(stencil_slot(o), g_cell);
    return a != 0.0 ? a * corrected(g_coord + o) : value_t(0.0);
}
#include "solvers/mgpcg/galerkin_sum.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_dims.w) return;
    value_t v = value_t(0.0);
    float diag = coefficient(kCentre, c);
    if (PF_CELL_KIND(cell_type[c]) == PF_CELL_FLUID && diag > 0.0) {
        g_cell = c;
        g_coord = level_coord(c);
        g_coarsened = ivec3(lessThan(u_coarse_dims.xyz, u_dims.xyz));
        v = corrected(g_coord) + (kGalerkinOmega / diag) * (r[c] - galerkin_sum());
    }
    out_e[c] = v;
}
