// Quaternion rotation and signed distances of the primitive shapes the effects place in the
// world (emitters, sinks): positions are turned into the shape's frame by the inverse of its
// unit quaternion (x, y, z, w), then measured against the shape centred at the origin.

// v rotated by unit quaternion q (shape frame -> world direction).
vec3 quat_rotate(vec4 q, vec3 v) {
    vec3 t = 2.0 * cross(q.xyz, v);
    return v + q.w * t + cross(q.xyz, t);
}

// v rotated by the inverse of unit quaternion q (world direction -> shape frame).
vec3 quat_rotate_inverse(vec4 q, vec3 v) { return quat_rotate(vec4(-q.xyz, q.w), v); }

// Signed distance (negative inside) from p to the box of half sizes `half_size` at the origin.
float box_distance(vec3 p, vec3 half_size) {
    vec3 q = abs(p) - half_size;
    return length(max(q, vec3(0.0))) + min(max(q.x, max(q.y, q.z)), 0.0);
}

// Signed distance (negative inside) from p to the ball of radius r at the origin.
float sphere_distance(vec3 p, float r) { return length(p) - r; }
