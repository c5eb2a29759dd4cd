// The particle-density excess a FLUID cell's volume correction removes (docs/design.md §4.5):
// e = count / rest - 1, at most 1 (a cell never holds more than twice the rest count for long).
// A cell beside AIR is partly filled by nature, so there only a surplus counts (e >= 0). With the
// ghost-fluid surface only a surplus beyond a quarter of the rest count does (e - 1/4 >= 0): that
// surface follows the particles, so lifting the particle or two a moving surface brings into a
// cell raises the surface the pressure sees and adds potential energy that becomes waves; a clump
// is still spread (docs/design.md §4.5). With
// separation on, so is a cell beside a wall or obstacle whose pressure (the last solve's) is 0:
// the liquid there may be leaving the wall (a slab falling away from the lid), and pulling it
// back would hold it up. Where the pressure presses the liquid against the wall, the cell is
// corrected both ways (making every wall one-sided would inflate the liquid: docs/notes/2026-11-25-volume-correction.md).
// Needs common/sim.glsl and the cell types, counts and pressures as `cell_type[]`,
// `cell_count[]` and `pressure[]`.

// Surplus a ghost-fluid surface cell keeps, in rest counts (measured:
// docs/notes/2026-11-26-ghost-fluid-default.md).
const float kGhostSurfaceDeadBand = 0.25;

float volume_excess(ivec3 ijk) {
    int c = cell_index(ijk);
    float excess = min(float(cell_count[c]) / sim.rest_particles - 1.0, 1.0);
    bool leaving = sim.separation != 0u && pressure[c] <= 0.0;
    bool open = false;
    for (int n = 0; n < 6; ++n) {
        ivec3 nb = ijk + kNeighbours[n];
        uint kind = cell_inside(nb) ? PF_CELL_KIND(cell_type[cell_index(nb)]) : PF_CELL_SOLID;
        if (kind == PF_CELL_AIR && sim.ghost_fluid != 0u) return max(excess - kGhostSurfaceDeadBand, 0.0);
        open = open || kind == PF_CELL_AIR || (leaving && kind == PF_CELL_SOLID);
    }
    return open ? max(excess, 0.0) : excess;
}
