// The lighting the samples' world and obstacles share (GLSL): the sun, a sky/ground hemisphere
// and a Blinn-Phong highlight, so an obstacle sits in the scene's light like the tank and the
// crate. A fragment shader declares `uniform vec3 u_sun` (towards the sun, normalised) and
// `uniform vec3 u_eye`, writes the line `#pragma sun_light` where the function belongs, and is
// linked through with_sun_light().
#pragma once

#include <string>

namespace pfs {

inline constexpr const char* kSunLightGlsl = R"(
vec3 sun_lit(vec3 albedo, vec3 n, vec3 world, float spec_strength, float shininess) {
    vec3 v = normalize(u_eye - world);
    vec3 h = normalize(u_sun + v);
    float diffuse = max(dot(n, u_sun), 0.0);
    vec3 hemi = mix(vec3(0.36, 0.33, 0.30), vec3(0.62, 0.72, 0.86), 0.5 + 0.5 * n.y);
    vec3 sun_color = vec3(1.0, 0.95, 0.86);
    return albedo * (0.55 * hemi + 0.8 * diffuse * sun_color)
           + spec_strength * pow(max(dot(n, h), 0.0), shininess) * sun_color * step(0.0, dot(n, u_sun));
}
)";

// `fs` with its `#pragma sun_light` line replaced by kSunLightGlsl (unchanged if it has none).
inline std::string with_sun_light(const char* fs) {
    std::string s(fs);
    const std::string marker = "#pragma sun_light";
    const size_t at = s.find(marker);
    if (at != std::string::npos) s.replace(at, marker.size(), kSunLightGlsl);
    return s;
}

}  // namespace pfs
