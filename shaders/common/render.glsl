// Camera, look and geometry helpers shared by every render shader. Depths come in three
// forms: eye depth (metres in front of the camera, -z in eye space; what the screen-space
// passes store), NDC z and window depth (what the engine's depth buffer holds, in its
// convention: pf_depth_convention).
#include "common/render_slots.h"

layout(std140, binding = PF_UBO_RENDER) uniform RenderUniforms {
    mat4 view;        // world -> eye
    mat4 proj;        // eye -> clip, engine convention
    mat4 inv_proj;    // clip -> eye
    mat4 inv_view;    // eye -> world
    vec4 viewport;    // width, height, 1/width, 1/height in pixels (own textures are this size)
    vec4 planes;      // near, far, depth convention id, 1 for an orthographic projection
    vec4 sphere;      // particle radius, filter radius (px), filter depth range (m), 1 if scene depth given
    vec4 absorption;  // Beer-Lambert absorption per metre (rgb), refraction offset (w)
    vec4 light;       // world direction towards the sun, normalised (xyz), specular strength (w)
    vec4 surface;     // fresnel f0, shininess, 1 if an environment cube map is given,
                      // y sign of window -> NDC (-1 when the engine set glClipControl(GL_UPPER_LEFT))
    vec4 color_low;   // debug view: rgb at range[0] (xyz), range[0] (w)
    vec4 color_high;  // debug view: rgb at range[1] (xyz), range[1] (w)
    ivec4 modes;      // debug view colour source (pf_particle_color), -, -, -
    ivec4 target;     // viewport x, y in the engine's target (own texel = target pixel - this), -, -
    mat4 domain_view; // simulation (domain) coordinates -> eye: view * the domain's pose
    vec4 filter_size; // filter half-width in metres, pixels per metre at eye depth 1 (perspective) or at
                      // any depth (orthographic), -, -
    vec4 whitewater;  // sprite radius of foam (m), opacity at a sprite's centre, -, -
    vec4 liquid;      // a particle's liquid volume over its sphere's volume (x; the summed chords
                      // times x are metres of liquid), -, -, -
    vec4 spray;       // spray's radius over a particle's, neighbourhood count below which a particle is
                      // spray, 1 if the cell counts are current, - (common/ssf_spray.glsl)
    vec4 grid_origin; // the simulation grid's origin (xyz, simulation coordinates) and cell size (w)
    ivec4 grid_dims;  // the simulation grid's cells per axis (xyz), -
} rnd;

// Larger than any eye depth: "no scene surface here".
const float kFarAway = 3.0e38;

bool render_orthographic() { return rnd.planes.w > 0.5; }

float window_to_ndc_z(float window) {
    return int(rnd.planes.z) == PF_DEPTH_STANDARD_ID ? 2.0 * window - 1.0 : window;
}

float ndc_to_window_z(float ndc) {
    return int(rnd.planes.z) == PF_DEPTH_STANDARD_ID ? 0.5 * ndc + 0.5 : ndc;
}

// NDC xy of a pixel centre of the own (viewport-sized) textures; frag is gl_FragCoord.xy
// or a texel index + 0.5. With an upper-left clip origin the GL flips window y, so NDC y
// runs the other way.
vec2 pixel_ndc(vec2 frag) {
    vec2 ndc = frag * 2.0 * rnd.viewport.zw - 1.0;
    return vec2(ndc.x, ndc.y * rnd.surface.w);
}

// Eye-space point on the camera ray through ndc_xy with eye depth `depth`. Perspective rays
// start at the eye, so any point on the ray fixes it (NDC z of window depth 0.5, finite in
// every convention, also for an infinite reversed-Z far plane); orthographic rays run along -z.
vec3 eye_point(vec2 ndc_xy, float depth) {
    vec4 h = rnd.inv_proj * vec4(ndc_xy, window_to_ndc_z(0.5), 1.0);
    vec3 p = h.xyz / h.w;
    if (render_orthographic()) return vec3(p.xy, -depth);
    return p * (depth / -p.z);
}

// Window depth in the engine's convention of an eye-space point.
float window_depth(vec3 eye) {
    vec4 clip = rnd.proj * vec4(eye, 1.0);
    return ndc_to_window_z(clip.z / clip.w);
}

// Eye depth of an engine window depth at ndc_xy; kFarAway where the depth maps to no finite
// point (the far plane of an infinite projection) or lies behind the camera.
float eye_depth_of_window(vec2 ndc_xy, float window) {
    vec4 h = rnd.inv_proj * vec4(ndc_xy, window_to_ndc_z(window), 1.0);
    if (!(abs(h.w) > 1e-30)) return kFarAway;
    float depth = -h.z / h.w;
    return depth > 0.0 ? depth : kFarAway;
}

// The ray of the camera through an eye-space point (origin and unit direction).
void camera_ray(vec3 through, out vec3 origin, out vec3 dir) {
    if (render_orthographic()) {
        origin = vec3(through.xy, 0.0);
        dir = vec3(0.0, 0.0, -1.0);
    } else {
        origin = vec3(0.0);
        dir = normalize(through);
    }
}

// Ray-sphere intersection: ray parameters of the entry and exit points. The distance of the
// centre from the ray comes from a vector difference, not |oc|^2 - tc^2, which cancels
// catastrophically for small far spheres.
bool sphere_hit(vec3 origin, vec3 dir, vec3 center, float radius, out float t_front, out float t_back) {
    vec3 oc = center - origin;
    float tc = dot(oc, dir);
    vec3 off = oc - tc * dir;
    float disc = radius * radius - dot(off, off);
    if (disc < 0.0) return false;
    float half_chord = sqrt(disc);
    t_front = tc - half_chord;
    t_back = tc + half_chord;
    return true;
}
