// Sorted-gather P2G, step 5 of 5, per face sample: gathers the sums that p2g.comp scatters,
// with no atomics. A particle reaches sample f of lattice `axis` when f - base of its stencil
// (face_stencil, common/sim.glsl) is in {0,1}^3; its cell is then f - 1 or f along `axis`
// and f - 1, f or f + 1 along the other two (the stencil base lies at the cell or one below
// it there). So the kernel visits those 2 x 3 x 3 cells (clamped to the grid) in a fixed
// order, and each cell's particles in the order of the sorted index list
// (p2g_sort_rank.comp), recomputes the particle's stencil and adds w·v_axis and w exactly as
// p2g.comp's float permutation does (w·(v_a + c_a·(x_node - x_p)) with PF_APIC). Float sums
// in a fixed order: bit-identical run to run and for any order of the particle array; no
// rounding grid and no overflow. Writes both words of every sample (no clear needed) in the
// float layout that grid_forces.comp reads with PF_P2G_FLOAT.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) readonly buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_SORT_CELL_START) readonly buffer Start { uint cell_start[]; };
layout(std430, binding = PF_SLOT_CELL_COUNT) readonly buffer Count { uint cell_count[]; };
layout(std430, binding = PF_SLOT_SORT_SORTED) readonly buffer Sorted { uint sorted_index[]; };
layout(std430, binding = PF_SLOT_FACE_ACCUM) writeonly buffer Accum { float accum[]; };  // 2 words per face
#if PF_APIC
layout(std430, binding = PF_SLOT_PARTICLE_AFFINE) readonly buffer Affine { vec4 affine[]; };
#endif

void main() {
    int id = int(flat_id());
    if (id >= sim.face_count.w) return;
    int axis;
    ivec3 f;
    decode_face(id, axis, f);
    ivec3 reach = ivec3(1);
    reach[axis] = 0;
    ivec3 lo = max(f - 1, ivec3(0)), hi = min(f + reach, sim.grid.xyz - 1);

    float momentum = 0.0, weight = 0.0;
    for (int z = lo.z; z <= hi.z; ++z) {
        for (int y = lo.y; y <= hi.y; ++y) {
            for (int x = lo.x; x <= hi.x; ++x) {
                int c = cell_index(ivec3(x, y, z));
                uint first = cell_start[c], end = first + cell_count[c];
                for (uint k = first; k < end; ++k) {
                    uint p = sorted_index[k];
                    vec3 g = grid_coord(pos[p].xyz);
                    Stencil st = face_stencil(axis, g);
                    ivec3 d = f - st.base;
                    if (any(lessThan(d, ivec3(0))) || any(greaterThan(d, ivec3(1)))) continue;
                    float w = stencil_weight(st.frac, d);
#if PF_APIC
                    vec3 ca = affine[3u * p + uint(axis)].xyz * sim.dx;  // per grid unit
                    vec3 node_offset = vec3(0.5);
                    node_offset[axis] = 0.0;
                    vec3 to_base = vec3(st.base) + node_offset - g;      // node b minus particle, grid units
                    float va = vel[p][axis] + dot(ca, to_base + vec3(d));
#else
                    float va = vel[p][axis];
#endif
                    momentum += w * va;
                    weight += w;
                }
            }
        }
    }
    accum[2 * id] = momentum;
    accum[2 * id + 1] = weight;
}
