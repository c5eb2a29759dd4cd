// Helpers shared by the whitewater kernels (PF_FEATURE_WHITEWATER): the cell-centred and
// interpolated liquid velocity, the kinds of whitewater particle and how the liquid around a
// point decides a particle's kind.
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

// The liquid's velocity at cell c's centre: the mean of its two faces on each lattice.
vec3 centre_velocity(ivec3 c) {
    vec3 u;
    for (int a = 0; a < 3; ++a) {
        ivec3 upper = c;
        upper[a] += 1;
        u[a] = 0.5 * (face_vel[face_index(a, c)] + face_vel[face_index(a, upper)]);
    }
    return u;
}

// The liquid's velocity at world point x: the clamped trilinear stencil of G2P. The face
// velocities reach a few cells into the air (extrapolation), so foam and spray near the
// surface see the liquid's motion.
vec3 liquid_velocity(vec3 x) {
    vec3 g = grid_coord(x);
    vec3 v;
    for (int axis = 0; axis < 3; ++axis) {
        Stencil st = face_stencil(axis, g);
        float t[8];
        for (int n = 0; n < 8; ++n) {
            ivec3 d = stencil_offset(n);
            t[n] = stencil_weight(st.frac, d) * face_vel[face_index(axis, st.base + d)];
        }
        v[axis] = mirror_sum(t);
    }
    return v;
}

float kind_for(float fraction) {
    return fraction < kSprayBelow ? PF_WW_SPRAY : (fraction > kBubbleAbove ? PF_WW_BUBBLE : PF_WW_FOAM);
}

// Uniform numbers in [0, 1) from a hash chain.
float next_random(inout uint state) {
    state = pcg_hash(state);
    return float(state >> 8u) * (1.0 / 16777216.0);
}
