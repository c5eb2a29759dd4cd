// The particle trace inside a substep (docs/design.md §5): a particle crosses at most
// kTraceCells cells in one sub-step, and every sub-step's end goes through the wall clamp of
// common/sim.glsl, so a move of several cells cannot leave the domain between two checks. A
// particle that moves no further than kTraceCells in the substep takes one sub-step of the
// whole substep, which is the single move of one-clock stepping exactly. A trace of several
// sub-steps ends where it stands before a sub-step that would enter a SOLID cell (an obstacle's):
// moved several cells at once it could jump over a thin obstacle, which the obstacles' push after
// advection would then never see. (Euler's single sub-step of at most a cell ends where it lands,
// as a one-clock move did, and the push moves it out; the Runge-Kutta traces stop before a SOLID
// cell at every sub-step: sim/advect_rk.comp.) The including kernel declares cell_type[]
// (PF_SLOT_CELL_TYPE).

// Cells a particle crosses at most in one sub-step (tests/reference/cpu_reference.cpp: the same).
const float kTraceCells = 1.0;
// Sub-steps a particle takes at most (a bound on the loop, far above any CFL the API allows).
const int kMaxTraceSubsteps = 64;

// The walls a trace crossed in any of its sub-steps (the velocity stops into each at the end:
// common/sim.glsl's stopped_at_walls).
struct WallsCrossed {
    bvec3 low, high;
};

WallsCrossed no_walls_crossed() { return WallsCrossed(bvec3(false), bvec3(false)); }

// One sub-step's end: records the walls x crossed and returns it clamped into the domain.
vec3 trace_wall_clamp(vec3 x, inout WallsCrossed walls) {
    vec3 g = grid_coord(x);
    walls.low = bvec3(uvec3(walls.low) | uvec3(beyond_low_wall(g)));
    walls.high = bvec3(uvec3(walls.high) | uvec3(beyond_high_wall(g)));
    return keep_in_domain(x);
}

// Whether x lies in a SOLID cell (positions beyond a wall count in the cell inside it).
bool in_solid_cell(vec3 x) {
    ivec3 c = cell_of(grid_coord(x));
    return PF_CELL_KIND(cell_type[cell_index(c)]) == PF_CELL_SOLID;
}

// Whether the straight move from x0 to x (both inside the domain) passes through a SOLID cell:
// sampled at its quarters, so that a move of up to four cells cannot step over a wall one cell
// thick (a sub-step sized by its first stage's speed can move more than a cell).
bool move_enters_solid(vec3 x0, vec3 x) {
    for (int k = 1; k <= 4; ++k)
        if (in_solid_cell(mix(x0, x, 0.25 * float(k)))) return true;
    return false;
}

// The length of the next sub-step at speed `speed` with `remaining` seconds of the substep left:
// all of it when the particle crosses no more than kTraceCells cells in it, else as long as
// crossing that many takes; the last permitted sub-step takes the rest.
float trace_substep(float speed, float remaining, int substep) {
    float reach = kTraceCells * sim.dx;
    return (speed * remaining <= reach || substep == kMaxTraceSubsteps - 1) ? remaining : reach / speed;
}
