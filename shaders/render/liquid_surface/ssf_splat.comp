// THICKNESS pass, compute path: one invocation per particle walks the pixels of its sphere's
// projected quad and, for each pixel whose centre ray hits the sphere (the same test the
// raster sprites make per fragment), keeps the nearest eye depth with an atomic minimum on its
// float bits (positive floats order like their bits); then it walks the quad's texels of the
// half-resolution thickness image the same way and adds the chord length there in fixed point.
// One invocation for both, where the raster path draws the spheres twice. Compute instead of
// raster because fragment work is slow on compute-heavy GPUs (H100).
#include "common/slots.h"
#include "common/ssf_sphere.glsl"
#include "common/ssf_spray.glsl"

layout(local_size_x = PF_SPLAT_WORKGROUP) in;
layout(std430, binding = PF_SSBO_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(binding = PF_IMG_SPLAT_DEPTH, r32ui) uniform coherent uimage2D io_depth_bits;
layout(binding = PF_IMG_SPLAT_THICKNESS, r32ui) uniform coherent uimage2D io_thickness_bits;
layout(std430, binding = PF_SSBO_PARTICLE_COUNT) readonly buffer Count { uint count_record[]; };
layout(std430, binding = PF_SSBO_PARTICLE_ORDER) readonly buffer Order { uint order[]; };
layout(location = PF_LOC_SPLAT_COUNT) uniform uint u_count;  // slots covered by the dispatch
layout(location = PF_LOC_SPLAT_ORDERED) uniform uint u_ordered;  // 1: invocation k splats order[k]

// Own-texture pixel of an eye-space point (may lie outside the texture).
vec2 eye_to_pixel(vec3 p) {
    vec4 clip = rnd.proj * vec4(p, 1.0);
    vec2 ndc = clip.xy / clip.w;
    return (vec2(ndc.x, ndc.y * rnd.surface.w) + 1.0) * 0.5 * rnd.viewport.xy;
}

void main() {
    uint k = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * uint(PF_SPLAT_WORKGROUP);
    uint live = min(u_count, count_record[PF_COUNT_LIVE]);
    if (k >= live) return;
    uint i = u_ordered != 0u ? order[k] : k;
    if (i >= live) return;
    vec3 position = pos[i].xyz;
    float radius = particle_radius(position);
    vec3 center;
    if (!sphere_visible(position, radius, center)) return;
    vec4 sphere = vec4(center, radius);
    float half_size;
    vec3 t, b;
    sphere_quad(sphere, half_size, t, b);
    // Pixel bounds of the quad's corners (all in front of the camera: the quad is culled
    // otherwise, as the raster sprites are).
    vec2 lo = vec2(1e30), hi = vec2(-1e30);
    for (int k = 0; k < 4; ++k) {
        vec2 corner = vec2(float(k & 1), float(k >> 1)) * 2.0 - 1.0;
        vec3 p = center + half_size * (corner.x * t + corner.y * b);
        if (!render_orthographic() && p.z >= 0.0) return;
        vec2 px = eye_to_pixel(p);
        lo = min(lo, px);
        hi = max(hi, px);
    }
    ivec2 first = max(ivec2(floor(lo - 0.5)), ivec2(0));
    ivec2 last = min(ivec2(ceil(hi + 0.5)), ivec2(rnd.viewport.xy) - 1);
    for (int y = first.y; y <= last.y; ++y) {
        for (int x = first.x; x <= last.x; ++x) {
            float depth;
            if (sphere_depth_at(vec2(x, y) + 0.5, sphere, depth))
                imageAtomicMin(io_depth_bits, ivec2(x, y), floatBitsToUint(depth));
        }
    }
    // Thickness texel t is centred on full-resolution point 2 t + 1 (thickness_frag).
    ivec2 t_first = max(ivec2(floor((lo - 1.0) * 0.5)), ivec2(0));
    ivec2 t_last = min(ivec2(ceil((hi - 1.0) * 0.5)), imageSize(io_thickness_bits) - 1);
    for (int y = t_first.y; y <= t_last.y; ++y) {
        for (int x = t_first.x; x <= t_last.x; ++x) {
            float chord = sphere_chord_at(thickness_frag(vec2(x, y) + 0.5), sphere);
            if (chord > 0.0) imageAtomicAdd(io_thickness_bits, ivec2(x, y), uint(chord * PF_THICKNESS_FIXED_SCALE + 0.5));
        }
    }
}
