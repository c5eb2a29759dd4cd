// Sphere sprite: one camera-facing quad per particle (instanced, 4 strip vertices), large
// enough to hold the sphere's projected silhouette; the fragment shaders intersect the
// camera ray with the sphere. Quads rather than GL points: points are clipped by their centre
// (spheres at the screen edge would pop) and their size is capped by GL_POINT_SIZE_RANGE.
// gl_Position.z is 0.5 w, inside the clip range of both glClipControl depth modes: the
// fragment shaders write gl_FragDepth themselves and cull by near/far.
#include "common/ssf_sphere.glsl"

#ifndef PF_SPHERE_VALUE
#define PF_SPHERE_VALUE 0
#endif
#if !PF_SPHERE_VALUE
#include "common/ssf_spray.glsl"
#endif

layout(location = PF_ATTR_POSITION) in vec4 a_position;
#if PF_SPHERE_VALUE
layout(location = PF_ATTR_VELOCITY) in vec4 a_velocity;
// the scalar the debug view colours by
layout(location = PF_VARY_VALUE) flat out float v_value;
#endif

// eye-space point on the quad (the camera ray through the fragment passes through it), and
// the sphere: centre in eye space (xyz) and radius (w; the debug view's is always the full one)
layout(location = PF_VARY_THROUGH) out vec3 v_through;
layout(location = PF_VARY_CENTER) flat out vec4 v_sphere;

// Outside every clip volume: the quad is dropped.
const vec4 kCulled = vec4(2.0, 2.0, 2.0, 1.0);

void main() {
#if PF_SPHERE_VALUE
    float r = rnd.sphere.x;
#else
    float r = particle_radius(a_position.xyz);
#endif
    vec3 c;
    bool visible = sphere_visible(a_position.xyz, r, c);
    v_sphere = vec4(c, r);
#if PF_SPHERE_VALUE
    int mode = rnd.modes.x;
    v_value = mode == PF_COLOR_SPEED_ID ? length(a_velocity.xyz)
            : mode == PF_COLOR_VELOCITY_X_ID ? a_velocity.x
            : mode == PF_COLOR_VELOCITY_Y_ID ? a_velocity.y
            : mode == PF_COLOR_VELOCITY_Z_ID ? a_velocity.z
            : mode == PF_COLOR_HEIGHT_ID ? a_position.y : rnd.color_low.w;
#endif
    if (!visible) {
        gl_Position = kCulled;
        v_through = vec3(0.0);
        return;
    }
    float half_size;
    vec3 t, b;
    sphere_quad(v_sphere, half_size, t, b);
    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 2.0 - 1.0;
    vec3 p = c + half_size * (corner.x * t + corner.y * b);
    v_through = p;
    vec4 clip = rnd.proj * vec4(p, 1.0);
    gl_Position = vec4(clip.xy, 0.5 * clip.w, clip.w);
}
