// Depth pass, raster path: the nearest sphere surface per pixel as linear eye depth, where it
// lies inside [near, far] and in front of the engine's scene (common/ssf_sphere.glsl, shared
// with the compute splats). gl_FragDepth (normalised eye depth on the own depth attachment,
// test LESS) keeps the nearest sphere.
#include "common/ssf_sphere.glsl"

layout(location = PF_VARY_CENTER) flat in vec4 v_sphere;
layout(location = 0) out float o_depth;

void main() {
    float depth;
    if (!sphere_depth_at(gl_FragCoord.xy, v_sphere, depth)) discard;
    o_depth = depth;
    gl_FragDepth = (depth - rnd.planes.x) / (rnd.planes.y - rnd.planes.x);
}
