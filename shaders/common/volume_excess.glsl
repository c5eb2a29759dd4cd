// The particle-density excess a FLUID cell's volume correction removes (docs/design.md §4.5):
// e = count / rest - 1, at most 1 (a cell never holds more than twice the rest count for long).
// A cell beside AIR is partly filled by nature, so there only a surplus counts (e >= 0). With
// separation on, so is a cell beside a wall or obstacle whose pressure (the last solve's) is 0:
// the liquid there may be leaving the wall (a slab falling away from the lid), and pulling it
// back would hold it up. Where the pressure presses the liquid against the wall, the cell is
// corrected both ways (making every wall one-sided would inflate the liquid: docs/design.md).
// Needs common/sim.glsl and the cell types, counts and pressures as `cell_type[]`,
// `cell_count[]` and `pressure[]`.
float volume_excess(ivec3 ijk) {
    int c = cell_index(ijk);
    float excess = min(float(cell_count[c]) / sim.rest_particles - 1.0, 1.0);
    bool leaving = sim.separation != 0u && pressure[c] <= 0.0;
    for (int n = 0; n < 6; ++n) {
        ivec3 nb = ijk + kNeighbours[n];
        bool open = cell_inside(nb) ? PF_CELL_KIND(cell_type[cell_index(nb)]) == PF_CELL_AIR ||
                                          (leaving && PF_CELL_KIND(cell_type[cell_index(nb)]) == PF_CELL_SOLID)
                                    : leaving;
        if (open) return max(excess, 0.0);
    }
    return excess;
}
