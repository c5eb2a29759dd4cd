// Pressure setup: right-hand side b = -div(u) * density * dx / dt for FLUID cells; AIR
// cells get b = 0 and p = 0 (free surface). FLUID cells keep last substep's pressure as the
// solver's starting guess (pascals do not depend on dt).
// Volume correction (docs/design.md §4.5): a FLUID cell holding more particles than the rest
// count is given a target divergence that spreads the fraction volume_correction of its excess
// out in this substep. Its excess volume is e * dx^3 with e = count / rest - 1; removing k e dx^3
// in dt takes a net outflow (sum of face-velocity differences) of D = k e dx / dt, so the
// projection solves div = D instead of 0: b = -(div - D) * density * dx / dt, i.e.
//     b += k * e * density * dx^2 / dt^2   (pascals, like b).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_FACE_VEL) readonly buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_CELL_COUNT) readonly buffer Count { uint cell_count[]; };
layout(std430, binding = PF_SLOT_RHS) writeonly buffer Rhs { float rhs[]; };
layout(std430, binding = PF_SLOT_PRESSURE) buffer Pressure { float pressure[]; };
#include "common/volume_excess.glsl"

void main() {
    int c = int(flat_id());
    if (c >= sim.grid.w) return;
    if (cell_type[c] != PF_CELL_FLUID) {
        rhs[c] = 0.0;
        pressure[c] = 0.0;
        return;
    }
    ivec3 ijk = ivec3(c % sim.grid.x, (c / sim.grid.x) % sim.grid.y, c / (sim.grid.x * sim.grid.y));
    float div = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        ivec3 hi = ijk;
        hi[axis] += 1;
        div += face_vel[face_index(axis, hi)] - face_vel[face_index(axis, ijk)];
    }
    float target = sim.volume_correction * volume_excess(ijk) * sim.dx / sim.dt;  // D, m/s
    rhs[c] = -(div - target) * sim.density * sim.dx / sim.dt;
}
