// Flat invocation index. Large 1D workloads are dispatched as a 2D grid of workgroups
// (x at most 65535, the GL 4.3 minimum), so the index folds y back in. Every kernel uses
// local_size_x = PF_WORKGROUP_SIZE.
#include "common/slots.h"
#include "common/grid_layout.glsl"

uint flat_id() {
    return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * uint(PF_WORKGROUP_SIZE);
}

