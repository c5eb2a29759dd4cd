// SMOOTH pass, raster path: one 1D filter pass (render/liquid_surface/ssf_filter.glsl) over the liquid
// depth, one fragment per pixel of a full-screen triangle into an R32F attachment.
#include "common/render.glsl"
#include "render/liquid_surface/ssf_filter.glsl"

layout(location = PF_LOC_SMOOTH_DIRECTION) uniform ivec2 u_direction;
layout(location = 0) out float o_depth;

void main() { o_depth = ssf_filter(ivec2(gl_FragCoord.xy), u_direction); }
