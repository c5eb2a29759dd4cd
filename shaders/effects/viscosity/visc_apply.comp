// Viscosity (PF_FEATURE_VISCOSITY), per face: the matrix-vector product's second half, the
// divergence of the stresses that visc_stress.comp wrote (D^T sigma, shaders/effects/viscosity/
// viscosity.glsl). With PF_VISC_START it makes the solve's first residual r = -D^T sigma(u*) (the
// start is u = u*, so the mass term cancels) and direction p = r / diag, and the last workgroup
// stores r.z and r.r; otherwise it stores this iteration's direction p = r / diag + beta p_old
// (as visc_stress.comp formed it) and q = m p + D^T sigma(p), and the last workgroup turns p.q
// into CG's step length alpha (stopping the solve if p.q is not positive).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_VISC_SIGMA_CELL) readonly buffer SigmaCell { vec4 sigma_cell[]; };
layout(std430, binding = PF_SLOT_VISC_SIGMA_NODE) readonly buffer SigmaNode { vec4 sigma_node[]; };
layout(std430, binding = PF_SLOT_VISC_COEF) readonly buffer Coef { vec2 coef[]; };
layout(std430, binding = PF_SLOT_VISC_R) buffer Residual { float r[]; };
layout(std430, binding = PF_SLOT_VISC_P) buffer Direction { float p[]; };
#if !PF_VISC_START
layout(std430, binding = PF_SLOT_VISC_Q) writeonly buffer Product { float q[]; };
#endif
layout(std430, binding = PF_SLOT_VISC_STATE) coherent buffer State { uint state[]; };
layout(std430, binding = PF_SLOT_VISC_PARTIALS) coherent buffer Partials { vec4 partials[]; };
#include "solvers/common/reduce.glsl"
#include "effects/viscosity/viscosity_state.h"
#include "effects/viscosity/visc_reduce.glsl"

// (D^T sigma) on face (axis, f), a face with cells on both sides.
float stress_divergence(int axis, ivec3 f) {
    ivec3 ea = ivec3(0);
    ea[axis] = 1;
    float s = sigma_cell[cell_index(f - ea)][axis] - sigma_cell[cell_index(f)][axis];
    for (int b = 0; b < 3; ++b) {
        if (b == axis) continue;
        ivec3 eb = ivec3(0);
        eb[b] = 1;
        int pair = axis + b - 1;
        s += 0.5 * (sigma_node[node_index(f)][pair] - sigma_node[node_index(f + eb)][pair]);
    }
    return s;
}

void main() {
    int id = int(flat_id());
    vec4 v = vec4(0.0);
    if (id < face_total()) {
        vec2 k = coef[id];
        int axis;
        ivec3 f;
        decode_face(id, axis, f);
#if PF_VISC_START
        float res = k.y > 0.0 ? -stress_divergence(axis, f) : 0.0;
        r[id] = res;
        p[id] = k.y * res;
        v = vec4(k.y * res * res, res * res, 0.0, 0.0);
#else
        if (k.y > 0.0) {
            float dir = k.y * r[id] + uintBitsToFloat(state[PF_VISC_BETA]) * p[id];
            float prod = k.x * dir + stress_divergence(axis, f);
            p[id] = dir;
            q[id] = prod;
            v.x = dir * prod;
        } else {
            q[id] = 0.0;
        }
#endif
    }
    vec4 sum;
    if (!visc_reduce(v, sum) || gl_LocalInvocationIndex != 0u) return;
#if PF_VISC_START
    visc_set_state_float(PF_VISC_RZ, sum.x);
    visc_set_state_float(PF_VISC_RR0, sum.y);
    visc_set_state_float(PF_VISC_BETA, 0.0);
    if (!(sum.y > 0.0) || !(sum.x > 0.0)) visc_stop();  // u* is already the minimum
#else
    float rz = visc_state_float(PF_VISC_RZ);
    if (!(sum.x > 0.0) || !(rz > 0.0)) {
        visc_stop();  // no further progress is possible in float
        return;
    }
    visc_set_state_float(PF_VISC_ALPHA, rz / sum.x);
#endif
}
