// Reading the grid's face velocities away from the faces, for kernels that sample the flow
// without transferring to particles (G2P weighs its own stencil). The including kernel declares
// face_vel[] (PF_SLOT_FACE_VEL), and cell_type[] with PF_SOLID_WALLS 1.
#include "common/solid_walls.glsl"

// The velocity at cell c's centre: the mean of its two faces on each lattice.
vec3 centre_velocity(ivec3 c) {
    vec3 u;
    for (int a = 0; a < 3; ++a) {
        u[a] = 0.5 * (face_vel[cell_face(a, c, 0)] + face_vel[cell_face(a, c, 1)]);
    }
    return u;
}

// The velocity at world point x: G2P's clamped trilinear stencil on each lattice (stopped at
// obstacles with PF_SOLID_WALLS), summed mirror-exactly (common/sim.glsl's mirror_sum).
vec3 sample_velocity(vec3 x) {
    vec3 g = grid_coord(x);
    vec3 v;
    for (int axis = 0; axis < 3; ++axis) {
        Stencil st = sampling_stencil(axis, g);
        float t[8];
        for (int n = 0; n < 8; ++n) {
            ivec3 d = stencil_offset(n);
            t[n] = stencil_weight(st.frac, d) * face_vel[face_index(axis, st.base + d)];
        }
        v[axis] = mirror_sum(t);
    }
    return v;
}
