// Multigrid, one coarse level's way up in one pass per tile of PF_MG_UP_TILE^3 cells: the
// coarse correction and the whole post-smoothing sweep (black, then red), out = the level's
// result. With c = P e_coarse (multigrid.glsl's trilinear stencil), red FLUID cells take
// e + c, black FLUID cells a Gauss-Seidel update from those, and red FLUID cells then one from
// the black results; cells that are not FLUID get 0. mg_prolong_smooth.comp and a red
// half-sweep in one pass (the fine level keeps those two: its red half-sweep is fused with CG's
// sums instead, mg_smooth_zstats.comp). The tile is staged with a halo of two cells (a red
// result needs its black neighbours, each of which needs its red neighbours corrected) and
// the coarse values beneath it; halo cells are computed again by the neighbouring tiles.
// Only e's red values are read: black cells are overwritten by the sweep. The arithmetic per
// cell is the unfused passes' (same terms, same order).
// A pair solve (PF_PAIR 1, solver_value.glsl) does both problems: vec2 values.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/common/solver_value.glsl"
#include "solvers/mgpcg/multigrid_limits.h"
layout(local_size_x = PF_MG_TILE_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_R) readonly buffer R { value_t r[]; };
layout(std430, binding = PF_SLOT_MG_E) readonly buffer E { value_t e[]; };
layout(std430, binding = PF_SLOT_MG_TMP) writeonly buffer Out { value_t out_e[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_E) readonly buffer CoarseE { value_t coarse_e[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/mgpcg/multigrid.glsl"

const int kTile = PF_MG_UP_TILE;
const int kStaged = kTile + 4;      // fine cells per axis of the staged types and values
const int kCoarse = kTile / 2 + 4;  // coarse cells per axis of the staged coarse values
const int kStagedCells = kStaged * kStaged * kStaged;
shared value_t s_e[kStaged * kStaged * kStaged];
shared value_t s_coarse[kCoarse * kCoarse * kCoarse];
#include "solvers/mgpcg/multigrid_tile.glsl"

void main() {
    ivec3 tiles = tile_dims(u_dims.xyz, kTile);
    int g = int(workgroup_index());
    if (g >= lattice_total(tiles)) return;  // uniform across the workgroup
    ivec3 t0 = tile_first_cell(tile_coord(g, tiles), kTile);
    ivec3 origin = t0 - 2;                  // fine coordinates of staged cell 0
    ivec3 coarse_origin = (t0 >> 1) - 2;    // coarse coordinates of s_coarse[0]
    int lid = int(gl_LocalInvocationIndex);
    clear_staged_types();

    for (int i = lid; i < kCoarse * kCoarse * kCoarse; i += PF_MG_TILE_INVOCATIONS) {
        ivec3 c = coarse_origin + tile_local(i, kCoarse);
        bool inside = coarse_inside(c);
        s_coarse[i] = inside ? coarse_e[coarse_index(c)] : value_t(0.0);
    }
    for (int i = lid; i < kStaged * kStaged * kStaged; i += PF_MG_TILE_INVOCATIONS) {
        ivec3 f = origin + tile_local(i, kStaged);
        stage_type(i, level_inside(f) ? cell_type[level_index(f)] : uint(PF_CELL_SOLID));
    }
    barrier();

    // Red FLUID cells of the staged block: e + P e_coarse (mg_prolong_smooth.comp's corrected()).
    for (int i = lid; i < kStaged * kStaged * kStaged; i += PF_MG_TILE_INVOCATIONS) {
        ivec3 f = origin + tile_local(i, kStaged);
        value_t v = value_t(0.0);
        if (cell_color_at(f) == 0u && PF_CELL_KIND(staged_type(i)) == PF_CELL_FLUID) {
            ivec3 parent = f >> 1;
            ivec3 other = clamp(parent + 2 * (f & 1) - 1, ivec3(0), u_coarse_dims.xyz - 1);
            value_t sum = value_t(0.0);
            for (int n = 0; n < 8; ++n) {
                ivec3 pick = ivec3(n & 1, (n >> 1) & 1, (n >> 2) & 1);
                ivec3 c = parent + pick * (other - parent);
                vec3 w = vec3(0.75) - 0.5 * vec3(pick);
                sum += w.x * w.y * w.z * s_coarse[tile_index(c - coarse_origin, kCoarse)];
            }
            v = e[level_index(f)] + sum;
        }
        s_e[i] = v;
    }
    barrier();

    // Black FLUID cells one cell past the tile, from their corrected red neighbours (in place:
    // they read only red cells).
    const int steps[6] = tile_steps(kStaged);
    for (int i = lid; i < (kTile + 2) * (kTile + 2) * (kTile + 2); i += PF_MG_TILE_INVOCATIONS) {
        ivec3 local = tile_local(i, kTile + 2) + 1;
        ivec3 f = origin + local;
        int s = tile_index(local, kStaged);
        if (cell_color_at(f) == 0u || PF_CELL_KIND(staged_type(s)) != PF_CELL_FLUID) continue;
        float diag;
        pairs_t pair_sum;
        staged_stencil(s, steps, diag, pair_sum);
        s_e[s] = diag > 0.0 ? (r[level_index(f)] + pair_total(pair_sum)) / diag : value_t(0.0);
    }
    barrier();

    // The tile's cells: red FLUID cells from their black neighbours, black ones as swept.
    for (int i = lid; i < kTile * kTile * kTile; i += PF_MG_TILE_INVOCATIONS) {
        ivec3 local = tile_local(i, kTile) + 2;
        ivec3 f = origin + local;
        if (!level_inside(f)) continue;
        int s = tile_index(local, kStaged);
        value_t v = value_t(0.0);
        if (PF_CELL_KIND(staged_type(s)) == PF_CELL_FLUID) {
            if (cell_color_at(f) == 0u) {
                float diag;
                pairs_t pair_sum;
                staged_stencil(s, steps, diag, pair_sum);
                v = diag > 0.0 ? (r[level_index(f)] + pair_total(pair_sum)) / diag : value_t(0.0);
            } else {
                v = s_e[s];
            }
        }
        out_e[level_index(f)] = v;
    }
}
