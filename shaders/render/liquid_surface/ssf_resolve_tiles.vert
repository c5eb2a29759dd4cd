// RESOLVE pass, compute path: two triangles per PF_RENDER_TILE tile of the list the splat
// resolve made (PF_SSBO_LIQUID_TILES), one instance per tile, so ssf_resolve.frag runs on the
// liquid's tiles only. Own texel corners go to NDC as the splat projects (pixel_ndc: the engine's
// clip origin included); z = 0.5 w lies inside the clip range of both glClipControl depth modes.
#include "common/render.glsl"

layout(std430, binding = PF_SSBO_LIQUID_TILES) readonly buffer LiquidTiles { uint liquid_tiles[]; };

void main() {
    uint tile = liquid_tiles[PF_TILES_HEADER + uint(gl_InstanceID)];
    // Corners of triangles (0,0) (1,0) (0,1) and (0,1) (1,0) (1,1).
    const ivec2 corners[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1));
    ivec2 corner = (ivec2(tile & 0xFFFFu, tile >> 16) + corners[gl_VertexID]) * PF_RENDER_TILE;
    vec2 texel = min(vec2(corner), rnd.viewport.xy);
    gl_Position = vec4(pixel_ndc(texel), 0.5, 1.0);
}
