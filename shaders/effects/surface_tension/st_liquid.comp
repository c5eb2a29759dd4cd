// Surface tension (PF_FEATURE_SURFACE_TENSION), second pass, per cell: a smooth liquid fraction
// whose level sets follow the free surface, for st_force.comp's curvature: st_fraction.comp's
// values blurred with the 27-point binomial kernel (1 2 1 per axis, over 64). A neighbour
// outside the domain or SOLID stands in with the cell's own value, so the field's level sets meet
// walls and obstacles at a right angle (a 90 degree contact angle); a SOLID cell holds the mean of
// its non-SOLID face neighbours, the field continued into obstacles for the curvature's stencil.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_ST_FRACTION) readonly buffer Fraction { float fraction[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer CellType { uint cell_type[]; };
layout(std430, binding = PF_SLOT_ST_LIQUID) writeonly buffer Liquid { float liquid[]; };

bool open_cell(ivec3 c) { return cell_inside(c) && PF_CELL_KIND(cell_type[cell_index(c)]) != PF_CELL_SOLID; }

void main() {
    int id = int(flat_id());
    if (id >= cell_total()) return;
    ivec3 c = cell_coord(id);
    if (!open_cell(c)) {
        float sum = 0.0, n = 0.0;
        for (int k = 0; k < 6; ++k) {
            ivec3 q = c + kNeighbours[k];
            if (!open_cell(q)) continue;
            sum += fraction[cell_index(q)];
            n += 1.0;
        }
        liquid[id] = n > 0.0 ? sum / n : 0.0;
        return;
    }
    float own = fraction[id];
    float sum = 0.0;
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x) {
                ivec3 q = c + ivec3(x, y, z);
                float w = float((2 - abs(x)) * (2 - abs(y)) * (2 - abs(z)));
                sum += w * (open_cell(q) ? fraction[cell_index(q)] : own);
            }
    liquid[id] = sum / 64.0;
}
