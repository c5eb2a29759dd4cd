// SHADE pass, raster path: render/liquid_surface/ssf_shade.glsl per fragment of a full-screen triangle into
// the liquid colour (attachment 0) and liquid window depth (attachment 1).
#include "common/render.glsl"
#include "render/liquid_surface/ssf_shade.glsl"

layout(location = 0) out vec4 o_color;
layout(location = 1) out float o_depth;

void main() { ssf_shade(ivec2(gl_FragCoord.xy), o_color, o_depth); }
