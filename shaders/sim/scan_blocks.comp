// Exclusive prefix sum, one level: each workgroup scans PF_WORKGROUP_SIZE consecutive items of
// its input in shared memory (Hillis-Steele), writes every item's exclusive prefix within the
// block to the output and the block's total to the block-sum array. The host runs it again on
// the block sums until one block holds them all, then adds the scanned sums back down
// (scan_add.comp). Integer sums: exact, the same whatever the order of execution.
// Used by the sorted-gather P2G for the cell starts (exclusive sum of the per-cell counts).
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
    uint i = flat_id();
    uint lane = gl_LocalInvocationID.x;
    uint value = i < u_count ? src[u_in + i] : 0u;
    partial[lane] = value;
    barrier();
    for (uint d = 1u; d < uint(PF_WORKGROUP_SIZE); d <<= 1) {
        uint add = lane >= d ? partial[lane - d] : 0u;
        barrier();
        partial[lane] += add;
        barrier();
    }
    if (i < u_count) dst[u_out + i] = partial[lane] - value;
    // The dispatch may hold whole workgroups past the last block (2D folding): they write nothing.
    uint block = i / uint(PF_WORKGROUP_SIZE);
    uint blocks = (u_count + uint(PF_WORKGROUP_SIZE) - 1u) / uint(PF_WORKGROUP_SIZE);
    if (lane == uint(PF_WORKGROUP_SIZE) - 1u && block < blocks) dst[u_sums + block] = partial[lane];
}
