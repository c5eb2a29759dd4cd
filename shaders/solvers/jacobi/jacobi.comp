// One (weighted) Jacobi iteration of the pressure Poisson equation on FLUID cells:
//   sum over in-domain neighbours j of (p_i - p_j) = b_i,  p = 0 in AIR, walls excluded.
// With separation on, each iterate is projected onto p >= 0 (projected Jacobi for the
// complementarity problem of Gerszewski & Bargteil 2013): liquid may expand into air
// (leave a wall, the lid, or itself) but is never held by suction.
// Ping-pong: reads PF_SLOT_PRESSURE, writes PF_SLOT_PRESSURE_OUT.
#include "common/sim.glsl"
#include "solvers/jacobi/jacobi_locations.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_RHS) readonly buffer Rhs { float rhs[]; };
layout(std430, binding = PF_SLOT_PRESSURE) readonly buffer Pressure { float p_in[]; };
layout(std430, binding = PF_SLOT_PRESSURE_OUT) writeonly buffer PressureOut { float p_out[]; };
layout(location = PF_LOC_JACOBI_OMEGA) uniform float u_omega;  // relaxation weight in (0, 1]

void main() {
    int c = int(flat_id());
    if (c >= sim.grid.w) return;
    if (cell_type[c] != PF_CELL_FLUID) {
        p_out[c] = 0.0;
        return;
    }
    ivec3 ijk = ivec3(c % sim.grid.x, (c / sim.grid.x) % sim.grid.y, c / (sim.grid.x * sim.grid.y));
    // Neighbour pressures summed per axis pair first, so mirrored inputs sum identically.
    vec3 pair_sum = vec3(0.0);
    float diag = 0.0;
    for (int n = 0; n < 6; ++n) {
        ivec3 nb = ijk + kNeighbours[n];
        if (!cell_inside(nb)) continue;
        int nc = cell_index(nb);
        uint t = cell_type[nc];
        if (t == PF_CELL_SOLID) continue;
        diag += 1.0;
        if (t == PF_CELL_FLUID) pair_sum[n / 2] += p_in[nc];
    }
    float sum = (pair_sum.x + pair_sum.y) + pair_sum.z;
    float omega = u_omega;
    float p = (1.0 - omega) * p_in[c] + omega * (rhs[c] + sum) / diag;
    p_out[c] = sim.separation != 0u ? max(p, 0.0) : p;
}
