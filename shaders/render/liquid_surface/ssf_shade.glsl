// Shading of the screen-space liquid, shared by the compute and raster SHADE passes: normals
// from the smoothed eye depth, refraction of the copied scene colour, Beer-Lambert absorption
// over the thickness, Fresnel-weighted reflection (the engine's cube map or a built-in sky)
// and a Blinn-Phong sun highlight. Produces the liquid colour (alpha 1 where there is liquid,
// 0 elsewhere) and the liquid's window depth in the engine's convention.
#include "common/render.glsl"
#include "render/liquid_surface/ssf_depth.glsl"

layout(binding = PF_TEX_SCENE_COLOR) uniform sampler2D u_scene_color;
layout(binding = PF_TEX_THICKNESS) uniform sampler2D u_thickness;
layout(binding = PF_TEX_ENVIRONMENT) uniform samplerCube u_environment;

vec3 eye_at(ivec2 p, float depth) { return eye_point(pixel_ndc(vec2(p) + 0.5), depth); }

// Surface tangent along `dir` at pixel p. Of the two one-sided differences, the one with the
// smaller depth step belongs to this surface (the other may jump to a surface behind or in
// front); a missing neighbour leaves the other side, and a pixel with liquid on neither side
// gets the tangent of a surface facing the camera.
vec3 surface_tangent(ivec2 p, vec3 center, float depth, ivec2 dir) {
    float ahead = liquid_depth(p + dir), back = liquid_depth(p - dir);
    bool has_ahead = is_liquid(ahead), has_back = is_liquid(back);
    if (has_ahead && (!has_back || abs(ahead - depth) <= abs(depth - back))) return eye_at(p + dir, ahead) - center;
    if (has_back) return center - eye_at(p - dir, back);
    return eye_at(p + dir, depth) - center;
}

// Eye-space unit normal, turned towards the camera.
vec3 surface_normal(ivec2 p, vec3 center, float depth) {
    vec3 n = normalize(cross(surface_tangent(p, center, depth, ivec2(1, 0)),
                             surface_tangent(p, center, depth, ivec2(0, 1))));
    vec3 to_camera = render_orthographic() ? vec3(0.0, 0.0, 1.0) : -center;
    return dot(n, to_camera) < 0.0 ? -n : n;
}

// Built-in sky for reflections when the engine gives no cube map: ground below the horizon,
// a horizon-to-zenith gradient above, a sun disc with a soft glow towards light.xyz.
vec3 builtin_sky(vec3 dir) {
    const vec3 kGround = vec3(0.30, 0.28, 0.25), kHorizon = vec3(0.78, 0.86, 0.95), kZenith = vec3(0.22, 0.42, 0.78);
    vec3 sky = dir.y >= 0.0 ? mix(kHorizon, kZenith, sqrt(dir.y)) : mix(kHorizon, kGround, min(1.0, -4.0 * dir.y));
    float sun = max(dot(dir, rnd.light.xyz), 0.0);
    return sky + vec3(1.0, 0.92, 0.75) * (6.0 * pow(sun, 900.0) + 0.25 * pow(sun, 12.0));
}

void ssf_shade(ivec2 p, out vec4 color, out float window) {
    float depth = liquid_depth(p);
    color = vec4(0.0);
    window = 0.0;
    if (!is_liquid(depth)) return;
    vec3 center = eye_at(p, depth);
    vec3 n_eye = surface_normal(p, center, depth);
    vec3 v_eye = render_orthographic() ? vec3(0.0, 0.0, 1.0) : normalize(-center);

    // Refraction: look up the scene behind, displaced along the normal's screen direction.
    vec2 uv = (vec2(p) + 0.5) * rnd.viewport.zw + rnd.absorption.w * vec2(n_eye.x, n_eye.y * rnd.surface.w);
    vec3 behind = textureLod(u_scene_color, clamp(uv, vec2(0.0), vec2(1.0)), 0.0).rgb;
    // The thickness (half resolution, filtered between its texels) sums the chords of
    // overlapping spheres: scaled to the depth of liquid they stand for.
    float thickness = rnd.liquid.x * textureLod(u_thickness, (vec2(p) + 0.5) * rnd.viewport.zw, 0.0).r;
    vec3 transmitted = behind * exp(-rnd.absorption.rgb * thickness);

    // World space: normals go through the inverse transpose of inv_view, i.e. view^T.
    vec3 n = normalize(transpose(mat3(rnd.view)) * n_eye);
    vec3 v = normalize(mat3(rnd.inv_view) * v_eye);
    float cos_v = clamp(dot(n, v), 0.0, 1.0);
    float fresnel = rnd.surface.x + (1.0 - rnd.surface.x) * pow(1.0 - cos_v, 5.0);
    vec3 r = reflect(-v, n);
    vec3 reflected = rnd.surface.z > 0.5 ? textureLod(u_environment, r, 0.0).rgb : builtin_sky(r);
    vec3 h = normalize(rnd.light.xyz + v);
    float highlight = rnd.light.w * pow(max(dot(n, h), 0.0), rnd.surface.y);

    color = vec4(mix(transmitted, reflected, fresnel) + highlight, 1.0);
    window = window_depth(center);
}
