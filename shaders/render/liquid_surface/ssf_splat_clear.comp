// Clears the compute splat images before the splat: no liquid (+inf depth bits) and zero
// thickness (half resolution), one invocation per pixel.
#include "common/render.glsl"

layout(local_size_x = PF_RENDER_TILE, local_size_y = PF_RENDER_TILE) in;
layout(binding = PF_IMG_SPLAT_DEPTH, r32ui) writeonly uniform uimage2D o_depth_bits;
layout(binding = PF_IMG_SPLAT_THICKNESS, r32ui) writeonly uniform uimage2D o_thickness_bits;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(rnd.viewport.xy)))) return;
    imageStore(o_depth_bits, p, uvec4(PF_SPLAT_NO_DEPTH_BITS));
    if (all(lessThan(p, imageSize(o_thickness_bits)))) imageStore(o_thickness_bits, p, uvec4(0u));
}
