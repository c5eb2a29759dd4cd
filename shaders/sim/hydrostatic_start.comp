// Hydrostatic start (docs/design.md §4.5a): the warm start of the first pressure solve after
// particles were added, so that liquid at rest starts in equilibrium instead of sagging while
// an iterative solver climbs from p = 0. One invocation per column of cells along gravity's
// dominant axis a: the run of FLUID cells resting on the floor (the wall gravity points at) of
// length L gets, in its k-th cell from the floor (k = 0..L-1), the discrete hydrostatic pressure
//     p = density * |g_a| * dx * (L - k)   (pascals)
// which solves §4.6 exactly for a flat tank: the face between the top FLUID cell and the AIR
// above it carries p_top - 0 = density |g_a| dx, every face below the same step. Only cells still
// at p = 0 are written (cells the solver has seen keep their warm start); fluid not resting on
// the floor (a falling blob: p = 0 is its solution) and AIR are left alone. A SOLID cell
// (obstacle) is a floor for the run above it; a run capped by a SOLID cell (liquid under an
// obstacle, whose pressure comes from the liquid around it) is left to the solver.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_PRESSURE) buffer Pressure { float pressure[]; };

void main() {
    vec3 g = abs(sim.gravity.xyz);
    int axis = (g.x >= g.y && g.x >= g.z) ? 0 : (g.y >= g.z ? 1 : 2);  // the host picks the same
    if (g[axis] == 0.0) return;
    int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    ivec3 n = sim.grid.xyz;
    int column = int(flat_id());
    ivec3 columns = ivec3(n[a1], n[a2], 1);  // the columns' box, a1 fastest
    if (column >= lattice_total(columns)) return;
    ivec3 c;
    ivec3 base = lattice_coord(columns, column);
    c[a1] = base.x;
    c[a2] = base.y;
    bool down_is_low = sim.gravity[axis] < 0.0;  // the floor is cell 0 along the axis, else n - 1
    int floor_cell = down_is_low ? 0 : n[axis] - 1;
    int up = down_is_low ? 1 : -1;

    float step = sim.density * g[axis] * sim.dx;
    int start = 0;  // first cell of the current run, counted from the floor
    for (int k = 0; k <= n[axis]; ++k) {
        uint t = PF_CELL_AIR;  // k = n: the run ends at the lid, as under AIR
        if (k < n[axis]) {
            c[axis] = floor_cell + up * k;
            t = PF_CELL_KIND(cell_type[cell_index(c)]);
        }
        if (t == PF_CELL_FLUID) continue;
        // The run [start, k) rests on the floor or a SOLID cell and ends here.
        if (t != PF_CELL_SOLID) {
            for (int j = start; j < k; ++j) {
                c[axis] = floor_cell + up * j;
                int i = cell_index(c);
                if (pressure[i] == 0.0) pressure[i] = step * float(k - j);
            }
            break;  // above AIR nothing rests on anything
        }
        start = k + 1;
    }
}
