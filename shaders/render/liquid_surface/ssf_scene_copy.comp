// SCENE_COPY pass: the engine's scene colour and depth under the viewport into the liquid
// surface's own textures, one invocation per pixel, so later passes read the scene while the
// engine's textures may be the very target they draw into. texelFetch decodes an sRGB scene to
// linear; the depth is converted once from the engine's window depth to eye depth, which every
// sphere covering the pixel compares with. A workgroup is one PF_RENDER_TILE tile and also
// stores the tile's nearest eye depth: the splat skips the per-pixel comparison for a sphere
// that lies wholly in front of its tiles' nearest scene surface.
#include "common/render.glsl"

layout(local_size_x = PF_RENDER_TILE, local_size_y = PF_RENDER_TILE) in;
layout(binding = PF_TEX_SCENE_COLOR) uniform sampler2D u_engine_color;
layout(binding = PF_TEX_SCENE_DEPTH) uniform sampler2D u_engine_depth;
layout(binding = PF_IMG_SCENE_COLOR, rgba16f) writeonly uniform image2D o_color;
layout(binding = PF_IMG_SCENE_DEPTH, r32f) writeonly uniform image2D o_depth;
layout(binding = PF_IMG_SCENE_DEPTH_TILES, r32f) writeonly uniform image2D o_depth_tiles;

shared uint s_nearest;  // float bits of the tile's nearest eye depth (positive: ordered like floats)

void main() {
    bool scene_depth = rnd.sphere.w > 0.5;
    if (gl_LocalInvocationIndex == 0u) s_nearest = floatBitsToUint(kFarAway);
    barrier();
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(p, ivec2(rnd.viewport.xy)))) {
        ivec2 engine = p + rnd.target.xy;
        imageStore(o_color, p, texelFetch(u_engine_color, engine, 0));
        if (scene_depth) {
            float window = texelFetch(u_engine_depth, engine, 0).r;
            float eye = eye_depth_of_window(pixel_ndc(vec2(p) + 0.5), window);
            imageStore(o_depth, p, vec4(eye));
            atomicMin(s_nearest, floatBitsToUint(eye));
        }
    }
    barrier();
    if (scene_depth && gl_LocalInvocationIndex == 0u)
        imageStore(o_depth_tiles, ivec2(gl_WorkGroupID.xy), vec4(uintBitsToFloat(s_nearest)));
}
