// THICKNESS pass, compute path: one invocation per particle walks the pixels of its sphere's
// projected quad and, for each pixel whose centre ray hits the sphere (the same test the
// raster sprites make per fragment), keeps the nearest eye depth with an atomic minimum on its
// float bits (positive floats order like their bits); then it walks the quad's texels of the
// half-resolution thickness image the same way and adds the chord length there in fixed point.
// One invocation for both, where the raster path draws the spheres twice. Compute instead of
// raster because fragment work is slow on compute-heavy GPUs (H100). With PF_SPLAT_SHARED 1 (the
// renderer's choice where spheres span several texels on screen) the thickness is summed per
// workgroup in shared memory first when its spheres' texels fit there (in the P2G's tile order
// they overlap): one global atomic per texel instead of one per sphere and texel, the same
// integer sums. For smaller spheres the workgroup's barriers and shared memory cost more than the
// atomics they save.
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
#ifndef PF_SPLAT_SHARED
#error "PF_SPLAT_SHARED must be defined (permutations.inc)"
#endif
layout(binding = PF_TEX_SCENE_DEPTH_TILES) uniform sampler2D u_scene_depth_tiles;

// Tiles a sphere's pixels may span before the test below is not worth its reads.
const int kMaxSceneTiles = 16;

// Whether the engine's scene can hide any part of a sphere whose farthest eye depth is `back`
// over pixels first..last (and last + 1, where the thickness samples may fall): not when every
// tile there has its nearest scene surface behind it (ssf_scene_copy.comp). Then the pixels need
// not read the scene depth.
bool scene_may_hide(float back, ivec2 first, ivec2 last) {
    if (rnd.sphere.w < 0.5) return false;  // no scene depth
    ivec2 t0 = first / PF_RENDER_TILE;
    ivec2 t1 = min((last + 1) / PF_RENDER_TILE, textureSize(u_scene_depth_tiles, 0) - 1);
    if ((t1.x - t0.x + 1) * (t1.y - t0.y + 1) > kMaxSceneTiles) return true;
    for (int y = t0.y; y <= t1.y; ++y)
        for (int x = t0.x; x <= t1.x; ++x)
            if (texelFetch(u_scene_depth_tiles, ivec2(x, y), 0).r <= back) return true;
    return false;
}

// The scene's eye depth at pixel p when it matters, else kFarAway (which it exceeds).
float scene_at(ivec2 p, bool matters) { return matters ? scene_eye_depth(p) : kFarAway; }

// Pixels of slack around a quad's bounds.
const float kEdge = 1.0e-3;

#if PF_SPLAT_SHARED
// Thickness texels a workgroup may sum in shared memory (the rectangle its spheres' texels span).
const int kSharedTexels = 1024;
shared uint s_thickness[kSharedTexels];
shared int s_lo_x, s_lo_y, s_hi_x, s_hi_y;  // the workgroup's thickness texels
#endif

// Own-texture pixel of an eye-space point (may lie outside the texture).
vec2 eye_to_pixel(vec3 p) {
    vec4 clip = rnd.proj * vec4(p, 1.0);
    vec2 ndc = clip.xy / clip.w;
    return (vec2(ndc.x, ndc.y * rnd.surface.w) + 1.0) * 0.5 * rnd.viewport.xy;
}

// The thickness texels whose centres lie in pixel bounds lo..hi: texel t is centred on
// full-resolution point 2 t + 1 (thickness_frag).
void thickness_texels(vec2 lo, vec2 hi, out ivec2 t_first, out ivec2 t_last) {
    t_first = max(ivec2(ceil((lo - 1.0 - kEdge) * 0.5)), ivec2(0));
    t_last = min(ivec2(floor((hi - 1.0 + kEdge) * 0.5)), imageSize(io_thickness_bits) - 1);
}

// The sphere of slot k of the dispatch, and its pixel bounds; false when it draws nothing.
bool splat_sphere(uint k, out vec3 position, out vec4 sphere, out vec2 lo, out vec2 hi) {
    position = vec3(0.0);
    sphere = vec4(0.0);
    lo = hi = vec2(0.0);
    uint live = min(u_count, count_record[PF_COUNT_LIVE]);
    if (k >= live) return false;
    uint i = u_ordered != 0u ? order[k] : k;
    if (i >= live) return false;
    position = pos[i].xyz;
    float radius = particle_radius(position);
    vec3 center;
    if (!sphere_visible(position, radius, center)) return false;
    sphere = vec4(center, radius);
    float half_size;
    vec3 t, b;
    sphere_quad(sphere, half_size, t, b);
    // Pixel bounds of the quad's corners (all in front of the camera: the quad is culled
    // otherwise, as the raster sprites are).
    lo = vec2(1e30);
    hi = vec2(-1e30);
    for (int c = 0; c < 4; ++c) {
        vec2 corner = vec2(float(c & 1), float(c >> 1)) * 2.0 - 1.0;
        vec3 p = center + half_size * (corner.x * t + corner.y * b);
        if (!render_orthographic() && p.z >= 0.0) return false;
        vec2 px = eye_to_pixel(p);
        lo = min(lo, px);
        hi = max(hi, px);
    }
    return true;
}

