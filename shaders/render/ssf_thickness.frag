// Thickness pass: length of the camera ray inside each sphere, blended additively (ONE, ONE),
// counting only the part between the near plane and the nearer of the far plane and the
// engine's scene surface (liquid behind a wall adds nothing).
#include "common/render.glsl"
#include "common/ssf_scene.glsl"

layout(location = PF_VARY_THROUGH) in vec3 v_through;
layout(location = PF_VARY_CENTER) flat in vec3 v_center;
layout(location = 0) out float o_thickness;

void main() {
    vec3 origin, dir;
    camera_ray(v_through, origin, dir);
    float t_front, t_back;
    if (!sphere_hit(origin, dir, v_center, rnd.sphere.x, t_front, t_back)) discard;
    float front = -(origin.z + t_front * dir.z), back = -(origin.z + t_back * dir.z);
    float lo = max(front, rnd.planes.x);
    float hi = min(min(back, rnd.planes.y), scene_eye_depth(ivec2(gl_FragCoord.xy)));
    if (hi <= lo) discard;
    o_thickness = (hi - lo) / -dir.z;  // eye depth runs along -z: convert to length along the ray
}
