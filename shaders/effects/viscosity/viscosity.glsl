// What the viscosity kernels share (PF_FEATURE_VISCOSITY; the variational viscosity of Batty &
// Bridson 2008 on the MAC grid, docs/design.md §9.8). The solve finds the face velocities u that
// minimise  1/2 sum_f m_f (u_f - u*_f)^2 + c/2 (sum_cells w e_aa^2 + sum_edges 2 w e_ab^2),
// c = 2 nu dt / dx^2, where e is the strain rate times dx: e_aa = u_a(c + e_a) - u_a(c) at a cell
// centre, e_ab = ((u_a(n) - u_a(n - e_b)) + (u_b(n) - u_b(n - e_a))) / 2 on the edge of axes a, b
// through cell corner n. Its gradient is m (u - u*) + D^T sigma with the stresses
// sigma_aa = c w e_aa and sigma_ab = 2 c w e_ab (times dx / (rho dt)).
// Weights: a cell centre counts if the cell is liquid; an edge by the liquid and solid among its
// four cells, and not at all where one of its faces has air on both sides (there the surface is
// stress-free) or, with free slip, where it touches a solid.
// Requires the kernel to declare `cell_type` (uint[]) and include common/sim.glsl first.
#include "effects/viscosity/viscosity_state.h"

layout(location = PF_LOC_VISC_NU) uniform float u_nu;

// c = 2 nu dt / dx^2: the strain energy's weight against the kinetic energy's.
float visc_coupling() { return 2.0 * u_nu * sim.dt / (sim.dx * sim.dx); }
layout(location = PF_LOC_VISC_FREE_SLIP) uniform uint u_free_slip;

const int VISC_FREE = 0;     // air on both sides: never part of a weighted stress
const int VISC_UNKNOWN = 1;  // liquid on a side, no solid: solved for
const int VISC_FIXED = 2;    // a wall or a solid on a side: keeps its velocity (the solid's)

// A cell's kind; outside the domain is solid (the walls).
int visc_kind(ivec3 c) { return cell_inside(c) ? int(PF_CELL_KIND(cell_type[cell_index(c)])) : PF_CELL_SOLID; }

int visc_role(int lo, int hi) {
    if (lo == PF_CELL_SOLID || hi == PF_CELL_SOLID) return VISC_FIXED;
    return (lo == PF_CELL_FLUID || hi == PF_CELL_FLUID) ? VISC_UNKNOWN : VISC_FREE;
}

ivec3 visc_unit(int axis) {
    ivec3 e = ivec3(0);
    e[axis] = 1;
    return e;
}

// Role and mass weight (the liquid share of its control volume) of face (axis, f).
int visc_face_role(int axis, ivec3 f) { return visc_role(visc_kind(f - visc_unit(axis)), visc_kind(f)); }
float visc_face_mass(int axis, ivec3 f) {
    return 0.5 * (float(visc_kind(f - visc_unit(axis)) == PF_CELL_FLUID) + float(visc_kind(f) == PF_CELL_FLUID));
}

float visc_cell_weight(ivec3 c) { return visc_kind(c) == PF_CELL_FLUID ? 1.0 : 0.0; }

// Weight of the edge of axes a < b through corner n (its four cells share n's third coordinate).
float visc_edge_weight(int a, int b, ivec3 n) {
    ivec3 ea = visc_unit(a), eb = visc_unit(b);
    int k00 = visc_kind(n - ea - eb), k10 = visc_kind(n - eb), k01 = visc_kind(n - ea), k11 = visc_kind(n);
    int fluid = int(k00 == PF_CELL_FLUID) + int(k10 == PF_CELL_FLUID) + int(k01 == PF_CELL_FLUID) + int(k11 == PF_CELL_FLUID);
    int solid = int(k00 == PF_CELL_SOLID) + int(k10 == PF_CELL_SOLID) + int(k01 == PF_CELL_SOLID) + int(k11 == PF_CELL_SOLID);
    if (fluid == 0 || (solid > 0 && u_free_slip != 0u)) return 0.0;
    // Its four faces: u_a(n) between k01 and k11, u_a(n - e_b) between k00 and k10, u_b(n)
    // between k10 and k11, u_b(n - e_a) between k00 and k01.
    if (visc_role(k01, k11) == VISC_FREE || visc_role(k00, k10) == VISC_FREE || visc_role(k10, k11) == VISC_FREE ||
        visc_role(k00, k01) == VISC_FREE)
        return 0.0;
    return 0.25 * float(fluid + solid);
}

// Index of the stress of edge pair (a, b) in a node's vec4: xy 0, xz 1, yz 2.
int visc_pair(int a, int b) { return a + b - 1; }
