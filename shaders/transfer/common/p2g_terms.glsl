// One particle's terms on one MAC lattice, shared by the splatting kernels
// (transfer/atomic/p2g.comp, transfer/tiled/tile_splat.comp) so that they compute, and round,
// the same terms: the lattice's stencil at the particle, then per node n its face sample, its
// weight and the velocity carried there: v_a, or with PF_APIC the particle's affine velocity at
// the node, v_a + c_a . (x_node - x_p) (Jiang et al. 2015; the includer declares affine[]).
// Fixed point rounds with roundEven, which is odd-symmetric: mirrored inputs give mirrored
// integers.

struct LatticeTerms {
    Stencil st;
    float v;        // the particle's velocity component along the lattice's axis
#if PF_APIC
    vec3 c;         // its affine vector for that component, per grid unit
    vec3 to_base;   // stencil node `base` minus the particle, grid units
#endif
};

LatticeTerms lattice_terms(uint i, int axis, vec3 g, vec3 v) {
    LatticeTerms t;
    t.st = face_stencil(axis, g);
    t.v = v[axis];
#if PF_APIC
    t.c = affine[3u * i + uint(axis)].xyz * sim.dx;
    vec3 node_offset = vec3(0.5);
    node_offset[axis] = 0.0;
    t.to_base = vec3(t.st.base) + node_offset - g;
#endif
    return t;
}

ivec3 term_node(LatticeTerms t, int n) { return t.st.base + stencil_offset(n); }

float term_weight(LatticeTerms t, int n) { return stencil_weight(t.st.frac, stencil_offset(n)); }

float term_velocity(LatticeTerms t, int n) {
#if PF_APIC
    return t.v + dot(t.c, t.to_base + vec3(stencil_offset(n)));
#else
    return t.v;
#endif
}

int fixed_momentum(float w, float va) { return int(roundEven(w * va * sim.momentum_scale)); }

int fixed_weight(float w) { return int(roundEven(w * sim.weight_scale)); }
