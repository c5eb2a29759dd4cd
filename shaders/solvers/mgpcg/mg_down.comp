// Multigrid, one level's way down in one pass per tile of PF_MG_DOWN_TILE^3 coarse cells: the
// black half-sweep that completes the pre-smoothing, the residual tmp = r - A e and its
// restriction r_coarse = (1/2) P^T tmp (multigrid.glsl), with, for PF_MG_START 1, the coarse
// level's first red half-sweep from zero. Three passes of the unfused V-cycle (a smoothing
// pass, the residual and the restriction, each a few microseconds of launch and barrier whatever the
// level's size; docs/performance.md) become one. The tile's fine cells and a halo are staged
// in shared memory: the restriction reads fine residuals 2 cc - 1 .. 2 cc + 2, each residual
// needs e at its neighbours, and a black e needs its red neighbours, so the staged region
// reaches three fine cells past the tile. Halo cells are computed again by the neighbouring
// tiles (no tile writes e), so no tile waits for another.
// e holds the red half-sweep from zero (written with r by the pass that made r: CG's update on
// the fine grid, this kernel's PF_MG_START on coarser ones); its black cells are not read. The
// arithmetic per cell is the unfused passes' (same terms, same order).
// A pair solve (PF_PAIR 1, solver_value.glsl) does both problems: vec2 values.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
#include "solvers/mgpcg/multigrid_limits.h"
layout(local_size_x = PF_MG_TILE_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_R) readonly buffer R { value_t r[]; };
layout(std430, binding = PF_SLOT_MG_E) readonly buffer E { value_t e[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_TYPE) readonly buffer CoarseType { uint coarse_type[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_R) writeonly buffer CoarseR { value_t coarse_r[]; };
#if PF_MG_START
layout(std430, binding = PF_SLOT_MG_COARSE_E) writeonly buffer CoarseE { value_t coarse_e[]; };
#endif
#include "solvers/common/poisson.glsl"
#include "solvers/mgpcg/multigrid.glsl"

const int kTile = PF_MG_DOWN_TILE;
const int kStaged = 2 * kTile + 6;    // fine cells per axis of the staged types and e
const int kResidual = 2 * kTile + 2;  // fine cells per axis of the residuals restricted
const int kStagedCells = kStaged * kStaged * kStaged;
shared value_t s_e[kStaged * kStaged * kStaged];
shared value_t s_res[kResidual * kResidual * kResidual];
#include "solvers/mgpcg/multigrid_tile.glsl"
#include "solvers/mgpcg/restriction.glsl"

void main() {
    ivec3 tiles = tile_dims(u_coarse_dims.xyz, kTile);
    int g = int(workgroup_index());
    if (g >= lattice_total(tiles)) return;  // uniform across the workgroup
    ivec3 c0 = tile_first_cell(tile_coord(g, tiles), kTile);
    ivec3 origin = 2 * c0 - 3;  // fine coordinates of staged cell 0
    int lid = int(gl_LocalInvocationIndex);
    clear_staged_types();

    // Stage types (outside the level: SOLID, which the stencil leaves out as poisson.glsl does)
    // and e's red FLUID values (everything else 0: the sweep started from zero).
    for (int i = lid; i < kStaged * kStaged * kStaged; i += PF_MG_TILE_INVOCATIONS) {
        ivec3 f = origin + tile_local(i, kStaged);
        uint word = uint(PF_CELL_SOLID);
        value_t value = value_t(0.0);
        if (level_inside(f)) {
            int c = level_index(f);
            word = cell_type[c];
            if (PF_CELL_KIND(word) == PF_CELL_FLUID && cell_color_at(f) == 0u) value = e[c];
        }
        stage_type(i, word);
        s_e[i] = value;
    }
    barrier();

    // The black half-sweep, one cell inside the staged region (in place: black cells read only
    // red neighbours, which nothing here writes).
    const int steps[6] = tile_steps(kStaged);
    for (int i = lid; i < (kStaged - 2) * (kStaged - 2) * (kStaged - 2); i += PF_MG_TILE_INVOCATIONS) {
        ivec3 local = tile_local(i, kStaged - 2) + 1;
        ivec3 f = origin + local;
        int s = tile_index(local, kStaged);
        if (cell_color_at(f) == 0u || PF_CELL_KIND(staged_type(s)) != PF_CELL_FLUID) continue;
        float diag;
        pairs_t pair_sum;
        staged_stencil(s, steps, diag, pair_sum);
        s_e[s] = diag > 0.0 ? (r[level_index(f)] + pair_total(pair_sum)) / diag : value_t(0.0);
    }
    barrier();

    // Residuals of the fine cells the tile's coarse cells gather (0 where not FLUID).
    for (int i = lid; i < kResidual * kResidual * kResidual; i += PF_MG_TILE_INVOCATIONS) {
        ivec3 local = tile_local(i, kResidual) + 2;
        int s = tile_index(local, kStaged);
        value_t res = value_t(0.0);
        if (PF_CELL_KIND(staged_type(s)) == PF_CELL_FLUID) {
            float diag;
            pairs_t pair_sum;
            staged_stencil(s, steps, diag, pair_sum);
            res = r[level_index(origin + local)] - (diag * s_e[s] - pair_total(pair_sum));
        }
        s_res[i] = res;
    }
    barrier();

    if (lid >= kTile * kTile * kTile) return;
    ivec3 cc = c0 + tile_local(lid, kTile);
    if (!coarse_inside(cc)) return;  // cc >= 0
    int c = coarse_index(cc);
    bool fluid = PF_CELL_KIND(coarse_type[c]) == PF_CELL_FLUID;
    value_t rc = value_t(0.0);
    if (fluid) {
        // Per axis: the fine cells 2 cc - 1 .. 2 cc + 2 (s_res index 2 (cc - c0) + d) and their
        // weights, 0 outside the level (whose residuals were staged as 0).
        ivec3 base = 2 * (cc - c0);
        vec4 wx, wy, wz;
        for (int d = 0; d < 4; ++d) {
            ivec3 f = 2 * cc + (d - 1);
            wx[d] = f.x >= 0 && f.x < u_dims.x ? prolong_weight_1d(f.x, cc.x, u_coarse_dims.x) : 0.0;
            wy[d] = f.y >= 0 && f.y < u_dims.y ? prolong_weight_1d(f.y, cc.y, u_coarse_dims.y) : 0.0;
            wz[d] = f.z >= 0 && f.z < u_dims.z ? prolong_weight_1d(f.z, cc.z, u_coarse_dims.z) : 0.0;
        }
        value_t sum = value_t(0.0);
        for (int dz = 0; dz < 4; ++dz) {
            for (int dy = 0; dy < 4; ++dy) {
                float wyz = wz[dz] * wy[dy];
                int row = tile_index(base + ivec3(0, dy, dz), kResidual);
                for (int dx = 0; dx < 4; ++dx) sum += wyz * wx[dx] * s_res[row + dx];
            }
        }
        rc = restrict_scale() * sum;
    }
    coarse_r[c] = rc;
#if PF_MG_START
    bool red = cell_color_at(cc) == 0u;
    float diag = fluid && red ? coarse_diag(cc) : 0.0;
    coarse_e[c] = diag > 0.0 ? rc / diag : value_t(0.0);
#endif
}
