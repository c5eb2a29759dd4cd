// Exclusive prefix sum, one level: each workgroup scans PF_SCAN_BLOCK consecutive items of its
// input (PF_SCAN_ITEMS_PER_INVOCATION per invocation, summed in registers, then a Hillis-Steele
// scan of the invocations' sums in shared memory), writes every item's exclusive prefix within
// the block to the output and the block's total to the block-sum array. The host runs it again
// on the block sums until one block holds them all, then adds the scanned sums back down
// (scan_add.comp). Integer sums: exact, the same whatever the order of execution.
// Used by the sorted-gather and tiled P2G for their keys' starts (exclusive sum of the counts).
#include "common/slots.h"
#include "common/dispatch.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_SCAN_IN) readonly buffer In { uint src[]; };
layout(std430, binding = PF_SLOT_SCAN_OUT) buffer Out { uint dst[]; };
layout(location = PF_LOC_SCAN_COUNT) uniform uint u_count;        // items of this level
layout(location = PF_LOC_SCAN_IN_OFFSET) uniform uint u_in;       // first item in src
layout(location = PF_LOC_SCAN_OUT_OFFSET) uniform uint u_out;     // first prefix in dst
layout(location = PF_LOC_SCAN_SUMS_OFFSET) uniform uint u_sums;   // first block total in dst

shared uint partial[PF_WORKGROUP_SIZE];

void main() {
    uint lane = gl_LocalInvocationID.x;
    uint block = flat_id() / uint(PF_WORKGROUP_SIZE);
    uint first = block * uint(PF_SCAN_BLOCK) + lane * uint(PF_SCAN_ITEMS_PER_INVOCATION);
    uint items[PF_SCAN_ITEMS_PER_INVOCATION];
    uint sum = 0u;
    for (int k = 0; k < PF_SCAN_ITEMS_PER_INVOCATION; ++k) {
        uint i = first + uint(k);
        items[k] = i < u_count ? src[u_in + i] : 0u;
        sum += items[k];
    }
    partial[lane] = sum;
    barrier();
    for (uint d = 1u; d < uint(PF_WORKGROUP_SIZE); d <<= 1) {
        uint add = lane >= d ? partial[lane - d] : 0u;
        barrier();
        partial[lane] += add;
        barrier();
    }
    uint prefix = partial[lane] - sum;
    for (int k = 0; k < PF_SCAN_ITEMS_PER_INVOCATION; ++k) {
        uint i = first + uint(k);
        if (i < u_count) dst[u_out + i] = prefix;
        prefix += items[k];
    }
    // The dispatch may hold whole workgroups past the last block (2D folding): they write nothing.
    uint blocks = (u_count + uint(PF_SCAN_BLOCK) - 1u) / uint(PF_SCAN_BLOCK);
    if (lane == uint(PF_WORKGROUP_SIZE) - 1u && block < blocks) dst[u_sums + block] = partial[lane];
}
