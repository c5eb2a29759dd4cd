// Start of every solve, per workgroup: (sum b, b.b, FLUID cells, AIR cells). The system is
// singular when no cell is AIR (a closed, full domain): then begin_solve removes the mean of b
// so the system is consistent. A pair solve (PF_PAIR 1) sums each problem's b in a column
// of its own (the second problem's b in rhs_second).
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
#if defined(PF_PAIR) && PF_PAIR
#define PF_SUMS 2
#endif
#include "solvers/common/solver_value.glsl"
layout(local_size_x = PF_REDUCTION_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_RHS) readonly buffer Rhs { float rhs[]; };
#if PF_PAIR
layout(std430, binding = PF_SLOT_SOLVER_RHS_SECOND) readonly buffer RhsSecond { float rhs_second[]; };
#endif
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"

vec4 rhs_sums(uint t, float b) {
    if (t == PF_CELL_FLUID) return vec4(b, b * b, 1.0, 0.0);
    return vec4(0.0, 0.0, 0.0, t == PF_CELL_AIR ? 1.0 : 0.0);
}

sums_t cell_contribution(int c, ivec3 ijk) {
    uint t = PF_CELL_KIND(cell_type[c]);
    bool fluid = t == PF_CELL_FLUID;
#if PF_PAIR
    return mat2x4(rhs_sums(t, fluid ? rhs[c] : 0.0), rhs_sums(t, fluid ? rhs_second[c] : 0.0));
#else
    return rhs_sums(t, fluid ? rhs[c] : 0.0);
#endif
}
#include "solvers/common/orbit_main.glsl"
