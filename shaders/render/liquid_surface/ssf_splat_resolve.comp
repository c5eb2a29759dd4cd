// Turns the compute splat images into the float textures the rest of the pipeline reads
// (the raster passes write those directly): eye depth or PF_NO_LIQUID, thickness in metres
// (half resolution). A workgroup is one PF_RENDER_TILE tile; a tile with liquid appends itself to
// the tile list (PF_SSBO_LIQUID_TILES) that SHADE and RESOLVE cover instead of the whole screen
// (the filters never spread liquid into a pixel without it, so these are the shaded tiles too).
#include "common/render.glsl"

layout(local_size_x = PF_RENDER_TILE, local_size_y = PF_RENDER_TILE) in;
layout(binding = PF_IMG_SPLAT_DEPTH, r32ui) readonly uniform uimage2D i_depth_bits;
layout(binding = PF_IMG_SPLAT_THICKNESS, r32ui) readonly uniform uimage2D i_thickness_bits;
layout(binding = PF_IMG_RAW_DEPTH, r32f) writeonly uniform image2D o_depth;
layout(binding = PF_IMG_THICKNESS, r32f) writeonly uniform image2D o_thickness;
layout(std430, binding = PF_SSBO_LIQUID_TILES) buffer LiquidTiles { uint liquid_tiles[]; };

shared uint s_liquid;  // 1 if a pixel of this tile holds liquid

void main() {
    if (gl_LocalInvocationIndex == 0u) s_liquid = 0u;
    barrier();
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(p, ivec2(rnd.viewport.xy)))) {
        uint bits = imageLoad(i_depth_bits, p).r;
        imageStore(o_depth, p, vec4(bits == PF_SPLAT_NO_DEPTH_BITS ? float(PF_NO_LIQUID) : uintBitsToFloat(bits)));
        if (bits != PF_SPLAT_NO_DEPTH_BITS) atomicOr(s_liquid, 1u);
        if (all(lessThan(p, imageSize(o_thickness))))
            imageStore(o_thickness, p, vec4(float(imageLoad(i_thickness_bits, p).r) / PF_THICKNESS_FIXED_SCALE));
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u && s_liquid != 0u) {
        uint slot = atomicAdd(liquid_tiles[1], 1u);
        // SHADE's workgroups: rows of PF_TILES_ROW (the x count GL promises), enough rows.
        atomicMax(liquid_tiles[PF_TILES_DISPATCH], min(slot + 1u, PF_TILES_ROW));
        atomicMax(liquid_tiles[PF_TILES_DISPATCH + 1], slot / PF_TILES_ROW + 1u);
        liquid_tiles[PF_TILES_HEADER + slot] = gl_WorkGroupID.x | (gl_WorkGroupID.y << 16);
    }
}
