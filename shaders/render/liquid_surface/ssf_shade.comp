// SHADE pass, compute path: render/liquid_surface/ssf_shade.glsl per pixel into the liquid colour (rgba16f)
// and liquid window depth (r32f) images.
#include "common/render.glsl"
#include "render/liquid_surface/ssf_shade.glsl"

layout(local_size_x = PF_RENDER_TILE, local_size_y = PF_RENDER_TILE) in;
layout(binding = PF_IMG_SHADE_COLOR, rgba16f) writeonly uniform image2D o_color;
layout(binding = PF_IMG_SHADE_DEPTH, r32f) writeonly uniform image2D o_depth;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(rnd.viewport.xy)))) return;
    vec4 color;
    float window;
    ssf_shade(p, color, window);
    imageStore(o_color, p, color);
    imageStore(o_depth, p, vec4(window));
}
