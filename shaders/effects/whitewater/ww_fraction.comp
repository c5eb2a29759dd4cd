// Whitewater (PF_FEATURE_WHITEWATER), first pass, per cell: the share of liquid among the 3^3
// cells around it that lie inside the domain and are not SOLID. It decides a whitewater
// particle's kind (whitewater.glsl) and, through its gradient, the surface normal whose
// divergence is the wave-crest curvature (ww_emit.comp).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer CellType { uint cell_type[]; };
layout(std430, binding = PF_SLOT_WW_FRACTION) writeonly buffer Fraction { float fraction[]; };

void main() {
    int id = int(flat_id());
    if (id >= cell_total()) return;
    ivec3 c = cell_coord(id);
    float liquid = 0.0, counted = 0.0;
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x) {
                ivec3 n = c + ivec3(x, y, z);
                if (!cell_inside(n)) continue;
                uint kind = PF_CELL_KIND(cell_type[cell_index(n)]);
                if (kind == PF_CELL_SOLID) continue;
                counted += 1.0;
                liquid += kind == PF_CELL_FLUID ? 1.0 : 0.0;
            }
    fraction[id] = counted > 0.0 ? liquid / counted : 0.0;
}
