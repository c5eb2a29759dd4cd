// Helpers shared by the whitewater kernels (PF_FEATURE_WHITEWATER): the liquid's velocity
// (common/face_velocity.glsl; the face velocities reach a few cells into the air through the
// extrapolation, so foam and spray near the surface see the liquid's motion), the kinds of
// whitewater particle and how the liquid around a point decides a particle's kind.
#include "common/sim.glsl"
#include "common/hash.glsl"

// pf_whitewater_kind
#define PF_WW_SPRAY 0.0
#define PF_WW_FOAM 1.0
#define PF_WW_BUBBLE 2.0
// The liquid fraction of the 3^3 cells around a point (ww_fraction.comp) below which a particle
// is spray and above which it is a bubble (Ihmsen et al. count SPH neighbours instead: fewer than
// 6 spray, more than 20 bubble). Just above a flat surface it is 1/3, in the surface's cells 2/3.
const float kSprayBelow = 0.3;
const float kBubbleAbove = 0.9;

layout(std430, binding = PF_SLOT_FACE_VEL) readonly buffer FaceVel { float face_vel[]; };

#include "common/face_velocity.glsl"

float kind_for(float fraction) {
    return fraction < kSprayBelow ? PF_WW_SPRAY : (fraction > kBubbleAbove ? PF_WW_BUBBLE : PF_WW_FOAM);
}

// Uniform numbers in [0, 1) from a hash chain.
float next_random(inout uint state) {
    state = pcg_hash(state);
    return float(state >> 8u) * (1.0 / 16777216.0);
}
