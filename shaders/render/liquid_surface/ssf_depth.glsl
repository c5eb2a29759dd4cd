// The liquid's linear eye depth (PF_NO_LIQUID where there is none), read by the smoothing
// filters and the shading. Pixels outside the viewport read as no liquid.
#include "common/render.glsl"

layout(binding = PF_TEX_LIQUID_DEPTH) uniform sampler2D u_liquid_depth;

bool is_liquid(float depth) { return depth > PF_NO_LIQUID; }

float liquid_depth(ivec2 p) {
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, ivec2(rnd.viewport.xy)))) return PF_NO_LIQUID;
    return texelFetch(u_liquid_depth, p, 0).r;
}
