// Domain motion (PF_FEATURE_DOMAIN_MOTION), per face, right after grid_forces (gravity): the
// liquid is simulated in the frame of the domain the engine moves, so every face that received
// particles and is not a domain wall gets the frame's apparent accelerations at its sample
// position x (domain coordinates, measured from the frame's origin):
//   a = [R^T (g - A) - g]  -  alpha x x  -  omega x (omega x x)  -  2 omega x u
// (gravity turned into the frame in place of the core's, the frame's linear acceleration,
// Euler, centrifugal and Coriolis terms; omega, alpha in the frame's axes). The Coriolis term
// needs the whole velocity: the face's own component and the other two averaged from the four
// faces of each other lattice around it, all from the substep's start (face_vel_old: no face
// reads a value this pass writes).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_FACE_ACCUM) readonly buffer Accum { int accum[]; };
layout(std430, binding = PF_SLOT_FACE_VEL) buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_FACE_VEL_OLD) readonly buffer FaceVelOld { float face_vel_old[]; };
layout(location = PF_LOC_DOMAIN_LINEAR) uniform vec4 u_linear;
layout(location = PF_LOC_DOMAIN_OMEGA) uniform vec4 u_omega;
layout(location = PF_LOC_DOMAIN_ALPHA) uniform vec4 u_alpha;

// Component b of the old velocity at face f of lattice `axis` (b != axis): the mean of the
// four b-faces of the two cells the face separates.
float transverse(int axis, ivec3 f, int b) {
    ivec3 lo = face_cell_below(axis, f);
    return 0.25 * (face_vel_old[cell_face(b, lo, 0)] + face_vel_old[cell_face(b, lo, 1)] +
                   face_vel_old[cell_face(b, f, 0)] + face_vel_old[cell_face(b, f, 1)]);
}

void main() {
    int id = int(flat_id());
    if (id >= face_total()) return;
    int axis;
    ivec3 f;
    decode_face(id, axis, f);
    if (face_is_wall(axis, f) || accum[accum_word(id, 1)] <= 0) return;
    vec3 x = face_centre(axis, f);
    vec3 u;
    u[axis] = face_vel_old[id];
    for (int b = 0; b < 3; ++b)
        if (b != axis) u[b] = transverse(axis, f, b);
    vec3 w = u_omega.xyz;
    vec3 a = u_linear.xyz - cross(u_alpha.xyz, x) - cross(w, cross(w, x)) - 2.0 * cross(w, u);
    face_vel[id] += sim.dt * a[axis];
}
