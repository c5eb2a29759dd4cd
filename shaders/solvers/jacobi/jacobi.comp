// One (weighted) Jacobi sweep of the pressure Poisson equation on FLUID cells:
//   sum over in-domain neighbours j of (p_i - p_j) = b_i,  p = 0 in AIR, walls excluded
// (solvers/common/poisson.glsl). With separation on, each iterate is projected onto p >= 0
// (projected Jacobi for the complementarity problem of Gerszewski & Bargteil 2013): liquid may
// expand into air (leave a wall, the lid, or itself) but is never held by suction.
// Ping-pong: reads PF_SLOT_PRESSURE, writes PF_SLOT_PRESSURE_OUT.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#include "solvers/jacobi/jacobi_locations.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_RHS) readonly buffer Rhs { float rhs[]; };
layout(std430, binding = PF_SLOT_PRESSURE) readonly buffer Pressure { float p_in[]; };
layout(std430, binding = PF_SLOT_PRESSURE_OUT) writeonly buffer PressureOut { float p_out[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
layout(location = PF_LOC_JACOBI_OMEGA) uniform float u_omega;  // relaxation weight in (0, 1]
#include "solvers/common/poisson.glsl"
#include "solvers/common/state.glsl"

void main() {
    int c = int(flat_id());
    if (c >= u_dims.w) return;
    if (PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID) {
        p_out[c] = 0.0;
        return;
    }
    PoissonStencil s = poisson_stencil(c);
    vec3 pair_sum = vec3(0.0);
    for (int n = 0; n < 6; ++n) {
        if (s.nb[n] >= 0) pair_sum[n / 2] += p_in[s.nb[n]];
    }
    // diag = 0: a FLUID cell walled in by SOLID cells and domain walls (no equation): p = 0.
    float p = s.diag > 0.0 ? (1.0 - u_omega) * p_in[c] + u_omega * (rhs[c] - rhs_mean() + pair_total(pair_sum)) / s.diag : 0.0;
    p_out[c] = project_nonnegative() ? max(p, 0.0) : p;
}
