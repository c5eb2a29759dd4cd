// Particle-to-grid: splats each particle's velocity onto the 8 nearest samples of every MAC
// face lattice with 32-bit fixed-point integer atomics (momentum and weight), and counts
// particles per cell. Integer sums are order independent, so the result is bit-identical
// run to run. Overflow of an accumulator is detected and flagged, never silent.
// Permutation PF_APIC: each contribution is the particle's affine velocity at the node,
// v_a + c_a . (x_i - x_p) (Jiang et al. 2015), instead of v_a.
// Permutation PF_P2G_FLOAT (pf_p2g PF_P2G_FLOAT_ATOMIC): plain float sums of w·v and w instead,
// with GL_NV_shader_atomic_float's atomicAdd where the GL has it and a compare-and-swap loop on
// the float's bits elsewhere. No rounding to a fixed-point grid and no overflow, but float
// addition is not associative: the sums depend on the order the atomics land in, so results
// are not bit-identical run to run (docs/accuracy.md measures by how much).
#if PF_P2G_FLOAT && defined(GL_NV_shader_atomic_float)
#extension GL_NV_shader_atomic_float : enable
#define PF_NATIVE_FLOAT_ATOMICS 1
#else
#define PF_NATIVE_FLOAT_ATOMICS 0
#endif
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) readonly buffer Vel { vec4 vel[]; };
#if PF_P2G_FLOAT && PF_NATIVE_FLOAT_ATOMICS
layout(std430, binding = PF_SLOT_FACE_ACCUM) buffer Accum { float accum[]; };  // 2 words per face
#elif PF_P2G_FLOAT
layout(std430, binding = PF_SLOT_FACE_ACCUM) buffer Accum { uint accum_bits[]; };  // floats' bits
#else
layout(std430, binding = PF_SLOT_FACE_ACCUM) buffer Accum { int accum[]; };  // 2 words per face
#endif
layout(std430, binding = PF_SLOT_CELL_COUNT) buffer Count { uint cell_count[]; };
layout(std430, binding = PF_SLOT_STATUS) buffer Status { uint status[]; };
#if PF_APIC
layout(std430, binding = PF_SLOT_PARTICLE_AFFINE) readonly buffer Affine { vec4 affine[]; };
#endif
#include "transfer/common/p2g_terms.glsl"

#if PF_P2G_FLOAT
void accumulate_float(int word, float value) {
    if (value == 0.0) return;  // zero weights (clamped stencil edges) cost no atomic
#if PF_NATIVE_FLOAT_ATOMICS
    atomicAdd(accum[word], value);
#else
    // No float atomics: add through the bits with compare-and-swap.
    uint expected = accum_bits[word];
    for (;;) {
        uint desired = floatBitsToUint(uintBitsToFloat(expected) + value);
        uint seen = atomicCompSwap(accum_bits[word], expected, desired);
        if (seen == expected) break;
        expected = seen;
    }
#endif
}
#else
void accumulate(int word, int value) {
    if (value == 0) return;  // zero weights (clamped stencil edges) cost no atomic
    int old = atomicAdd(accum[word], value);
    int sum = int(uint(old) + uint(value));  // wrapping add, as the atomic did
    if ((old >= 0) == (value >= 0) && (sum >= 0) != (old >= 0))
        atomicOr(status[PF_STATUS_FLAGS], PF_GPU_FLAG_P2G_OVERFLOW);
}
#endif

void main() {
    uint i = flat_id();
    if (i >= sim.particle_count) return;
    vec3 g = grid_coord(pos[i].xyz);
    vec3 v = vel[i].xyz;

    ivec3 cell = cell_of(g);
    atomicAdd(cell_count[cell_index(cell)], 1u);

    for (int axis = 0; axis < 3; ++axis) {
        LatticeTerms t = lattice_terms(i, axis, g, v);
        for (int n = 0; n < 8; ++n) {
            float w = term_weight(t, n), va = term_velocity(t, n);
            int face = face_index(axis, term_node(t, n));
#if PF_P2G_FLOAT
            accumulate_float(accum_word(face, 0), w * va);
            accumulate_float(accum_word(face, 1), w);
#else
            accumulate(accum_word(face, 0), fixed_momentum(w, va));
            accumulate(accum_word(face, 1), fixed_weight(w));
#endif
        }
    }
}
