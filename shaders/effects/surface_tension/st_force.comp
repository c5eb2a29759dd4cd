// Surface tension (PF_FEATURE_SURFACE_TENSION), third pass, per FLUID cell beside AIR: the
// pressure jump p_liquid - p_air = sigma kappa across the free surface, imposed the ghost-fluid way
// (Kang, Fedkiw & Liu 2000). The surface's pressure is sigma kappa instead of 0, so
// sim/velocity_update.comp would subtract (dt / (rho dx)) (p_hi - p_lo) / theta with sigma kappa as
// the AIR side's p, theta the face's fraction as there. That term is known before the solve and
// the update is linear in it, so it is added to the face velocity here, before the pressure setup,
// and the projection (p = 0 at the surface) then gives exactly the jump's solution.
// kappa = div n at the centres of the cell's AIR neighbours, n the outward unit normal
// -grad L / |grad L| of st_liquid.comp's field L at each centre's 8 corners (gradients from the
// 2 x 2 x 2 cells around each), averaged, moved to the surface and clamped to kMaxCurvature / dx
// (a sphere of one cell's radius: smaller features are not resolved). One value per cell, on all its
// AIR faces: a jump that differs between the faces of a cell whose surface is near its centre
// (theta small) is divided by theta and drove a drop unstable; a uniform one moves nothing, so
// only differences of curvature between cells drive flow. Curvature taken at the FLUID centres
// was worse: the field saturates inside the liquid and its gradient there is noise.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_FACE_VEL) buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_FACE_FRACTION) readonly buffer Fraction { float face_fraction[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer CellType { uint cell_type[]; };
layout(std430, binding = PF_SLOT_ST_LIQUID) readonly buffer Liquid { float liquid[]; };
layout(location = PF_LOC_ST_TENSION) uniform float u_tension;

const float kMaxCurvature = 2.0;
// Below this |grad L| (per cell, summed over a corner's four differences) a corner has no normal.
const float kMinGradient = 4e-3;

// L at cell c, the domain's outer cells repeated beyond its walls (a mirror: no normal
// component across a wall).
float field(ivec3 c) { return liquid[cell_index(clamp(c, ivec3(0), sim.grid.xyz - 1))]; }

float curvature(ivec3 c) {
    float v[27];
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x) v[(z * 3 + y) * 3 + x] = field(c + ivec3(x, y, z) - 1);
    float div = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        // o: the corner's 2 x 2 x 2 block of cells starts at offset o - 1 (o = 0: the corner on
        // the - side of the centre, 1: on the + side).
        ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, corner >> 2);
        vec3 g = vec3(0.0);
        for (int k = 0; k < 2; ++k)
            for (int j = 0; j < 2; ++j) {
                g.x += v[((o.z + k) * 3 + o.y + j) * 3 + o.x + 1] - v[((o.z + k) * 3 + o.y + j) * 3 + o.x];
                g.y += v[((o.z + k) * 3 + o.y + 1) * 3 + o.x + j] - v[((o.z + k) * 3 + o.y) * 3 + o.x + j];
                g.z += v[((o.z + 1) * 3 + o.y + k) * 3 + o.x + j] - v[(o.z * 3 + o.y + k) * 3 + o.x + j];
            }
        float len = length(g);
        if (len < kMinGradient) continue;
        // d n_i / d x_i at the centre: the + corners' n_i minus the - corners', over 4 corners and dx.
        div -= dot(vec3(2 * o - 1), g) / len;
    }
    return div / (4.0 * sim.dx);
}

void main() {
    int id = int(flat_id());
    if (id >= cell_total() || PF_CELL_KIND(cell_type[id]) != PF_CELL_FLUID) return;
    ivec3 c = cell_coord(id);
    bool air[6];
    float kappa = 0.0, faces = 0.0;
    for (int n = 0; n < 6; ++n) {
        ivec3 q = c + kNeighbours[n];
        air[n] = cell_inside(q) && PF_CELL_KIND(cell_type[cell_index(q)]) == PF_CELL_AIR;
        if (!air[n]) continue;
        kappa += curvature(q);
        faces += 1.0;
    }
    if (faces == 0.0) return;
    kappa /= faces;
    // The AIR centres' level set lies about half a cell outside the surface (where theta is 1/2 on
    // average); in 3D a mean curvature k there is k / (1 - k d / 2) at distance d inside.
    if (sim.ghost_fluid != 0u) kappa /= max(1.0 - 0.25 * kappa * sim.dx, 0.5);
    kappa = clamp(kappa, -kMaxCurvature / sim.dx, kMaxCurvature / sim.dx);
    for (int n = 0; n < 6; ++n) {
        if (!air[n]) continue;
        int face = neighbour_face(c, n);
        float jump = sim.dt * u_tension * kappa / (sim.density * sim.dx * face_fraction[face]);
        // AIR on the + side: the surface's pressure is p_hi; on the - side, p_lo.
        face_vel[face] += (n & 1) != 0 ? -jump : jump;
    }
}
