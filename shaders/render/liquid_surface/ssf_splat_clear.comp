// Clears the compute splat images before the splat: no liquid (+inf depth bits) and zero
// thickness (half resolution), one invocation per pixel; the first also empties the liquid
// tile list (PF_SSBO_LIQUID_TILES) that this frame's splat resolve fills.
#include "common/render.glsl"

layout(local_size_x = PF_RENDER_TILE, local_size_y = PF_RENDER_TILE) in;
layout(binding = PF_IMG_SPLAT_DEPTH, r32ui) writeonly uniform uimage2D o_depth_bits;
layout(binding = PF_IMG_SPLAT_THICKNESS, r32ui) writeonly uniform uimage2D o_thickness_bits;
layout(std430, binding = PF_SSBO_LIQUID_TILES) writeonly buffer LiquidTiles { uint liquid_tiles[]; };

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p == ivec2(0)) {
        // Draw: 6 vertices (two triangles) per tile, no tiles yet, first vertex and instance 0.
        liquid_tiles[0] = 6u;
        liquid_tiles[1] = 0u;
        liquid_tiles[2] = 0u;
        liquid_tiles[3] = 0u;
        // Dispatch: no tiles yet (rows of workgroups, ssf_splat_resolve.comp).
        liquid_tiles[PF_TILES_DISPATCH] = 0u;
        liquid_tiles[PF_TILES_DISPATCH + 1] = 1u;
        liquid_tiles[PF_TILES_DISPATCH + 2] = 1u;
    }
    if (any(greaterThanEqual(p, ivec2(rnd.viewport.xy)))) return;
    imageStore(o_depth_bits, p, uvec4(PF_SPLAT_NO_DEPTH_BITS));
    if (all(lessThan(p, imageSize(o_thickness_bits)))) imageStore(o_thickness_bits, p, uvec4(0u));
}
