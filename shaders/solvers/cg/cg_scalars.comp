// Conjugate gradients, one workgroup: the scalar steps between the cell-wide kernels, decided
// on the GPU so the CPU never waits. PF_CG_STEP 0 (start) and 2 (after an update) add the
// partials (r.r, r.z, sum z, sum r), remove the null-space mean m of z when the system is
// singular (r.(z - m) = r.z - m sum r), test |r| / |b| against the tolerance (stopping the solve
// there) and form beta; PF_CG_STEP 1 forms alpha = r.z / p.A p, and stops the solve if p.A p is
// not positive (no further progress is possible in float).
#include "common/sim.glsl"
#include "solvers/common/solver_state.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_SOLVER_PARTIALS) buffer Partials { vec4 partials[]; };
layout(std430, binding = PF_SLOT_SOLVER_STATE) buffer State { uint state[]; };
layout(location = PF_LOC_SOLVER_COUNT) uniform uint u_partials;
#include "solvers/common/reduce.glsl"
#include "solvers/common/state.glsl"

void main() {
    if (solve_converged()) return;  // uniform across the workgroup
    vec4 t = sum_partials(u_partials);
    if (gl_LocalInvocationIndex != 0u) return;
#if PF_CG_STEP == 1
    float rz = state_float(PF_SOLVER_RZ);
    if (!(t.x > 0.0) || !(rz > 0.0)) {
        stop_solve();
        return;
    }
    set_state_float(PF_SOLVER_ALPHA, rz / t.x);
#else
    float fluid = float(state[PF_SOLVER_FLUID_CELLS]);
    float m = solve_singular() && fluid > 0.0 ? t.z / fluid : 0.0;
    float rz = t.y - m * t.w;
    float rel = relative_residual(t.x, state_float(PF_SOLVER_BB));
    set_state_float(PF_SOLVER_RESIDUAL, rel);
#if PF_CG_STEP == 2
    state[PF_SOLVER_ITERATIONS] += 1u;
#endif
    if (rel <= state_float(PF_SOLVER_TOLERANCE) || !(rz > 0.0)) {
        stop_solve();
        return;
    }
#if PF_CG_STEP == 2
    set_state_float(PF_SOLVER_BETA, rz / state_float(PF_SOLVER_RZ));
#else
    set_state_float(PF_SOLVER_BETA, 0.0);
#endif
    set_state_float(PF_SOLVER_RZ, rz);
    set_state_float(PF_SOLVER_Z_MEAN, m);
#endif
}
