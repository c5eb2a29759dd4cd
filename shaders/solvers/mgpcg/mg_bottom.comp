// Multigrid, the bottom of the V-cycle in one workgroup: the level above the coarsest (at most
// PF_MG_BOTTOM_CELLS cells) and the coarsest, where the fused passes took three dispatches
// (mg_down.comp, mg_coarse_solve.comp, mg_up.comp), each mostly launch and barrier at these
// sizes. Here the level's correction lives in shared memory and each invocation keeps its own
// cells' stencils (a mask of FLUID neighbours and the diagonal), right-hand sides and red values
// in registers, as mg_coarse_solve.comp does for the coarsest level:
//   the black half-sweep that completes the pre-smoothing (e holds the red half-sweep from zero,
//   written with r by the finer level's pass); the residual, restricted to the coarsest level
//   (R = P^T / 2, multigrid.glsl); the coarsest level's symmetric sweeps from zero; the
//   correction e + P e_coarse on red cells, then black and red half-sweeps; out = the result.
// The arithmetic per cell is that of the three passes (same terms, same order), so the V-cycle
// is the same operator. Skipped once the solve has converged.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/mgpcg/multigrid_limits.h"
layout(local_size_x = PF_MG_BOTTOM_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_MG_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_MG_R) readonly buffer R { float r[]; };
layout(std430, binding = PF_SLOT_MG_E) readonly buffer E { float e[]; };
layout(std430, binding = PF_SLOT_MG_COARSE_TYPE) readonly buffer CoarseType { uint coarse_type[]; };
layout(std430, binding = PF_SLOT_MG_TMP) writeonly buffer Out { float out_e[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/state.glsl"
#include "solvers/mgpcg/multigrid.glsl"
#include "solvers/mgpcg/restriction.glsl"

const int kOwned = PF_MG_BOTTOM_CELLS / PF_MG_BOTTOM_INVOCATIONS;  // level cells per invocation
shared float s_e[PF_MG_BOTTOM_CELLS];       // the level's correction, for a while its residual
shared float s_rc[PF_MG_COARSE_CELLS];      // the coarsest level's right-hand side
shared float s_ec[PF_MG_COARSE_CELLS];      // the coarsest level's correction

// One owned cell of the level, packed to keep a workgroup of PF_MG_BOTTOM_INVOCATIONS within
// the registers: its FLUID-neighbour mask (bits 0-5, kPoissonNeighbours' order), kFluid and
// kRed; the diagonal (poisson.glsl's: in-level neighbours that are not SOLID, then the word's
// surface term), the right-hand side and e's red value (red FLUID cells, else 0).
const uint kFluid = 64u, kRed = 128u;
struct Owned {
    uint flags;
    float diag, rhs, red;
};

Owned own(int c) {
    Owned o;
    o.flags = 0u;
    o.diag = 0.0;
    o.rhs = 0.0;
    o.red = 0.0;
    if (c >= u_dims.w) return o;
    ivec3 ijk = level_coord(c);
    if (cell_color_at(ijk) == 0u) o.flags |= kRed;
    if (PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID) return o;
    o.flags |= kFluid;
    for (int n = 0; n < 6; ++n) {
        ivec3 q = ijk + kPoissonNeighbours[n];
        if (!level_inside(q)) continue;
        uint kind = PF_CELL_KIND(cell_type[level_index(q)]);
        if (kind == PF_CELL_SOLID) continue;
        o.diag += 1.0;
        if (kind == PF_CELL_FLUID) o.flags |= 1u << n;
    }
    o.diag += surface_extra_diagonal(cell_type[c]);
    o.rhs = r[c];
    if ((o.flags & kRed) != 0u) o.red = e[c];
    return o;
}

bool fluid(Owned o) { return (o.flags & kFluid) != 0u; }
bool red(Owned o) { return (o.flags & kRed) != 0u; }

// Cell c's FLUID neighbours' values in s_e summed per axis pair (`step`: the level's strides).
vec3 fine_pairs(Owned o, int c, int step[6]) {
    vec3 pair_sum = vec3(0.0);
    for (int n = 0; n < 6; ++n) {
        if ((o.flags & (1u << n)) != 0u) pair_sum[n / 2] += s_e[c + step[n]];
    }
    return pair_sum;
}

float relaxed(Owned o, int c, int step[6]) {
    return o.diag > 0.0 ? (o.rhs + pair_total(fine_pairs(o, c, step))) / o.diag : 0.0;
}

void main() {
    if (solve_converged()) return;  // uniform across the workgroup
    int lid = int(gl_LocalInvocationIndex);
    const int step[6] = lattice_steps(u_dims.xyz);
    // Owned cells lid + k * PF_MG_BOTTOM_INVOCATIONS (coalesced loads).
    Owned cell[kOwned];
    for (int k = 0; k < kOwned; ++k) {
        int c = lid + k * PF_MG_BOTTOM_INVOCATIONS;
        cell[k] = own(c);
        if (c < u_dims.w) s_e[c] = cell[k].red;
    }
    barrier();

    // Pre-smoothing's black half-sweep (black cells read only red ones).
    for (int k = 0; k < kOwned; ++k) {
        int c = lid + k * PF_MG_BOTTOM_INVOCATIONS;
        if (fluid(cell[k]) && !red(cell[k])) s_e[c] = relaxed(cell[k], c, step);
    }
    barrier();

    // The residual (0 where not FLUID), kept while every invocation still reads e, then stored
    // over e for the restriction.
    float res[kOwned];
    for (int k = 0; k < kOwned; ++k) {
        int c = lid + k * PF_MG_BOTTOM_INVOCATIONS;
        Owned o = cell[k];
        res[k] = fluid(o) ? o.rhs - (o.diag * s_e[c] - pair_total(fine_pairs(o, c, step))) : 0.0;
    }
    barrier();
    for (int k = 0; k < kOwned; ++k) {
        int c = lid + k * PF_MG_BOTTOM_INVOCATIONS;
        if (c < u_dims.w) s_e[c] = res[k];
    }
    barrier();

    // The restriction onto the coarsest level (mg_down.comp's sum: fine cells 2 cc - 1 .. 2 cc + 2
    // per axis, weights 0 outside the level), one coarse cell per invocation, and that cell's
    // stencil on the coarsest level (mg_coarse_solve.comp's).
    int cc_index = lid;
    bool coarse_live = false;
    uint coarse_mask = 0u;
    float coarse_diag_value = 0.0;
    ivec3 cc = lattice_coord(u_coarse_dims.xyz, cc_index);
    float rc = 0.0;
    bool coarse_fluid = cc_index < u_coarse_dims.w && PF_CELL_KIND(coarse_type[cc_index]) == PF_CELL_FLUID;
    if (coarse_fluid) {
        vec4 wx, wy, wz;
        for (int d = 0; d < 4; ++d) {
            ivec3 f = 2 * cc + (d - 1);
            wx[d] = f.x >= 0 && f.x < u_dims.x ? prolong_weight_1d(f.x, cc.x, u_coarse_dims.x) : 0.0;
            wy[d] = f.y >= 0 && f.y < u_dims.y ? prolong_weight_1d(f.y, cc.y, u_coarse_dims.y) : 0.0;
            wz[d] = f.z >= 0 && f.z < u_dims.z ? prolong_weight_1d(f.z, cc.z, u_coarse_dims.z) : 0.0;
        }
        float sum = 0.0;
        for (int dz = 0; dz < 4; ++dz) {
            for (int dy = 0; dy < 4; ++dy) {
                float wyz = wz[dz] * wy[dy];
                for (int dx = 0; dx < 4; ++dx) {
                    ivec3 f = 2 * cc + ivec3(dx, dy, dz) - 1;
                    float value = level_inside(f) ? s_e[level_index(f)] : 0.0;
                    sum += wyz * wx[dx] * value;
                }
            }
        }
        rc = restrict_scale() * sum;
        for (int n = 0; n < 6; ++n) {
            ivec3 q = cc + kPoissonNeighbours[n];
            if (!coarse_inside(q)) continue;
            uint kind = PF_CELL_KIND(coarse_type[coarse_index(q)]);
            if (kind == PF_CELL_SOLID) continue;
            coarse_diag_value += 1.0;
            if (kind == PF_CELL_FLUID) coarse_mask |= 1u << n;
        }
        coarse_diag_value += surface_extra_diagonal(coarse_type[cc_index]);
        coarse_live = coarse_diag_value > 0.0;
    }
    if (cc_index < PF_MG_COARSE_CELLS) s_ec[cc_index] = 0.0;
    barrier();

    // The coarsest level: red, then (black, red) x PF_MG_COARSE_SWEEPS, from zero.
    const int coarse_step[6] = lattice_steps(u_coarse_dims.xyz);
    uint coarse_color = cell_color_at(cc);
    for (int sweep = 0; sweep < 2 * PF_MG_COARSE_SWEEPS + 1; ++sweep) {
        uint color = uint(sweep & 1);
        if (coarse_live && coarse_color == color) {
            vec3 pair_sum = vec3(0.0);
            for (int n = 0; n < 6; ++n) {
                if ((coarse_mask & (1u << n)) != 0u) pair_sum[n / 2] += s_ec[cc_index + coarse_step[n]];
            }
            s_ec[cc_index] = (rc + pair_total(pair_sum)) / coarse_diag_value;
        }
        barrier();
    }

    // The correction on red FLUID cells (mg_up.comp's), every other cell 0.
    for (int k = 0; k < kOwned; ++k) {
        int c = lid + k * PF_MG_BOTTOM_INVOCATIONS;
        Owned o = cell[k];
        if (c >= u_dims.w) continue;
        float v = 0.0;
        if (fluid(o) && red(o)) {
            ivec3 f = level_coord(c);
            ivec3 parent = f >> 1;
            ivec3 other = clamp(parent + 2 * (f & 1) - 1, ivec3(0), u_coarse_dims.xyz - 1);
            float sum = 0.0;
            for (int n = 0; n < 8; ++n) {
                ivec3 pick = ivec3(n & 1, (n >> 1) & 1, (n >> 2) & 1);
                ivec3 q = parent + pick * (other - parent);
                vec3 w = vec3(0.75) - 0.5 * vec3(pick);
                sum += w.x * w.y * w.z * s_ec[coarse_index(q)];
            }
            v = o.red + sum;
        }
        s_e[c] = v;
    }
    barrier();

    // Post-smoothing: black from the corrected red cells, then red from the black ones.
    for (int k = 0; k < kOwned; ++k) {
        int c = lid + k * PF_MG_BOTTOM_INVOCATIONS;
        if (fluid(cell[k]) && !red(cell[k])) s_e[c] = relaxed(cell[k], c, step);
    }
    barrier();
    for (int k = 0; k < kOwned; ++k) {
        int c = lid + k * PF_MG_BOTTOM_INVOCATIONS;
        Owned o = cell[k];
        if (c < u_dims.w) out_e[c] = fluid(o) ? (red(o) ? relaxed(o, c, step) : s_e[c]) : 0.0;
    }
}
