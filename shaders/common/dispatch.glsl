// Flat invocation index. Large 1D workloads are dispatched as a 2D grid of workgroups
// (x at most 65535, the GL 4.3 minimum), so the index folds y back in. Every kernel uses
// local_size_x = PF_WORKGROUP_SIZE.
#include "common/slots.h"

uint flat_id() {
    return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * uint(PF_WORKGROUP_SIZE);
}

// The coordinates of flat index i in a box of d (x fastest), with two integer divisions (each a
// long instruction sequence on GPUs); i % d.x, (i / d.x) % d.y, i / (d.x d.y) takes three
// divisions and two modulos (docs/notes/2026-11-27-kernel-profile-and-gaps.md).
ivec3 unflatten(int i, ivec3 d) {
    int row = i / d.x;
    int k = row / d.y;
    return ivec3(i - row * d.x, row - k * d.y, k);
}
