// Surface tension (PF_FEATURE_SURFACE_TENSION), first pass, per cell: the liquid fraction that
// st_liquid.comp smooths, the mean of the cell's six faces' P2G weight sums over the rest count
// (the particles' trilinear weights, so it changes continuously as particles move: a count per
// cell would jump by 1/8 as one crosses a cell's boundary, and the curvature with it), at most 1
// (compression is not surface).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
#if PF_P2G_FLOAT
layout(std430, binding = PF_SLOT_FACE_ACCUM) readonly buffer Accum { float accum[]; };
float weight_sum(int face) { return accum[accum_word(face, 1)]; }
#else
layout(std430, binding = PF_SLOT_FACE_ACCUM) readonly buffer Accum { int accum[]; };
float weight_sum(int face) { return float(accum[accum_word(face, 1)]) * sim.inv_weight_scale; }
#endif
layout(std430, binding = PF_SLOT_ST_FRACTION) writeonly buffer Fraction { float fraction[]; };

void main() {
    int id = int(flat_id());
    if (id >= cell_total()) return;
    ivec3 c = cell_coord(id);
    float sum = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        sum += weight_sum(cell_face(axis, c, 0)) + weight_sum(cell_face(axis, c, 1));
    }
    fraction[id] = min(sum / (6.0 * sim.rest_particles), 1.0);
}
