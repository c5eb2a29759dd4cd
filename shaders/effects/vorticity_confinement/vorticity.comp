// Vorticity confinement (PF_FEATURE_VORTICITY_CONFINEMENT), first pass, per cell: the vorticity
// w = curl u at the cell's centre by central differences of the cell-centred velocity (each
// component the mean of the cell's two faces on its lattice), and |w| in the fourth component.
// Only a FLUID cell whose six neighbours are FLUID gets one: beside AIR or SOLID the neighbours'
// velocities are not the liquid's yet (they are extrapolated after the pressure solve), so
// those cells keep w = 0 and the force pass leaves the surface and the walls alone.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_FACE_VEL) readonly buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer CellType { uint cell_type[]; };
layout(std430, binding = PF_SLOT_VORTICITY) writeonly buffer Vorticity { vec4 vorticity[]; };

bool fluid(ivec3 c) { return cell_inside(c) && PF_CELL_KIND(cell_type[cell_index(c)]) == PF_CELL_FLUID; }

#include "common/face_velocity.glsl"

void main() {
    int id = int(flat_id());
    if (id >= cell_total()) return;
    ivec3 c = cell_coord(id);
    bool interior = fluid(c);
    vec3 u_lo[3], u_hi[3];
    for (int a = 0; a < 3 && interior; ++a) {
        ivec3 e = ivec3(0);
        e[a] = 1;
        interior = fluid(c - e) && fluid(c + e);
        if (interior) {
            u_lo[a] = centre_velocity(c - e);
            u_hi[a] = centre_velocity(c + e);
        }
    }
    if (!interior) {
        vorticity[id] = vec4(0.0);
        return;
    }
    // d u_i / d x_j = (u_hi[j][i] - u_lo[j][i]) / (2 dx)
    float h2 = 0.5 / sim.dx;
    vec3 w = vec3(u_hi[1].z - u_lo[1].z - (u_hi[2].y - u_lo[2].y),
                  u_hi[2].x - u_lo[2].x - (u_hi[0].z - u_lo[0].z),
                  u_hi[0].y - u_lo[0].y - (u_hi[1].x - u_lo[1].x)) * h2;
    vorticity[id] = vec4(w, length(w));
}
