// Exclusive prefix sum, down sweep: adds each block's scanned total (the exclusive prefix of the
// block sums, scan_blocks.comp one level up) to the in-block prefixes of its PF_SCAN_BLOCK
// items, which makes them prefixes over the whole array. One invocation per item.
#include "common/slots.h"
#include "common/dispatch.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_SCAN_OUT) buffer Data { uint data[]; };
layout(location = PF_LOC_SCAN_COUNT) uniform uint u_count;     // items of the level
layout(location = PF_LOC_SCAN_OUT_OFFSET) uniform uint u_out;  // first in-block prefix
layout(location = PF_LOC_SCAN_SUMS_OFFSET) uniform uint u_sums; // first scanned block total

void main() {
    uint i = flat_id();
    if (i < u_count) data[u_out + i] += data[u_sums + i / uint(PF_SCAN_BLOCK)];
}
