// Turns the compute splat images into the float textures the rest of the pipeline reads
// (the raster passes write those directly): eye depth or PF_NO_LIQUID, thickness in metres
// (half resolution).
#include "common/render.glsl"

layout(local_size_x = PF_RENDER_TILE, local_size_y = PF_RENDER_TILE) in;
layout(binding = PF_IMG_SPLAT_DEPTH, r32ui) readonly uniform uimage2D i_depth_bits;
layout(binding = PF_IMG_SPLAT_THICKNESS, r32ui) readonly uniform uimage2D i_thickness_bits;
layout(binding = PF_IMG_RAW_DEPTH, r32f) writeonly uniform image2D o_depth;
layout(binding = PF_IMG_THICKNESS, r32f) writeonly uniform image2D o_thickness;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(rnd.viewport.xy)))) return;
    uint bits = imageLoad(i_depth_bits, p).r;
    imageStore(o_depth, p, vec4(bits == PF_SPLAT_NO_DEPTH_BITS ? float(PF_NO_LIQUID) : uintBitsToFloat(bits)));
    if (all(lessThan(p, imageSize(o_thickness))))
        imageStore(o_thickness, p, vec4(float(imageLoad(i_thickness_bits, p).r) / PF_THICKNESS_FIXED_SCALE));
}
