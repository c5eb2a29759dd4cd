// Viscosity (PF_FEATURE_VISCOSITY), per cell corner (node): the stresses of a face-velocity
// field (shaders/effects/viscosity/viscosity.glsl), the matrix-vector product's first half. Node n
// writes the three edges through it (xy, xz, yz) and, when n is also a cell, that cell's three
// normal stresses. With PF_VISC_START the field is the projected face velocities u*, with each
// fixed face at the velocity its wall or obstacle gave it after classify (velocity_update has
// since zeroed the faces inside a solid, where a moving obstacle's ghost velocity is needed);
// otherwise it is CG's next search direction, formed here from
// the residual and the last direction (p = r / diag + beta p_old on unknown faces, 0 elsewhere)
// exactly as visc_apply.comp forms and stores it.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer CellType { uint cell_type[]; };
layout(std430, binding = PF_SLOT_VISC_P) readonly buffer Field { float field[]; };
layout(std430, binding = PF_SLOT_VISC_SIGMA_CELL) writeonly buffer SigmaCell { vec4 sigma_cell[]; };
layout(std430, binding = PF_SLOT_VISC_SIGMA_NODE) writeonly buffer SigmaNode { vec4 sigma_node[]; };
#if PF_VISC_START
layout(std430, binding = PF_SLOT_VISC_SOLID_VEL) readonly buffer SolidVel { float solid_vel[]; };
#else
layout(std430, binding = PF_SLOT_VISC_R) readonly buffer Residual { float r[]; };
layout(std430, binding = PF_SLOT_VISC_COEF) readonly buffer Coef { vec2 coef[]; };
layout(std430, binding = PF_SLOT_VISC_STATE) readonly buffer State { uint state[]; };
#endif
#include "effects/viscosity/viscosity.glsl"

#if !PF_VISC_START
float g_beta;
#endif

// The field on face (axis, f); 0 outside the lattice (the ghost faces beyond the walls).
float value(int axis, ivec3 f) {
    if (!face_inside(axis, f)) return 0.0;
    int i = face_index(axis, f);
#if PF_VISC_START
    return visc_face_role(axis, f) == VISC_FIXED ? solid_vel[i] : field[i];
#else
    float inv_diag = coef[i].y;
    return inv_diag > 0.0 ? inv_diag * r[i] + g_beta * field[i] : 0.0;
#endif
}

void main() {
    int id = int(flat_id());
    if (id >= node_total()) return;
#if !PF_VISC_START
    g_beta = uintBitsToFloat(state[PF_VISC_BETA]);
#endif
    ivec3 n = node_coord(id);
    float c = visc_coupling();
    if (cell_inside(n)) {  // n >= 0
        vec4 s = vec4(0.0);
        if (visc_kind(n) == PF_CELL_FLUID) {
            for (int a = 0; a < 3; ++a) s[a] = c * (value(a, n + visc_unit(a)) - value(a, n));
        }
        sigma_cell[cell_index(n)] = s;
    }
    vec4 e = vec4(0.0);
    for (int a = 0; a < 2; ++a) {
        for (int b = a + 1; b < 3; ++b) {
            int third = 3 - a - b;
            if (n[third] >= sim.grid[third]) continue;  // the edge would lie beyond the last cell
            float w = visc_edge_weight(a, b, n);
            if (w <= 0.0) continue;
            ivec3 ea = visc_unit(a), eb = visc_unit(b);
            float strain = 0.5 * ((value(a, n) - value(a, n - eb)) + (value(b, n) - value(b, n - ea)));
            e[visc_pair(a, b)] = 2.0 * c * w * strain;
        }
    }
    sigma_node[id] = e;
}
