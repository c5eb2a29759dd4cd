// Debug view: a shaded sphere per particle, coloured by the value the vertex shader picked
// (mapped from range[0]..range[1] onto color_low..color_high), lit by a light at the eye.
// Writes the sphere's true depth in the engine's convention; the engine's depth test
// (LESS, or GREATER for reversed-Z) hides it behind the scene.
#include "common/render.glsl"

layout(location = PF_VARY_THROUGH) in vec3 v_through;
layout(location = PF_VARY_CENTER) flat in vec4 v_sphere;
layout(location = PF_VARY_VALUE) flat in float v_value;
layout(location = 0) out vec4 o_color;

void main() {
    vec3 origin, dir;
    camera_ray(v_through, origin, dir);
    float t_front, t_back;
    if (!sphere_hit(origin, dir, v_sphere.xyz, v_sphere.w, t_front, t_back)) discard;
    vec3 hit = origin + t_front * dir;
    if (-hit.z < rnd.planes.x || -hit.z > rnd.planes.y) discard;
    vec3 normal = (hit - v_sphere.xyz) / v_sphere.w;
    float t = clamp((v_value - rnd.color_low.w) / (rnd.color_high.w - rnd.color_low.w), 0.0, 1.0);
    vec3 base = rnd.modes.x == PF_COLOR_UNIFORM_ID ? rnd.color_low.rgb : mix(rnd.color_low.rgb, rnd.color_high.rgb, t);
    float light = 0.3 + 0.7 * max(dot(normal, -dir), 0.0);
    o_color = vec4(base * light, 1.0);
    gl_FragDepth = window_depth(hit);
}