void main() {
    uint k = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * uint(PF_SPLAT_WORKGROUP);
    vec3 position;
    vec4 sphere;
    vec2 lo, hi;
    bool drawn = splat_sphere(k, position, sphere, lo, hi);
#if !PF_SPLAT_SHARED
    if (!drawn) return;  // no barriers to meet
#endif
    // Only pixels whose centre (index + 0.5) lies in the quad's bounds can hit the sphere, as only
    // those are the raster sprite's fragments; kEdge absorbs the two paths' rounding of the corners.
    ivec2 first = max(ivec2(ceil(lo - 0.5 - kEdge)), ivec2(0));
    ivec2 last = min(ivec2(floor(hi - 0.5 + kEdge)), ivec2(rnd.viewport.xy) - 1);
#if PF_SPLAT_SHARED
    // The workgroup's thickness texels, before the depth walk (the variant without shared sums
    // finds them after it, with fewer values live across the walk).
    ivec2 t_first, t_last;
    thickness_texels(lo, hi, t_first, t_last);
    if (!drawn) {  // no pixels, no texels
        last = first - 1;
        t_last = t_first - 1;
    }
    if (gl_LocalInvocationIndex == 0u) {
        s_lo_x = s_lo_y = 0x7FFFFFFF;  // texels are >= 0: no sphere's texels leave span 0
        s_hi_x = s_hi_y = -1;
    }
    barrier();
    if (all(lessThanEqual(t_first, t_last))) {
        atomicMin(s_lo_x, t_first.x);
        atomicMin(s_lo_y, t_first.y);
        atomicMax(s_hi_x, t_last.x);
        atomicMax(s_hi_y, t_last.y);
    }
#endif

    // The sphere's farthest point lies at eye depth -center.z + radius.
    bool scene = drawn && scene_may_hide(-sphere.z + sphere.w, first, last);
    for (int y = first.y; y <= last.y; ++y) {
        for (int x = first.x; x <= last.x; ++x) {
            float front, back, per_length;
            if (sphere_span(vec2(x, y) + 0.5, sphere, front, back, per_length) &&
                span_front_visible(front, scene_at(ivec2(x, y), scene)))
                imageAtomicMin(io_depth_bits, ivec2(x, y), floatBitsToUint(front));
        }
    }

#if PF_SPLAT_SHARED
    barrier();  // the workgroup's texel bounds
    ivec2 base = ivec2(s_lo_x, s_lo_y);
    ivec2 span = max(ivec2(s_hi_x, s_hi_y) - base + 1, ivec2(0));  // 0 when no sphere has texels
    int texels = span.x * span.y;
    bool shared_sum = span.x <= kSharedTexels && span.y <= kSharedTexels && texels <= kSharedTexels;
    if (shared_sum) {
        for (int w = int(gl_LocalInvocationIndex); w < texels; w += PF_SPLAT_WORKGROUP) s_thickness[w] = 0u;
    }
    barrier();
#else
    const bool shared_sum = false;
    ivec2 t_first, t_last;
    thickness_texels(lo, hi, t_first, t_last);
#endif
    for (int y = t_first.y; y <= t_last.y; ++y) {
        for (int x = t_first.x; x <= t_last.x; ++x) {
            vec2 frag = thickness_frag(vec2(x, y) + 0.5);
            float front, back, per_length;
            if (!sphere_span(frag, sphere, front, back, per_length)) continue;
            float chord = span_chord(front, back, per_length, scene_at(ivec2(frag), scene));
            if (chord <= 0.0) continue;
            uint fixed_point = uint(chord * PF_THICKNESS_FIXED_SCALE + 0.5);
#if PF_SPLAT_SHARED
            if (shared_sum) {
                atomicAdd(s_thickness[(y - base.y) * span.x + (x - base.x)], fixed_point);
                continue;
            }
#endif
            imageAtomicAdd(io_thickness_bits, ivec2(x, y), fixed_point);
        }
    }
#if PF_SPLAT_SHARED
    if (!shared_sum) return;  // uniform across the workgroup
    barrier();
    for (int w = int(gl_LocalInvocationIndex); w < texels; w += PF_SPLAT_WORKGROUP) {
        uint sum = s_thickness[w];
        if (sum != 0u) imageAtomicAdd(io_thickness_bits, base + ivec2(w % span.x, w / span.x), sum);
    }
#endif
}
