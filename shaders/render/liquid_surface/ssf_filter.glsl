// Depth smoothing filters of the screen-space liquid, one 1D pass along `dir` ((1,0) or
// (0,1)); the renderer alternates directions (separable approximation of the 2D filter) and
// repeats them filter_iterations times. PF_SSF_FILTER picks the filter at compile time.
// Pixels without liquid stay without liquid; liquid never spreads into them.
#include "common/render.glsl"
#include "render/liquid_surface/ssf_depth.glsl"

#ifndef PF_SSF_FILTER
#error "PF_SSF_FILTER must be defined (permutations.inc)"
#endif

// Half-width in pixels of the filter at eye depth `depth`: filter_world_radius projected, between
// one pixel and filter_radius.
int filter_radius(float depth) {
    float pixels = rnd.filter_size.x * rnd.filter_size.y / (render_orthographic() ? 1.0 : depth);
    return int(clamp(pixels, 1.0, rnd.sphere.y) + 0.5);
}

// Spatial Gaussian with sigma = radius / 2: the outermost taps still weigh exp(-2).
float spatial_weight(int i, int radius) {
    float sigma = 0.5 * float(radius);
    return exp(-float(i * i) / (2.0 * sigma * sigma));
}

#if PF_SSF_FILTER == PF_SSF_FILTER_BILATERAL_ID

// Bilateral filter (Green, GDC 2010; the original's): each tap weighs its pixel distance
// times its depth difference to the centre, both Gaussian; the range sigma is half the
// filter depth range, so a tap one depth range away still weighs exp(-2) of a tap on the
// centre's surface. Background taps are skipped.
float ssf_filter(ivec2 p, ivec2 dir) {
    float center = liquid_depth(p);
    if (!is_liquid(center)) return center;
    float range_sigma = 0.5 * rnd.sphere.z;
    int radius = filter_radius(center);
    float sum = center, weights = 1.0;
    for (int i = 1; i <= radius; ++i) {
        float ws = spatial_weight(i, radius);
        for (int side = -1; side <= 1; side += 2) {
            float z = liquid_depth(p + side * i * dir);
            if (!is_liquid(z)) continue;
            float dz = (z - center) / range_sigma;
            float w = ws * exp(-0.5 * dz * dz);
            sum += w * z;
            weights += w;
        }
    }
    return sum / weights;
}

#elif PF_SSF_FILTER == PF_SSF_FILTER_NARROW_RANGE_ID

// Narrow-range filter (Truong & Yuksel, I3D 2018): a plain Gaussian, but only over depths
// within a narrow range around the centre's surface. Walking outwards from the centre on
// each side:
//  - a tap farther than the range (another surface behind, or background) is dropped, and so
//    is its mirror tap on the other side, which keeps the kernel symmetric: at a silhouette
//    the surface is not dragged towards the side that still has liquid;
//  - a tap nearer than the range is clamped to one particle radius in front of the centre,
//    so a surface in front pulls the centre forward a little instead of flattening into it;
//  - a tap inside the range widens that side's range around itself, so the range follows a
//    sloped surface outwards instead of cutting it off.
// The range half-width is the filter depth range.
float ssf_filter(ivec2 p, ivec2 dir) {
    float center = liquid_depth(p);
    if (!is_liquid(center)) return center;
    float range = rnd.sphere.z;
    float clamped = center - rnd.sphere.x;
    vec2 lower = vec2(center - range), upper = vec2(center + range);  // x: -dir side, y: +dir side
    int radius = filter_radius(center);
    float sum = center, weights = 1.0;
    for (int i = 1; i <= radius; ++i) {
        vec2 z = vec2(liquid_depth(p - i * dir), liquid_depth(p + i * dir));
        bvec2 behind = bvec2(!is_liquid(z.x) || z.x > upper.x, !is_liquid(z.y) || z.y > upper.y);
        for (int s = 0; s < 2; ++s) {
            if (behind[s]) continue;
            if (z[s] < lower[s]) {
                z[s] = clamped;
            } else {
                lower[s] = min(lower[s], z[s] - range);
                upper[s] = max(upper[s], z[s] + range);
            }
        }
        if (behind.x || behind.y) continue;
        float ws = spatial_weight(i, radius);
        sum += ws * (z.x + z.y);
        weights += 2.0 * ws;
    }
    return sum / weights;
}

#else
#error "unknown PF_SSF_FILTER"
#endif
