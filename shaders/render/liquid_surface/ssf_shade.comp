// SHADE pass, compute path: render/liquid_surface/ssf_shade.glsl per pixel into the liquid colour (rgba16f)
// and liquid window depth (r32f) images, over the tiles holding liquid only: workgroup w (counted
// row by row) shades tile w of the splat resolve's list (PF_SSBO_LIQUID_TILES), dispatched
// indirectly; the last row's spare workgroups do nothing. The RESOLVE reads these images on those
// tiles only.
#include "common/render.glsl"
#include "render/liquid_surface/ssf_shade.glsl"

layout(local_size_x = PF_RENDER_TILE, local_size_y = PF_RENDER_TILE) in;
layout(binding = PF_IMG_SHADE_COLOR, rgba16f) writeonly uniform image2D o_color;
layout(binding = PF_IMG_SHADE_DEPTH, r32f) writeonly uniform image2D o_depth;
layout(std430, binding = PF_SSBO_LIQUID_TILES) readonly buffer LiquidTiles { uint liquid_tiles[]; };

void main() {
    uint w = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    if (w >= liquid_tiles[1]) return;
    uint tile = liquid_tiles[PF_TILES_HEADER + w];
    ivec2 p = ivec2(tile & 0xFFFFu, tile >> 16) * PF_RENDER_TILE + ivec2(gl_LocalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(rnd.viewport.xy)))) return;
    vec4 color;
    float window;
    ssf_shade(p, color, window);
    imageStore(o_color, p, color);
    imageStore(o_depth, p, vec4(window));
}
