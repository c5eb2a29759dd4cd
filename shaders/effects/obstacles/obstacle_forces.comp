// Obstacles, per face, after velocity_update: the force and torque the liquid's pressure exerts
// on each obstacle. Every face between a SOLID cell and a FLUID cell adds -p n dx^2 to the
// obstacle the SOLID cell's centre lies deepest in (n: the unit axis from the solid cell into
// the fluid one), and (x_face - position) x that to its torque. p is the FLUID cell's pressure
// carried to the face along gravity, p + density g . (x_face - x_cell): the cell's pressure
// belongs to its centre, half a cell from the face, and without this a submerged box would feel
// the pressure difference of its height plus one cell (gravity-consistent buoyancy, rho g V for
// a box that covers whole cells). Each substep adds its sums times u_weight (1 / substeps), so
// the buffer holds the step's mean force.
// Summation: each workgroup first adds its faces' contributions per obstacle in shared memory,
// then adds each non-zero sum to the global word with one float compare-and-swap loop; float
// rather than fixed point because forces span many orders of magnitude with no scale known in
// advance, and at most one global atomic per workgroup and word keeps contention low. The order
// of the additions varies, so the last bits vary run to run.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
layout(std430, binding = PF_SLOT_PRESSURE) readonly buffer Pressure { float pressure[]; };
layout(std430, binding = PF_SLOT_OBSTACLE_FORCES) buffer Forces { uint force_bits[]; };
layout(location = PF_LOC_OBSTACLE_FORCE_WEIGHT) uniform float u_weight;
#include "effects/obstacles/obstacle_sdf.glsl"

// Per obstacle: force.xyz, torque.xyz (float bits).
shared uint s_sum[PF_OBSTACLE_MAX * 6];

void shared_add(uint word, float value) {
    uint expected = s_sum[word];
    for (;;) {
        uint seen = atomicCompSwap(s_sum[word], expected, floatBitsToUint(uintBitsToFloat(expected) + value));
        if (seen == expected) break;
        expected = seen;
    }
}

void global_add(uint word, float value) {
    uint expected = force_bits[word];
    for (;;) {
        uint seen = atomicCompSwap(force_bits[word], expected, floatBitsToUint(uintBitsToFloat(expected) + value));
        if (seen == expected) break;
        expected = seen;
    }
}

void main() {
    uint lid = gl_LocalInvocationIndex;
    for (uint w = lid; w < uint(PF_OBSTACLE_MAX * 6); w += uint(PF_WORKGROUP_SIZE)) s_sum[w] = 0u;
    barrier();
    int id = int(flat_id());
    if (id < face_total()) {
        int axis;
        ivec3 f;
        decode_face(id, axis, f);
        if (!face_is_wall(axis, f)) {
            ivec3 lo = face_cell_below(axis, f);
            uint ta = PF_CELL_KIND(cell_type[cell_index(lo)]);
            uint tb = PF_CELL_KIND(cell_type[cell_index(f)]);
            bool solid_lo = ta == PF_CELL_SOLID && tb == PF_CELL_FLUID;
            bool solid_hi = tb == PF_CELL_SOLID && ta == PF_CELL_FLUID;
            int k = -1;
            if (solid_lo || solid_hi) scene_distance(cell_centre(solid_lo ? lo : f), k);
            if (k >= 0) {
                ivec3 wet = solid_lo ? f : lo;
                vec3 xf = face_centre(axis, f);
                float p = pressure[cell_index(wet)] + sim.density * dot(sim.gravity.xyz, xf - cell_centre(wet));
                vec3 n = vec3(0.0);
                n[axis] = solid_lo ? 1.0 : -1.0;
                vec3 force = (-p * sim.dx * sim.dx * u_weight) * n;
                vec3 torque = cross(xf - obstacles[PF_OBSTACLE_VEC4S * uint(k)].xyz, force);
                uint base = uint(k) * 6u;
                for (int c = 0; c < 3; ++c) {
                    shared_add(base + uint(c), force[c]);
                    shared_add(base + 3u + uint(c), torque[c]);
                }
            }
        }
    }
    barrier();
    if (lid < u_count * 6u) {
        float v = uintBitsToFloat(s_sum[lid]);
        uint k = lid / 6u, c = lid % 6u;
        if (v != 0.0) global_add(k * uint(PF_OBSTACLE_FORCE_WORDS) + (c < 3u ? c : c + 1u), v);
    }
}
