// Thickness pass, raster path: length of the camera ray inside each sphere, blended
// additively (ONE, ONE), counting only the part between the near plane and the nearer of the
// far plane and the engine's scene surface (common/ssf_sphere.glsl, shared with the compute
// splats), at half resolution: the ray through each thickness texel's centre.
#include "common/ssf_sphere.glsl"

layout(location = PF_VARY_CENTER) flat in vec4 v_sphere;
layout(location = 0) out float o_thickness;

void main() {
    float chord = sphere_chord_at(thickness_frag(gl_FragCoord.xy), v_sphere);
    if (chord <= 0.0) discard;
    o_thickness = chord;
}
