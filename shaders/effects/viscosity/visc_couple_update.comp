// Viscosity's coupling rounds (pf_viscosity.coupling_rounds > 1), per face, after a round's
// projection: the next round's input u~ takes what the projection did to the round's viscous
// velocities, on the faces the viscous solve solves for, and the face velocities start the next
// round from u~. This is Uzawa's iteration on the coupled Stokes step, the pressure fed back into
// the viscous solve as a force: each round shrinks the divergence the viscous solve leaves
// (docs/design.md §9.8, "Coupling rounds").
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_VISC_X) buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_VISC_TARGET) buffer Target { float target[]; };
layout(std430, binding = PF_SLOT_VISC_BEFORE) readonly buffer Before { float before[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer CellType { uint cell_type[]; };
#include "effects/viscosity/viscosity.glsl"

void main() {
    int id = int(flat_id());
    if (id >= face_total()) return;
    int axis;
    ivec3 f;
    decode_face(id, axis, f);
    float u = target[id];
    if (visc_face_role(axis, f) == VISC_UNKNOWN) {
        u += face_vel[id] - before[id];
        target[id] = u;
    }
    face_vel[id] = u;
}
