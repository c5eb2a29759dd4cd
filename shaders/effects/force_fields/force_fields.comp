// Force fields (PF_FEATURE_FORCE_FIELDS), per face, right after grid_forces (gravity): every
// face that received particles (positive P2G weight) and is not a domain wall gets the fields'
// acceleration at its sample position, u += dt * sum of accelerations (directional fields
// without drag, attractors/repulsors, vortices); then each directional field with drag relaxes
// u towards its wind velocity exactly over the substep, u = w + (u - w) exp(-drag dt).
// Faces without particles stay 0 (as after gravity); walls stay 0 (free-slip).
#include "common/sim.glsl"
#include "effects/force_fields/force_field_types.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
// The weight word of a face's P2G pair is positive exactly when it received particles, for both
// P2G schemes: a positive int (fixed point) or the bits of a positive float, read as an int.
layout(std430, binding = PF_SLOT_FACE_ACCUM) readonly buffer Accum { int accum[]; };
layout(std430, binding = PF_SLOT_FACE_VEL) buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_FORCE_FIELDS) readonly buffer Fields { vec4 fields[]; };
layout(location = PF_LOC_EFFECT_COUNT) uniform uint u_count;  // live force fields

void main() {
    int id = int(flat_id());
    if (id >= face_total()) return;
    int axis;
    ivec3 f;
    decode_face(id, axis, f);
    if (face_is_wall(axis, f) || accum[accum_word(id, 1)] <= 0) return;
    vec3 x = face_centre(axis, f);

    vec3 a = vec3(0.0);
    for (uint k = 0u; k < u_count; ++k) {
        vec4 pr = fields[PF_FORCE_FIELD_VEC4S * k], vs = fields[PF_FORCE_FIELD_VEC4S * k + 1u];
        int type = int(fields[PF_FORCE_FIELD_VEC4S * k + 2u].x);
        float drag = fields[PF_FORCE_FIELD_VEC4S * k + 2u].y;
        if (type == PF_FORCE_FIELD_DIRECTIONAL_ID) {
            if (drag == 0.0) a += vs.xyz;
        } else if (type == PF_FORCE_FIELD_POINT_ID) {
            vec3 d = pr.xyz - x;
            float dist = length(d);
            if (dist > 0.0 && dist < pr.w) a += vs.w * (1.0 - dist / pr.w) * (d / dist);
        } else if (type == PF_FORCE_FIELD_VORTEX_ID) {
            vec3 rel = x - pr.xyz;
            vec3 radial = rel - dot(rel, vs.xyz) * vs.xyz;
            float r = length(radial);
            if (r > 0.0 && r < pr.w) {
                float s = r / pr.w;
                a += vs.w * 4.0 * s * (1.0 - s) * (cross(vs.xyz, radial) / r);
            }
        }
    }
    float u = face_vel[id] + sim.dt * a[axis];
    for (uint k = 0u; k < u_count; ++k) {
        vec4 ex = fields[PF_FORCE_FIELD_VEC4S * k + 2u];
        if (int(ex.x) == PF_FORCE_FIELD_DIRECTIONAL_ID && ex.y > 0.0) {
            float w = fields[PF_FORCE_FIELD_VEC4S * k + 1u][axis];
            u = w + (u - w) * exp(-ex.y * sim.dt);
        }
    }
    face_vel[id] = u;
}
