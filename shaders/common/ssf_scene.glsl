// The engine's scene depth as seen by the liquid passes: eye depth of the nearest opaque
// surface per pixel (the copy made in the scene-copy pass, in the engine's convention).
#include "common/render.glsl"

layout(binding = PF_TEX_SCENE_DEPTH) uniform sampler2D u_scene_depth;

// kFarAway where no scene depth texture was given.
float scene_eye_depth(ivec2 p) {
    if (rnd.sphere.w < 0.5) return kFarAway;
    return eye_depth_of_window(pixel_ndc(vec2(p) + 0.5), texelFetch(u_scene_depth, p, 0).r);
}
