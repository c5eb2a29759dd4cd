// Conjugate gradients with a stored z (the multigrid V-cycle), per cell: x += alpha p, r -= alpha q
// on FLUID cells, and the V-cycle's first pass, which needs nothing but the cell's new r: the red
// half-sweep from zero, start = r / diag on red FLUID cells and 0 elsewhere (gauss_seidel.comp's
// PF_GS_FROM_ZERO) — one pass less per iteration. The V-cycle's last pass sums z and runs the
// beta step (mg_smooth_zstats.comp). A pair solve (PF_PAIR 1) does both problems, each with its
// own alpha (0 once that problem has stopped), the second's iterate in x_second.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_SOLVER_X) buffer X { float x[]; };
#if PF_PAIR
layout(std430, binding = PF_SLOT_SOLVER_UPDATE_X_SECOND) buffer XSecond { float x_second[]; };
#endif
layout(std430, binding = PF_SLOT_SOLVER_R) buffer R { value_t r[]; };
layout(std430, binding = PF_SLOT_SOLVER_P) readonly buffer P { value_t p[]; };
layout(std430, binding = PF_SLOT_SOLVER_Q) readonly buffer Q { value_t q[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
layout(std430, binding = PF_SLOT_SOLVER_MG_START) writeonly buffer Start { value_t start[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/state.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_dims.w) return;
    value_t first = value_t(0.0);
    if (PF_CELL_KIND(cell_type[c]) == PF_CELL_FLUID) {
#if PF_PAIR
        vec2 alpha = live_state_value(PF_SOLVER_ALPHA);
        vec2 pc = p[c];
        x[c] += alpha.x * pc.x;
        x_second[c] += alpha.y * pc.y;
#else
        float alpha = state_float(PF_SOLVER_ALPHA);
        x[c] += alpha * p[c];
#endif
        value_t rn = r[c] - alpha * q[c];
        r[c] = rn;
        ivec3 ijk = level_coord(c);
        float diag = cell_color_at(ijk) == 0u ? poisson_stencil_at(c, ijk).diag : 0.0;
        first = diag > 0.0 ? rn / diag : value_t(0.0);
    }
    start[c] = first;  // read by the V-cycle's black half-sweep (not in this pass)
}
