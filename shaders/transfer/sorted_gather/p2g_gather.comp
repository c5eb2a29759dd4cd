// Sorted-gather P2G, step 5 of 5, per face sample: gathers the sums that p2g.comp scatters,
// with no atomics. Which particles reach sample f of lattice `axis` with a nonzero weight
// follows from the half cell h = floor(2 g) alone: the clamped stencil coordinate s (face_stencil,
// common/sim.glsl) gives weight max(0, 1 - |s - f|) per axis, nonzero only for g in (f - 1, f + 1)
// along `axis` and in (f - 1/2, f + 3/2) along the others (a clamp moves s only onto the
// lattice's end sample, which those ranges then hold too), i.e. h in [2f - 2, 2f + 1] along
// `axis` and [2f - 1, 2f + 2] along the others, clamped to the grid (the range edges are where a
// weight falls to 0, so should p2g_sort_count.comp round g differently from this kernel, a
// particle could only cross an edge with a weight of the order of that rounding). So the kernel
// visits those 4 x 4 x 4 half cells — 16 rows, each one contiguous range of the sorted order,
// since x runs fastest — in a fixed order, each half cell's particles in the order of
// p2g_sort_rank.comp (which wrote their grid coordinates and velocities in that order),
// recomputes the particle's stencil and adds w·v_axis and w exactly as
// p2g.comp's float permutation does (w·(v_a + c_a·(x_node - x_p)) with PF_APIC). Particles of
// those half cells whose weight is 0 add nothing (x + 0 = x), so the sums are p2g.comp's. Float
// sums in a fixed order: bit-identical run to run and for any order of the particle array; no
// rounding grid and no overflow. Writes both words of every sample (no clear needed) in the
// float layout that grid_forces.comp reads with PF_P2G_FLOAT.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_SORT_HALF_START) readonly buffer Start { uint half_start[]; };
layout(std430, binding = PF_SLOT_SORT_GRID) readonly buffer SortedGrid { vec4 sorted_grid[]; };
struct SortedParticle {
    vec3 vel;
    uint index;  // into the particle arrays (APIC's affine vectors)
};
layout(std430, binding = PF_SLOT_SORT_PARTICLE) readonly buffer SortedParticles { SortedParticle sorted_particle[]; };
layout(std430, binding = PF_SLOT_FACE_ACCUM) writeonly buffer Accum { float accum[]; };  // 2 words per face
#if PF_APIC
layout(std430, binding = PF_SLOT_PARTICLE_AFFINE) readonly buffer Affine { vec4 affine[]; };
#endif

void main() {
    int id = int(flat_id());
    if (id >= face_total()) return;
    int axis;
    ivec3 f;
    decode_face(id, axis, f);
    ivec3 below = ivec3(1);
    below[axis] = 2;
    ivec3 lo = max(2 * f - below, ivec3(0)), hi = min(2 * f + 3 - below, 2 * sim.grid.xyz - 1);

    float momentum = 0.0, weight = 0.0;
    for (int z = lo.z; z <= hi.z; ++z) {
        for (int y = lo.y; y <= hi.y; ++y) {
            // Half cells lo.x..hi.x of this row are consecutive: one range of the sorted arrays.
            uint first = half_start[half_cell_index(ivec3(lo.x, y, z))];
            uint end = half_start[half_cell_index(ivec3(hi.x, y, z)) + 1];
            for (uint k = first; k < end; ++k) {
                vec3 g = sorted_grid[k].xyz;
                Stencil st = face_stencil(axis, g);
                ivec3 d = f - st.base;
                if (any(lessThan(d, ivec3(0))) || any(greaterThan(d, ivec3(1)))) continue;  // weight 0 there
                float w = stencil_weight(st.frac, d);
#if PF_APIC
                vec3 ca = affine[3u * sorted_particle[k].index + uint(axis)].xyz * sim.dx;  // per grid unit
                vec3 node_offset = vec3(0.5);
                node_offset[axis] = 0.0;
                vec3 to_base = vec3(st.base) + node_offset - g;      // node b minus particle, grid units
                float va = sorted_particle[k].vel[axis] + dot(ca, to_base + vec3(d));
#else
                float va = sorted_particle[k].vel[axis];
#endif
                momentum += w * va;
                weight += w;
            }
        }
    }
    accum[accum_word(id, 0)] = momentum;
    accum[accum_word(id, 1)] = weight;
}
