// Sampling the face velocities beside an obstacle. With PF_SOLID_WALLS 1 (a simulation with
// PF_FEATURE_OBSTACLES) a tangential lattice's stencil stops at a SOLID cell one cell thick as
// face_stencil's does at the domain's walls: it takes the particle's own column only. Why: a face
// inside such a wall is filled by extrapolation from both of its sides, so a particle read the
// liquid beyond it (a still pool behind such a wall reached 2 m/s beside a jet). A thicker wall's
// inner faces are filled from their own side first, and its stencil is left as it was. The
// includer declares cell_type[] when PF_SOLID_WALLS is 1 (at PF_SLOT_CELL_TYPE, or
// PF_SLOT_APIC_CELL_TYPE beside APIC's affine vectors).
#ifndef PF_SOLID_WALLS
#define PF_SOLID_WALLS 0
#endif

#if PF_SOLID_WALLS
bool solid_cell(ivec3 c) { return PF_CELL_KIND(cell_type[cell_index(c)]) == PF_CELL_SOLID; }
#endif

// face_stencil(axis, g), stopped at SOLID cells beside the particle's own cell across each
// tangential axis; `slope` (stencil_slope's factor, APIC's) is 0 on the axes it stopped.
Stencil sampling_stencil(int axis, vec3 g, inout vec3 slope) {
    Stencil st = face_stencil(axis, g);
#if PF_SOLID_WALLS
    ivec3 c = cell_of(g);
    if (solid_cell(c)) return st;
    for (int a = 0; a < 3; ++a) {
        if (a == axis) continue;  // the normal lattice's two faces are the own cell's
        // On a cell-centred axis the stencil spans the own column and one beside it (on an axis
        // one cell long, the own column alone: its "beside" lies outside the domain).
        bool own_low = c[a] == st.base[a];
        ivec3 step = ivec3(0);
        step[a] = own_low ? 1 : -1;
        // Only a wall one cell thick with the domain going on beyond it: a thicker one's inner
        // faces come from the near side alone.
        if (!cell_inside(c + 2 * step) || !solid_cell(c + step) || solid_cell(c + 2 * step)) continue;
        st.frac[a] = own_low ? 0.0 : 1.0;
        slope[a] = 0.0;
    }
#endif
    return st;
}

Stencil sampling_stencil(int axis, vec3 g) {
    vec3 unused = vec3(1.0);
    return sampling_stencil(axis, g, unused);
}
