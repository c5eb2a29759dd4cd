// Whitewater sprites: a soft white disc lit as the front of a small sphere, hidden behind the
// scene (its eye depth from the liquid surface's scene copy) and, behind the liquid's surface
// (the depth the liquid surface layer shaded), seen through it: tinted and faded by the
// liquid's Beer-Lambert absorption over the depth below the surface. Premultiplied alpha,
// faded over the last half second of a particle's life.
#include "common/ssf_scene.glsl"

layout(binding = PF_TEX_LIQUID_DEPTH) uniform sampler2D u_liquid_depth;

layout(location = PF_VARY_THROUGH) in vec2 v_corner;
layout(location = PF_VARY_CENTER) flat in vec4 v_center;
layout(location = PF_VARY_VALUE) flat in vec2 v_kind_life;
layout(location = 0) out vec4 o_color;

void main() {
    float r2 = dot(v_corner, v_corner);
    if (r2 >= 1.0) discard;
    ivec2 p = ivec2(gl_FragCoord.xy) - rnd.target.xy;
    vec3 normal_eye = vec3(v_corner, sqrt(1.0 - r2));
    float depth = -v_center.z - v_center.w * normal_eye.z;
    if (depth > scene_eye_depth(p)) discard;
    vec3 normal = mat3(rnd.inv_view) * normal_eye;
    vec3 color = vec3(0.8 + 0.2 * max(dot(normal, rnd.light.xyz), 0.0));
    float alpha = rnd.whitewater.y * (1.0 - r2) * clamp(v_kind_life.y * 2.0, 0.0, 1.0);
    float surface = texelFetch(u_liquid_depth, p, 0).r;
    if (surface > PF_NO_LIQUID && depth > surface) {
        vec3 through = exp(-rnd.absorption.rgb * (depth - surface));
        color *= through;
        alpha *= (through.r + through.g + through.b) / 3.0;
    }
    o_color = vec4(color * alpha, alpha);
}
