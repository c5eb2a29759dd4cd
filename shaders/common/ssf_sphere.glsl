// One particle's sphere as the screen-space passes see it, shared by the raster sprites
// (render/sphere.vert + fragment shaders) and the compute splats (render/liquid_surface/ssf_splat.comp), so
// both paths cover the same pixels with the same depths: the camera ray through a pixel
// centre, intersected with the sphere. A sphere is a vec4: eye-space centre (xyz) and radius (w;
// common/ssf_spray.glsl gives spray a smaller one).
#include "common/render.glsl"
#include "common/ssf_scene.glsl"

// Eye-space sphere centre of a particle position (simulation coordinates: the domain's frame,
// placed in the world by PF_FEATURE_DOMAIN_MOTION); false when nothing of the sphere can be
// drawn (wholly outside [near, far], or the camera inside it).
bool sphere_visible(vec3 position, float r, out vec3 center) {
    center = (rnd.domain_view * vec4(position, 1.0)).xyz;
    float dist = length(center);
    return !(-center.z + r < rnd.planes.x || -center.z - r > rnd.planes.y ||
             (!render_orthographic() && dist <= r * 1.0001));
}

// Half size and in-plane axes of a quad through the centre, normal to the eye-centre axis,
// that holds the sphere's projected silhouette: perspective r d / sqrt(d^2 - r^2) (the
// section of the silhouette cone there); orthographic r, facing -z.
void sphere_quad(vec4 sphere, out float half_size, out vec3 t, out vec3 b) {
    vec3 center = sphere.xyz;
    float r = sphere.w;
    float dist = length(center);
    vec3 axis = render_orthographic() ? vec3(0.0, 0.0, 1.0) : center / dist;
    half_size = render_orthographic() ? r : r * dist / sqrt(dist * dist - r * r);
    vec3 helper = abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    t = normalize(cross(helper, axis));
    b = cross(axis, t);
}

// The camera ray through the centre of own-texture pixel `frag` (texel index + 0.5).
void pixel_ray(vec2 frag, out vec3 origin, out vec3 dir) {
    camera_ray(eye_point(pixel_ndc(frag), 1.0), origin, dir);
}

// Where the ray through pixel `frag` enters and leaves the sphere, as eye depths, and the eye
// depth it gains per unit of its length (-dir.z); false when it misses.
bool sphere_span(vec2 frag, vec4 sphere, out float front, out float back, out float per_length) {
    vec3 origin, dir;
    pixel_ray(frag, origin, dir);
    float t_front, t_back;
    if (!sphere_hit(origin, dir, sphere.xyz, sphere.w, t_front, t_back)) return false;
    front = -(origin.z + t_front * dir.z);
    back = -(origin.z + t_back * dir.z);
    per_length = -dir.z;
    return true;
}

// Whether the sphere's front surface at eye depth `front` is drawn: in [near, far] and in
// front of the engine's scene at eye depth `scene`.
bool span_front_visible(float front, float scene) {
    return front >= rnd.planes.x && front <= rnd.planes.y && front < scene;
}

// Length of a span inside [near, min(far, scene)] along its ray (0 when none).
float span_chord(float front, float back, float per_length, float scene) {
    float lo = max(front, rnd.planes.x);
    float hi = min(min(back, rnd.planes.y), scene);
    return hi > lo ? (hi - lo) / per_length : 0.0;
}

// Eye depth of the sphere's front surface seen through pixel `frag`, if the ray hits it in
// [near, far] and in front of the engine's scene.
bool sphere_depth_at(vec2 frag, vec4 sphere, out float depth) {
    float back, per_length;
    return sphere_span(frag, sphere, depth, back, per_length) && span_front_visible(depth, scene_eye_depth(ivec2(frag)));
}

// Length of the ray through pixel `frag` inside the sphere, between the near plane and the
// nearer of the far plane and the engine's scene surface (0 when none).
float sphere_chord_at(vec2 frag, vec4 sphere) {
    float front, back, per_length;
    if (!sphere_span(frag, sphere, front, back, per_length)) return 0.0;
    return span_chord(front, back, per_length, scene_eye_depth(ivec2(frag)));
}
