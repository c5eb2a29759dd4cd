// Accuracy metrics of a step, first half (docs/design.md §4.11): one fused pass over
// max(cells, particles) invocations. Invocation i looks at cell i (if i < cells) and particle i
// (if i < particle_count), so the grid and the particles are measured in one dispatch. Each
// workgroup writes three partial sums, added in a fixed order by metrics_finish.comp (no float
// atomics, so the same state always gives the same bits):
//   partials[3g]     = (sum div^2, max |div|, FLUID cells, sum min(count / rest, 1))
//   partials[3g + 1] = (sum |v|^2, sum -g . (x - origin), sum count / rest over interior
//                       FLUID cells, interior FLUID cells)
//   partials[3g + 2] = (sum of the strain P over interior FLUID cells, 0, 0, 0)
// An interior cell is FLUID with every face neighbour FLUID, SOLID or a domain wall: its
// count is not thinned by a free surface, so their mean is the liquid's density.
// P = (tr(G^2) - tr(G)^2) / 2 of the cell-centred velocity gradient G: a straight move of dt
// through the field changes a small volume by the factor 1 - dt^2 P (pure strain s: P = s^2,
// compressing; pure rotation w: P = -w^2, expanding), which the step clock limits for
// integrators that move particles along straight lines (src/sim/step_clock.h).
// div is the discrete divergence of the face velocities over a FLUID cell, in 1/s: after the
// velocity update (extrapolation only writes faces between two AIR cells, G2P and advection
// only read faces), so it is what the pressure solve of the step's last substep left.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) readonly buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_FACE_VEL) readonly buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_CELL_COUNT) readonly buffer Count { uint cell_count[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_METRICS_PARTIALS) writeonly buffer Partials { vec4 partials[]; };

shared vec4 s_grid[PF_WORKGROUP_SIZE];
shared vec4 s_particles[PF_WORKGROUP_SIZE];  // (|v|^2, height along -g, interior density, interior cells)
shared float s_strain[PF_WORKGROUP_SIZE];

// Cell-centred velocity component `a` of a FLUID cell: the mean of its two faces.
float centred(int a, ivec3 ijk) {
    return 0.5 * (face_vel[cell_face(a, ijk, 0)] + face_vel[cell_face(a, ijk, 1)]);
}

// The strain invariant P of an interior FLUID cell. G[a][a] from the cell's own faces; across
// an axis d != a, central differences of the centred components between FLUID neighbours,
// one-sided where a neighbour is not FLUID (a wall, an obstacle), 0 where neither is.
float strain_invariant(ivec3 ijk) {
    mat3 G;  // G[d][a] = d u_a / d x_d (the transpose does not change P)
    for (int a = 0; a < 3; ++a) {
        float own = centred(a, ijk);
        for (int d = 0; d < 3; ++d) {
            if (d == a) {
                G[d][a] = (face_vel[cell_face(a, ijk, 1)] - face_vel[cell_face(a, ijk, 0)]) / sim.dx;
                continue;
            }
            ivec3 p = ijk, m = ijk;
            p[d] += 1;
            m[d] -= 1;
            bool has_p = cell_inside(p) && PF_CELL_KIND(cell_type[cell_index(p)]) == PF_CELL_FLUID;
            bool has_m = cell_inside(m) && PF_CELL_KIND(cell_type[cell_index(m)]) == PF_CELL_FLUID;
            float span = float(has_p) + float(has_m);
            float up = has_p ? centred(a, p) : own, down = has_m ? centred(a, m) : own;
            G[d][a] = span > 0.0 ? (up - down) / (span * sim.dx) : 0.0;
        }
    }
    float trace = G[0][0] + G[1][1] + G[2][2];
    float trace_of_square = 0.0;
    for (int a = 0; a < 3; ++a)
        for (int d = 0; d < 3; ++d) trace_of_square += G[a][d] * G[d][a];
    return 0.5 * (trace_of_square - trace * trace);
}

void main() {
    uint id = flat_id();
    vec4 grid = vec4(0.0);  // (div^2, |div|, fluid, volume fraction)
    vec4 particles = vec4(0.0);  // (|v|^2, -g . (x - origin), count / rest if interior, interior)
    float strain = 0.0;
    if (id < uint(cell_total()) && PF_CELL_KIND(cell_type[id]) == PF_CELL_FLUID) {
        int c = int(id);
        ivec3 ijk = cell_coord(c);
        float div = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            div += face_vel[cell_face(axis, ijk, 1)] - face_vel[cell_face(axis, ijk, 0)];
        }
        div /= sim.dx;
        float density = float(cell_count[c]) / sim.rest_particles;
        grid = vec4(div * div, abs(div), 1.0, min(density, 1.0));
        bool interior = true;
        for (int n = 0; n < 6; ++n) {
            ivec3 nb = ijk + kNeighbours[n];
            if (cell_inside(nb) && PF_CELL_KIND(cell_type[cell_index(nb)]) == PF_CELL_AIR) interior = false;
        }
        if (interior) {
            particles.zw = vec2(density, 1.0);
            strain = strain_invariant(ijk);
        }
    }
    if (id < sim.particle_count)
        particles.xy = vec2(dot(vel[id].xyz, vel[id].xyz), -dot(sim.gravity.xyz, pos[id].xyz - sim.origin.xyz));

    // The workgroup's sums (the max in .y) as a fixed binary tree, as in solvers/common/reduce.glsl.
    uint lid = gl_LocalInvocationIndex;
    s_grid[lid] = grid;
    s_particles[lid] = particles;
    s_strain[lid] = strain;
    barrier();
    for (uint stride = uint(PF_WORKGROUP_SIZE) / 2u; stride > 0u; stride >>= 1u) {
        if (lid < stride) {
            vec4 a = s_grid[lid], b = s_grid[lid + stride];
            s_grid[lid] = vec4(a.x + b.x, max(a.y, b.y), a.z + b.z, a.w + b.w);
            s_particles[lid] += s_particles[lid + stride];
            s_strain[lid] += s_strain[lid + stride];
        }
        barrier();
    }
    if (lid == 0u) {
        uint g = gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;
        partials[3u * g] = s_grid[0];
        partials[3u * g + 1u] = s_particles[0];
        partials[3u * g + 2u] = vec4(s_strain[0], 0.0, 0.0, 0.0);
    }
}
