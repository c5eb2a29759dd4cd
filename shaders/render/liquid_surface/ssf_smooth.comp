// SMOOTH pass, compute path: one 1D filter pass (render/liquid_surface/ssf_filter.glsl) over the liquid
// depth, one invocation per pixel, written to an r32f image.
#include "common/render.glsl"
#include "render/liquid_surface/ssf_filter.glsl"

layout(local_size_x = PF_RENDER_TILE, local_size_y = PF_RENDER_TILE) in;
layout(binding = PF_IMG_SMOOTH_OUT, r32f) writeonly uniform image2D o_depth;
layout(location = PF_LOC_SMOOTH_DIRECTION) uniform ivec2 u_direction;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(rnd.viewport.xy)))) return;
    imageStore(o_depth, p, vec4(ssf_filter(p, u_direction)));
}
