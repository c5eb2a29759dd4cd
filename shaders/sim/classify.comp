// Cell classification: a cell holding at least one particle is FLUID, otherwise AIR.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_COUNT) readonly buffer Count { uint cell_count[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) writeonly buffer Type { uint cell_type[]; };

void main() {
    int c = int(flat_id());
    if (c >= cell_total()) return;
    cell_type[c] = cell_count[c] > 0u ? PF_CELL_FLUID : PF_CELL_AIR;
}
