// Free surface (ghost fluid, common/free_surface.glsl): each FLUID cell's type word takes the
// extra diagonal of its AIR faces, sum of 1/theta - 1 with theta from grid_forces' face
// fractions. Runs after classification and after obstacles marked their SOLID cells, so only
// faces that end up between FLUID and AIR count; every solver's operator reads the word
// (solvers/common/poisson.glsl).
#include "common/sim.glsl"
#include "common/free_surface.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_FACE_FRACTION) readonly buffer Fraction { float face_fraction[]; };

void main() {
    int c = int(flat_id());
    if (c >= cell_total() || PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID) return;
    ivec3 ijk = cell_coord(c);
    float term[6];
    for (int n = 0; n < 6; ++n) {
        term[n] = 0.0;
        ivec3 q = ijk + kNeighbours[n];
        // Neighbours' words change only above their kind bits here, so reading them races with nothing.
        if (!cell_inside(q) || PF_CELL_KIND(cell_type[cell_index(q)]) != PF_CELL_AIR) continue;
        term[n] = 1.0 / face_fraction[neighbour_face(ijk, n)] - 1.0;
    }
    // Pairs per axis first, as common/sim.glsl's mirror_sum: mirrored cells get equal words.
    cell_type[c] = fluid_word(((term[0] + term[1]) + (term[2] + term[3])) + (term[4] + term[5]));
}
