// Pressure setup: right-hand side b = -div(u) * density * dx / dt for FLUID cells; AIR
// cells get b = 0 and p = 0 (free surface). FLUID cells keep last substep's pressure as the
// solver's starting guess (pascals do not depend on dt). The projection's target is exactly
// div = 0: the volume correction moves positions in a problem of its own
// (sim/volume_correction_setup.comp), never velocities.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_FACE_VEL) readonly buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_RHS) writeonly buffer Rhs { float rhs[]; };
layout(std430, binding = PF_SLOT_PRESSURE) buffer Pressure { float pressure[]; };

void main() {
    int c = int(flat_id());
    if (c >= cell_total()) return;
    if (PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID) {
        rhs[c] = 0.0;
        pressure[c] = 0.0;
        return;
    }
    ivec3 ijk = cell_coord(c);
    float div = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        div += face_vel[cell_face(axis, ijk, 1)] - face_vel[cell_face(axis, ijk, 0)];
    }
    rhs[c] = -div * sim.density * sim.dx / sim.dt;
}
