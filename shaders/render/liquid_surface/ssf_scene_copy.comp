// SCENE_COPY pass: the engine's scene colour and depth under the viewport into the liquid
// surface's own textures, one invocation per pixel, so later passes read the scene while the
// engine's textures may be the very target they draw into. texelFetch decodes an sRGB scene to
// linear; the depth is converted once from the engine's window depth to eye depth, which every
// sphere covering the pixel compares with.
#include "common/render.glsl"

layout(local_size_x = PF_RENDER_TILE, local_size_y = PF_RENDER_TILE) in;
layout(binding = PF_TEX_SCENE_COLOR) uniform sampler2D u_engine_color;
layout(binding = PF_TEX_SCENE_DEPTH) uniform sampler2D u_engine_depth;
layout(binding = PF_IMG_SCENE_COLOR, rgba16f) writeonly uniform image2D o_color;
layout(binding = PF_IMG_SCENE_DEPTH, r32f) writeonly uniform image2D o_depth;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(rnd.viewport.xy)))) return;
    ivec2 engine = p + rnd.target.xy;
    imageStore(o_color, p, texelFetch(u_engine_color, engine, 0));
    if (rnd.sphere.w > 0.5) {
        float window = texelFetch(u_engine_depth, engine, 0).r;
        imageStore(o_depth, p, vec4(eye_depth_of_window(pixel_ndc(vec2(p) + 0.5), window)));
    }
}
