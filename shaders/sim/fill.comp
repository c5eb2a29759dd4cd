// Fills the first u_count words of a buffer with u_value (clears accumulators and counters;
// float zero and int zero share the bit pattern 0).
#include "common/slots.h"
#include "common/dispatch.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_FILL) writeonly buffer Data { uint data[]; };
layout(location = PF_LOC_FILL_COUNT) uniform uint u_count;
layout(location = PF_LOC_FILL_VALUE) uniform uint u_value;

void main() {
    uint i = flat_id();
    if (i < u_count) data[i] = u_value;
}
