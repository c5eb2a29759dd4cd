// Whitewater (PF_FEATURE_WHITEWATER), third pass, per cell: new particles where the liquid
// traps air, breaks at a crest and moves fast (Ihmsen et al. 2012, section 4, with the
// potentials measured on the grid instead of over SPH neighbours). For a FLUID cell with
// centre velocity u:
//   trapped air: sum over FLUID face neighbours j of |u - u_j| (1 - (u - u_j)^ . (x - x_j)^),
//     large where neighbours move into each other;
//   wave crest: where the cell touches AIR and moves outward (u^ . n >= 0.6), the divergence of
//     the outward normal n = -grad(fraction)^ times dx (a ridge of radius r cells: 1/r);
//   kinetic energy: |u|^2 / 2 per kilogram;
// each mapped to 0..1 by its range. The cell makes (rate_ta I_ta + rate_wc I_wc) I_k particles
// this step on average (the fraction by a random draw), at random points in the cell, with the
// liquid's velocity there; they are appended after the survivors (ww_advect.comp), and those
// that do not fit in the capacity are not made (PF_GPU_FLAG_WHITEWATER_FULL).
#include "effects/whitewater/whitewater.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer CellType { uint cell_type[]; };
layout(std430, binding = PF_SLOT_WW_FRACTION) readonly buffer Fraction { float fraction[]; };
layout(std430, binding = PF_SLOT_WW_OUT_POS) writeonly buffer OutPos { vec4 out_pos[]; };
layout(std430, binding = PF_SLOT_WW_OUT_VEL) writeonly buffer OutVel { vec4 out_vel[]; };
layout(std430, binding = PF_SLOT_WW_STATE) buffer State { uint state[]; };
layout(std430, binding = PF_SLOT_WW_STATUS) buffer Status { uint status[]; };
layout(location = PF_LOC_WW_CAPACITY) uniform uint u_capacity;
layout(location = PF_LOC_WW_LIMITS_A) uniform vec4 u_limits_a;  // trapped-air range, wave-crest range
layout(location = PF_LOC_WW_LIMITS_B) uniform vec4 u_limits_b;  // energy range, lifetime range
layout(location = PF_LOC_WW_RATES) uniform vec4 u_rates;        // particles per cell this step at full potential
layout(location = PF_LOC_WW_SEED) uniform uint u_seed;

// Most particles one cell makes in a step: a cap against a rate set far too high for the frame.
const int kMostPerCell = 16;

uint kind_at(ivec3 c) { return cell_inside(c) ? PF_CELL_KIND(cell_type[cell_index(c)]) : PF_CELL_SOLID; }

float fraction_at(ivec3 c) { return cell_inside(c) ? fraction[cell_index(c)] : 0.0; }

// The outward surface normal at cell c (0 where the fraction is flat).
vec3 surface_normal(ivec3 c) {
    vec3 g;
    for (int a = 0; a < 3; ++a) {
        ivec3 e = ivec3(0);
        e[a] = 1;
        g[a] = fraction_at(c + e) - fraction_at(c - e);
    }
    float len = length(g);
    return len > 1e-4 ? -g / len : vec3(0.0);
}

float potential(float value, vec2 range) { return clamp((value - range.x) / (range.y - range.x), 0.0, 1.0); }

void main() {
    int id = int(flat_id());
    if (id >= cell_total()) return;
    ivec3 c = cell_coord(id);
    if (PF_CELL_KIND(cell_type[id]) != PF_CELL_FLUID) return;
    vec3 u = centre_velocity(c);
    float energy = potential(0.5 * dot(u, u), u_limits_b.xy);
    if (energy <= 0.0) return;
    float trapped = 0.0;
    bool surface = false;
    for (int n = 0; n < 6; ++n) {
        ivec3 j = c + kNeighbours[n];
        uint kind = kind_at(j);
        surface = surface || kind == PF_CELL_AIR;
        if (kind != PF_CELL_FLUID) continue;
        vec3 du = u - centre_velocity(j);
        float len = length(du);
        // x - x_j points away from j: -kNeighbours[n]
        if (len > 1e-6) trapped += len * (1.0 - dot(du / len, -vec3(kNeighbours[n])));
    }
    float crest = 0.0;
    float speed = length(u);
    if (surface && speed > 0.0) {
        vec3 normal = surface_normal(c);
        if (dot(u / speed, normal) >= 0.6) {
            float divergence = 0.0;
            for (int a = 0; a < 3; ++a) {
                ivec3 e = ivec3(0);
                e[a] = 1;
                divergence += 0.5 * (surface_normal(c + e)[a] - surface_normal(c - e)[a]);
            }
            crest = potential(divergence, u_limits_a.zw);
        }
    }
    float mean = (u_rates.x * potential(trapped, u_limits_a.xy) + u_rates.y * crest) * energy;
    uint random = pcg_hash(uint(id) ^ pcg_hash(u_seed));
    int count = min(int(floor(mean + next_random(random))), kMostPerCell);
    if (count <= 0) return;
    uint first = atomicAdd(state[PF_WW_NEXT], uint(count));
    if (first + uint(count) > u_capacity) {
        atomicOr(status[PF_STATUS_FLAGS], PF_GPU_FLAG_WHITEWATER_FULL);
        count = int(u_capacity - min(first, u_capacity));
    }
    vec3 corner = cell_corner(c);
    float kind = kind_for(fraction[id]);
    for (int k = 0; k < count; ++k) {
        vec3 x = corner + sim.dx * vec3(next_random(random), next_random(random), next_random(random));
        float life = mix(u_limits_b.z, u_limits_b.w, next_random(random));
        out_pos[first + uint(k)] = vec4(x, life);
        out_vel[first + uint(k)] = vec4(sample_velocity(x), kind);
    }
}
