// Depth pass: the nearest sphere surface per pixel as linear eye depth, where it lies inside
// [near, far] and in front of the engine's scene. gl_FragDepth (normalised eye depth on the
// own depth attachment, test LESS) keeps the nearest sphere.
#include "common/render.glsl"
#include "common/ssf_scene.glsl"

layout(location = PF_VARY_THROUGH) in vec3 v_through;
layout(location = PF_VARY_CENTER) flat in vec3 v_center;
layout(location = 0) out float o_depth;

void main() {
    vec3 origin, dir;
    camera_ray(v_through, origin, dir);
    float t_front, t_back;
    if (!sphere_hit(origin, dir, v_center, rnd.sphere.x, t_front, t_back)) discard;
    float depth = -(origin.z + t_front * dir.z);
    if (depth < rnd.planes.x || depth > rnd.planes.y) discard;
    if (depth >= scene_eye_depth(ivec2(gl_FragCoord.xy))) discard;
    o_depth = depth;
    gl_FragDepth = (depth - rnd.planes.x) / (rnd.planes.y - rnd.planes.x);
}
