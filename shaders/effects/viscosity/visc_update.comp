// Viscosity (PF_FEATURE_VISCOSITY), per face: one conjugate-gradient update, u += alpha p,
// r -= alpha q, on the faces solved for; the last workgroup adds up r.z (z = r / diag) and r.r,
// counts the iteration, stops the solve once |r| / |r0| meets the tolerance and otherwise forms
// beta for the next direction (shaders/effects/viscosity/visc_apply.comp).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_VISC_X) buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_VISC_COEF) readonly buffer Coef { vec2 coef[]; };
layout(std430, binding = PF_SLOT_VISC_R) buffer Residual { float r[]; };
layout(std430, binding = PF_SLOT_VISC_P) readonly buffer Direction { float p[]; };
layout(std430, binding = PF_SLOT_VISC_Q) readonly buffer Product { float q[]; };
layout(std430, binding = PF_SLOT_VISC_STATE) coherent buffer State { uint state[]; };
layout(std430, binding = PF_SLOT_VISC_PARTIALS) coherent buffer Partials { vec4 partials[]; };
#include "solvers/common/reduce.glsl"
#include "effects/viscosity/viscosity_state.h"
#include "effects/viscosity/visc_reduce.glsl"
layout(location = PF_LOC_VISC_TOLERANCE) uniform float u_tolerance;

void main() {
    int id = int(flat_id());
    vec4 v = vec4(0.0);
    if (id < face_total()) {
        float inv_diag = coef[id].y;
        if (inv_diag > 0.0) {
            float alpha = visc_state_float(PF_VISC_ALPHA);
            face_vel[id] += alpha * p[id];
            float res = r[id] - alpha * q[id];
            r[id] = res;
            v = vec4(inv_diag * res * res, res * res, 0.0, 0.0);
        }
    }
    vec4 sum;
    if (!visc_reduce(v, sum) || gl_LocalInvocationIndex != 0u) return;
    uint iterations = state[PF_VISC_ITERATIONS] + 1u;
    state[PF_VISC_ITERATIONS] = iterations;
    state[PF_VISC_MAX_ITERATIONS] = max(state[PF_VISC_MAX_ITERATIONS], iterations);
    float rr0 = visc_state_float(PF_VISC_RR0);
    float residual = sqrt(max(sum.y, 0.0) / rr0);
    visc_set_state_float(PF_VISC_RESIDUAL, residual);
    visc_set_state_float(PF_VISC_MAX_RESIDUAL, max(visc_state_float(PF_VISC_PREV_MAX_RESIDUAL), residual));
    if (residual <= u_tolerance || !(sum.x > 0.0)) {
        visc_stop();
        return;
    }
    visc_set_state_float(PF_VISC_BETA, sum.x / visc_state_float(PF_VISC_RZ));
    visc_set_state_float(PF_VISC_RZ, sum.x);
}
