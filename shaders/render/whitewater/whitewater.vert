// Whitewater sprites (PF_FEATURE_WHITEWATER): one camera-facing quad per live whitewater
// particle (instanced, 4 strip vertices, the count from its draw record), sized by the
// particle's kind: foam pf_ssf_params.whitewater_radius, bubbles 0.7 of it, spray 0.5.
#include "common/render.glsl"

layout(location = PF_ATTR_POSITION) in vec4 a_position;  // xyz, seconds left
layout(location = PF_ATTR_VELOCITY) in vec4 a_velocity;  // xyz, kind (pf_whitewater_kind)

layout(location = PF_VARY_THROUGH) out vec2 v_corner;     // -1..1 across the sprite
layout(location = PF_VARY_CENTER) flat out vec4 v_center; // eye-space centre, radius
layout(location = PF_VARY_VALUE) flat out vec2 v_kind_life;

const vec4 kCulled = vec4(2.0, 2.0, 2.0, 1.0);  // outside every clip volume

void main() {
    float kind = a_velocity.w;
    float radius = rnd.whitewater.x * (kind < 0.5 ? 0.5 : (kind < 1.5 ? 1.0 : 0.7));
    vec3 c = (rnd.domain_view * vec4(a_position.xyz, 1.0)).xyz;
    v_center = vec4(c, radius);
    v_kind_life = vec2(kind, a_position.w);
    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 2.0 - 1.0;
    v_corner = corner;
    if (-c.z - radius < rnd.planes.x || -c.z > rnd.planes.y) {
        gl_Position = kCulled;
        return;
    }
    vec4 clip = rnd.proj * vec4(c + vec3(radius * corner, 0.0), 1.0);
    gl_Position = vec4(clip.xy, 0.5 * clip.w, clip.w);
}
