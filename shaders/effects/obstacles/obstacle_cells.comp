// Obstacles (PF_FEATURE_OBSTACLES), per cell, right after classify: a cell whose centre lies
// inside an obstacle (signed distance < 0) becomes SOLID, whatever particles it holds. The
// pressure solve leaves SOLID cells out (Neumann), velocity_update keeps their faces.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) buffer Type { uint cell_type[]; };
#include "effects/obstacles/obstacle_sdf.glsl"

void main() {
    int c = int(flat_id());
    if (c >= cell_total()) return;
    ivec3 ijk = cell_coord(c);
    int nearest;
    if (scene_distance(cell_centre(ijk), nearest) < 0.0) cell_type[c] = PF_CELL_SOLID;
}
