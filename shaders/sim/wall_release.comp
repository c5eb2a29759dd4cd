// Wall release: a ceiling holds the liquid under it only while it pushes. Where the last solve's
// pressure in a FLUID cell under a domain wall that gravity pulls the liquid away from (the lid,
// or any wall with gravity along its inward normal) is (near) zero or negative, and the cell
// touches AIR, the wall would have to pull to keep the liquid there: that wall face takes the part
// of the velocity across the cell (its opposite face's) that leaves the wall, so the pressure
// solve and G2P see liquid falling off the wall instead of a film held by suction or by the wall
// face's zero, which a particle touching the wall interpolates whole. Where the liquid moves into
// the wall the face stays 0 (free-slip). Only where AIR touches the cell: a box full of liquid
// has no pressure gauge (its pressure is known up to a constant) and nothing to let in; and only
// ceilings: liquid slides down a side wall anyway, and letting every wall go added energy to a
// capillary wave (docs/notes/2026-11-27-wall-release.md). Runs before the pressure setup, after every force on the
// faces; each wall face belongs to one cell and it reads only interior faces, so it races with
// nothing. A grid one cell thick along an axis keeps its walls.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_FACE_VEL) buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_PRESSURE) readonly buffer Pressure { float pressure[]; };

// A wall bears a cell's liquid while the cell's pressure exceeds this share of the weight of one
// cell of liquid (rho |g| dx): a film released last substep solves to about 0, and must stay
// released rather than flicker on the solver's tolerance; a full column's top cell carries half.
const float kHoldingShare = 0.1;

// One invocation per cell of the three wall layers (x, then y, then z): the cell beside the wall
// of that axis that gravity pulls away from, if any.
void main() {
    int id = int(flat_id());
    ivec3 n = sim.grid.xyz;
    int layers[3] = int[3](n.y * n.z, n.x * n.z, n.x * n.y);
    int axis = id < layers[0] ? 0 : (id < layers[0] + layers[1] ? 1 : 2);
    int k = id - (axis > 0 ? layers[0] : 0) - (axis > 1 ? layers[1] : 0);
    if (axis == 2 && k >= layers[2]) return;
    float g = sim.gravity[axis];
    if (g == 0.0 || n[axis] < 2) return;
    int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    ivec3 ijk;
    ijk[axis] = g < 0.0 ? n[axis] - 1 : 0;
    ivec3 wall = lattice_coord(ivec3(n[min(a1, a2)], n[max(a1, a2)], 1), k);  // the lower axis fastest
    ijk[min(a1, a2)] = wall.x;
    ijk[max(a1, a2)] = wall.y;
    int c = cell_index(ijk);
    if (PF_CELL_KIND(cell_type[c]) != PF_CELL_FLUID) return;
    float holding = kHoldingShare * sim.density * length(sim.gravity.xyz) * sim.dx;
    if (pressure[c] > holding) return;
    bool air = false;
    for (int q = 0; q < 6; ++q) {
        ivec3 nb = ijk + kNeighbours[q];
        air = air || (cell_inside(nb) && PF_CELL_KIND(cell_type[cell_index(nb)]) == PF_CELL_AIR);
    }
    if (!air) return;
    if (g > 0.0) {  // the low wall: leaving is +
        face_vel[cell_face(axis, ijk, 0)] = max(face_vel[cell_face(axis, ijk, 1)], 0.0);
    } else {  // the high wall: leaving is -
        face_vel[cell_face(axis, ijk, 1)] = min(face_vel[cell_face(axis, ijk, 0)], 0.0);
    }
}
