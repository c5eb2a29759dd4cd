// RESOLVE pass: copies the shaded liquid into the engine's target, over a full-screen triangle
// (render/fullscreen.vert) or the liquid's tiles (render/liquid_surface/ssf_resolve_tiles.vert)
// in the engine's viewport. Pixels without liquid are discarded, so the engine's framebuffer
// stays untouched there; liquid pixels write colour and, through gl_FragDepth with the depth
// test ALWAYS, the liquid's depth in the engine's convention (where the target has depth).
#include "common/render.glsl"

layout(binding = PF_TEX_SHADED_COLOR) uniform sampler2D u_color;
layout(binding = PF_TEX_SHADED_DEPTH) uniform sampler2D u_depth;
layout(location = 0) out vec4 o_color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) - rnd.target.xy;
    vec4 color = texelFetch(u_color, p, 0);
    if (color.a == 0.0) discard;
    o_color = vec4(color.rgb, 1.0);
    gl_FragDepth = texelFetch(u_depth, p, 0).r;
}
