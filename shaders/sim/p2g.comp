// Particle-to-grid: splats each particle's velocity onto the 8 nearest samples of every MAC
// face lattice with 32-bit fixed-point integer atomics (momentum and weight), and counts
// particles per cell. Integer sums are order independent, so the result is bit-identical
// run to run. Overflow of an accumulator is detected and flagged, never silent.
// Permutation PF_APIC: each contribution is the particle's affine velocity at the node,
// v_a + c_a . (x_i - x_p) (Jiang et al. 2015), instead of v_a.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) readonly buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_FACE_ACCUM) buffer Accum { int accum[]; };  // 2 words per face
layout(std430, binding = PF_SLOT_CELL_COUNT) buffer Count { uint cell_count[]; };
layout(std430, binding = PF_SLOT_STATUS) buffer Status { uint status[]; };
#if PF_APIC
layout(std430, binding = PF_SLOT_PARTICLE_AFFINE) readonly buffer Affine { vec4 affine[]; };
#endif

void accumulate(int word, int value) {
    if (value == 0) return;  // zero weights (clamped stencil edges) cost no atomic
    int old = atomicAdd(accum[word], value);
    int sum = int(uint(old) + uint(value));  // wrapping add, as the atomic did
    if ((old >= 0) == (value >= 0) && (sum >= 0) != (old >= 0))
        atomicOr(status[PF_STATUS_FLAGS], PF_GPU_FLAG_P2G_OVERFLOW);
}

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    vec3 g = grid_coord(pos[i].xyz);
    vec3 v = vel[i].xyz;

    ivec3 cell = clamp(ivec3(floor(g)), ivec3(0), sim.grid.xyz - 1);
    atomicAdd(cell_count[cell_index(cell)], 1u);

    for (int axis = 0; axis < 3; ++axis) {
        Stencil st = face_stencil(axis, g);
#if PF_APIC
        vec3 c = affine[3u * i + uint(axis)].xyz * sim.dx;  // per grid unit
        vec3 node_offset = vec3(0.5);
        node_offset[axis] = 0.0;
        vec3 to_base = vec3(st.base) + node_offset - g;     // node b minus particle, grid units
#endif
        for (int n = 0; n < 8; ++n) {
            ivec3 d = stencil_offset(n);
            float w = stencil_weight(st.frac, d);
            int face = face_index(axis, st.base + d);
#if PF_APIC
            float va = v[axis] + dot(c, to_base + vec3(d));
#else
            float va = v[axis];
#endif
            // roundEven is odd-symmetric: mirrored inputs give mirrored integers.
            accumulate(2 * face, int(roundEven(w * va * sim.momentum_scale)));
            accumulate(2 * face + 1, int(roundEven(w * sim.weight_scale)));
        }
    }
}
