// Emitters, once per step before the first substep: invocation i writes new particle i of the
// step's emission into slot live + i (live: the count record's word, which emit_commit then
// raises), with the emitter's velocity (a disc's plus what gravity added in flight, below), at
// the next point of the emitter's low-discrepancy sequence mapped into its shape by
// volume-preserving maps, so the particles fill the shape evenly (rate / volume particles per
// m^3 and s), as a fill does, not in random clumps. Slots at or
// beyond the capacity are skipped (emit_commit flags it). New particles start as plain PIC
// under APIC (C = 0), like those of pf_add_particles.
#include "common/sim.glsl"
#include "common/shapes.glsl"
#include "common/hash.glsl"
#include "effects/emitters/emitter_records.h"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) writeonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) writeonly buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_EMITTERS) readonly buffer Emitters { vec4 emitters[]; };
layout(std430, binding = PF_SLOT_PARTICLE_COUNT) readonly buffer Count { uint count_record[]; };
#if PF_APIC
layout(std430, binding = PF_SLOT_PARTICLE_AFFINE) writeonly buffer Affine { vec4 affine[]; };
#endif
layout(location = PF_LOC_EFFECT_COUNT) uniform uint u_emitters;
layout(location = PF_LOC_EMIT_TOTAL) uniform uint u_total;
layout(location = PF_LOC_EMIT_SEED) uniform uint u_seed;
layout(location = PF_LOC_EMIT_CAPACITY) uniform uint u_capacity;

const float kTwoPi = 6.28318530718;

void main() {
    uint i = flat_id();
    if (i >= u_total) return;
    uint slot = count_record[PF_COUNT_LIVE] + i;
    if (slot >= u_capacity) return;
    // The emitter whose range [first, first + n) holds i (unsigned wrap-around rejects i < first).
    uint k = 0u, n = 0u;
    for (uint e = 0u; e < u_emitters; ++e) {
        uvec3 range = floatBitsToUint(emitters[PF_EMITTER_VEC4S * e + 4u].xyz);
        if (i - range.x < range.y) {
            k = e;
            n = range.z + (i - range.x);
            break;
        }
    }
    vec4 ps = emitters[PF_EMITTER_VEC4S * k];
    vec4 q = emitters[PF_EMITTER_VEC4S * k + 1u];
    vec4 size = emitters[PF_EMITTER_VEC4S * k + 2u];
    vec3 v = emitters[PF_EMITTER_VEC4S * k + 3u].xyz;
    float frame_dt = emitters[PF_EMITTER_VEC4S * k + 3u].w;
    // Each emitter's sequence has its own fixed shift, so two emitters do not stack their points.
    vec3 r = r3_point(n, uvec3(pcg_hash(u_seed ^ k), pcg_hash(u_seed ^ k ^ 0x5bd1e995u), pcg_hash(u_seed + k)));
    int shape = int(ps.w);
    vec3 p;
    vec3 along = vec3(0.0);
    if (shape == PF_EMITTER_BOX_ID) {
        p = (2.0 * r - 1.0) * size.xyz;
    } else if (shape == PF_EMITTER_SPHERE_ID) {
        // Uniform in the ball: radius ~ cbrt(u), direction uniform on the sphere.
        float cos_t = 2.0 * r.y - 1.0, sin_t = sqrt(max(0.0, 1.0 - cos_t * cos_t));
        float phi = kTwoPi * r.z;
        p = size.x * pow(r.x, 1.0 / 3.0) * vec3(sin_t * cos(phi), cos_t, sin_t * sin(phi));
    } else {
        // Uniform on the disc (local xz plane), then where it would be had it left the disc tau
        // ago, tau spread over one frame, in free flight (the body acceleration acting): the
        // frame's particles join the previous frame's, which the step accelerated the same way,
        // so even a slow pour leaves as an unbroken jet.
        float rad = size.x * sqrt(r.x), phi = kTwoPi * r.y;
        p = vec3(rad * cos(phi), 0.0, rad * sin(phi));
        float tau = frame_dt * r.z;
        vec3 g = sim.gravity.xyz;
        vec3 v_tau = v + g * tau;
        along = v * tau + 0.5 * g * (tau * tau);
        // A free jet keeps its flux: as its speed grows its section shrinks by |v0| / |v|, so a
        // point rad from the axis is rad sqrt(|v0| / |v|) from it tau later, moving inwards at
        // half the stretch rate d|v|/ds = (v . g) / |v|^2 times that distance: the jet leaves
        // divergence-free, and the projection does not pull the top of each frame's batch into
        // the stretching stream below it (which left gaps between the frames' batches). Only
        // where gravity has sped the jet up: one it slows is left as it leaves the disc, since its
        // widening would grow without bound toward the top of its flight.
        float s0 = length(v), s1 = length(v_tau);
        if (s0 > 0.0 && s1 > s0 && dot(v_tau, g) > 0.0) {
            p *= sqrt(s0 / s1);
            v_tau -= (0.5 * dot(v_tau, g) / (s1 * s1)) * quat_rotate(q, p);
        }
        v = v_tau;
    }
    vec3 x = ps.xyz + quat_rotate(q, p) + along;
    pos[slot] = vec4(keep_in_domain(x), 0.0);
    vel[slot] = vec4(v, 0.0);
#if PF_APIC
    affine[3u * slot] = vec4(0.0);
    affine[3u * slot + 1u] = vec4(0.0);
    affine[3u * slot + 2u] = vec4(0.0);
#endif
}
