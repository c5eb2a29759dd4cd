// Start of every solve, per workgroup: (sum b, b.b, FLUID cells, AIR cells). The system is
// singular when no cell is AIR (a closed, full domain): then begin_solve removes the mean of b
// so the system is consistent.
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_REDUCTION_INVOCATIONS) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_RHS) readonly buffer Rhs { float rhs[]; };
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
#include "solvers/common/poisson.glsl"
#include "solvers/common/reduce.glsl"

vec4 cell_contribution(int c, ivec3 ijk) {
    uint t = PF_CELL_KIND(cell_type[c]);
    if (t == PF_CELL_FLUID) {
        float b = rhs[c];
        return vec4(b, b * b, 1.0, 0.0);
    }
    return vec4(0.0, 0.0, 0.0, t == PF_CELL_AIR ? 1.0 : 0.0);
}
#include "solvers/common/orbit_main.glsl"
