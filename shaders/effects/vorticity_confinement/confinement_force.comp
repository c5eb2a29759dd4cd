// Vorticity confinement (PF_FEATURE_VORTICITY_CONFINEMENT), second pass, per face (Fedkiw, Stam
// & Jensen 2001, eq. 11): at each cell centre with a vorticity w (vorticity.comp), N is the unit
// vector along the gradient of |w| (central differences; a neighbour without one counts as 0)
// and the acceleration is f = strength * dx * (N x w); a face between two such cells gets the
// mean of their f along its axis times the substep's dt. Added before the pressure solve, like
// gravity, so the projection keeps the velocity divergence-free and FLIP's difference carries it.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_FACE_VEL) buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_VORTICITY) readonly buffer Vorticity { vec4 vorticity[]; };
layout(location = PF_LOC_VORTICITY_STRENGTH) uniform float u_strength;

float magnitude(ivec3 c) { return cell_inside(c) ? vorticity[cell_index(c)].w : 0.0; }

// The confinement acceleration at cell c (0 where the cell has no vorticity).
vec3 confinement(ivec3 c) {
    vec4 w = vorticity[cell_index(c)];
    if (w.w <= 0.0) return vec3(0.0);
    vec3 eta;
    for (int a = 0; a < 3; ++a) {
        ivec3 e = ivec3(0);
        e[a] = 1;
        eta[a] = magnitude(c + e) - magnitude(c - e);
    }
    float len = length(eta);
    // A flat |w| has no direction to push along.
    if (!(len > 1e-6 * w.w)) return vec3(0.0);
    return u_strength * sim.dx * cross(eta / len, w.xyz);
}

void main() {
    int id = int(flat_id());
    if (id >= face_total()) return;
    int axis;
    ivec3 f;
    decode_face(id, axis, f);
    if (face_is_wall(axis, f)) return;
    ivec3 lo = face_cell_below(axis, f);
    if (vorticity[cell_index(lo)].w <= 0.0 || vorticity[cell_index(f)].w <= 0.0) return;
    face_vel[id] += sim.dt * 0.5 * (confinement(lo)[axis] + confinement(f)[axis]);
}
