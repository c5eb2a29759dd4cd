// The engine's scene depth as seen by the liquid passes: eye depth of the nearest opaque
// surface per pixel, as the scene-copy pass converted it once
// (render/liquid_surface/ssf_scene_copy.comp).
#include "common/render.glsl"

layout(binding = PF_TEX_SCENE_DEPTH) uniform sampler2D u_scene_depth;

// kFarAway where no scene depth texture was given.
float scene_eye_depth(ivec2 p) {
    if (rnd.sphere.w < 0.5) return kFarAway;
    return texelFetch(u_scene_depth, min(p, ivec2(rnd.viewport.xy) - 1), 0).r;
}

// The point of the full-resolution own textures (texel index + 0.5 units) at the centre of
// thickness texel `t`: the thickness has half the resolution (it only tints the refraction).
vec2 thickness_frag(vec2 t) { return 2.0 * t; }
