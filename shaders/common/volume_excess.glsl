// The particle-density excess a FLUID cell's volume correction removes (docs/design.md §4.5):
// e = count / rest - 1, at most 1 (a cell never holds more than twice the rest count for long);
// a cell beside AIR is partly filled by nature, so there only a surplus counts (e >= 0).
// Needs common/sim.glsl and the cell types and counts as `cell_type[]`, `cell_count[]`.
float volume_excess(ivec3 ijk) {
    float excess = min(float(cell_count[cell_index(ijk)]) / sim.rest_particles - 1.0, 1.0);
    for (int n = 0; n < 6; ++n) {
        ivec3 nb = ijk + kNeighbours[n];
        if (cell_inside(nb) && cell_type[cell_index(nb)] == PF_CELL_AIR) return max(excess, 0.0);
    }
    return excess;
}
