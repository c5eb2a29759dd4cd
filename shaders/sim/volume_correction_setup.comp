// Volume correction, right-hand side (docs/design.md §4.5): the displacement potential q whose
// face differences move particles out of over-full cells. A FLUID cell with volume excess e
// (common/volume_excess.glsl) must lose k e dx^3 of liquid, i.e. a net outward displacement
// (sum of its faces' displacement differences) of k e dx; with face displacement
// d = q_lo - q_hi that sum is A q (the pressure solvers' operator), so b = k e dx (metres).
// Every other cell gets b = 0 and q = 0 (AIR is q = 0: the free surface moves freely).
// q starts from 0: the potential of one step says nothing about the next.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_CELL_COUNT) readonly buffer Count { uint cell_count[]; };
layout(std430, binding = PF_SLOT_RHS) writeonly buffer Rhs { float rhs[]; };
layout(std430, binding = PF_SLOT_PRESSURE) readonly buffer Pressure { float pressure[]; };
layout(std430, binding = PF_SLOT_VOLUME_POTENTIAL_OUT) writeonly buffer Potential { float potential[]; };
#include "common/volume_excess.glsl"

void main() {
    int c = int(flat_id());
    if (c >= cell_total()) return;
    potential[c] = 0.0;
    if (PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID) {
        rhs[c] = 0.0;
        return;
    }
    ivec3 ijk = cell_coord(c);
    rhs[c] = sim.volume_correction * volume_excess(ijk) * sim.dx;
}
