// |v| and v/|v| without overflow. length() squares the components, so a component above
// ~1.8e19 makes it +Inf, and v * max_speed / |v| then turns a huge velocity into 0. Vectors
// with a component above 2^64 are scaled by 2^-100 first (exact: a power of two; the squares
// then stay between 2^-72 and 2^58), so the direction is always right and the length is +Inf
// only when |v| itself exceeds float range. (Dividing by the largest component instead fails
// near FLT_MAX, where 1/m is denormal and flushed to 0.)
const float kRobustLarge = 1.8446744073709552e19;  // 2^64
const float kRobustDown = 7.888609052210118e-31;   // 2^-100
const float kRobustUp = 1.2676506002282294e30;     // 2^100

float robust_length(vec3 v) {
    float m = max(max(abs(v.x), abs(v.y)), abs(v.z));
    return m > kRobustLarge ? length(v * kRobustDown) * kRobustUp : length(v);
}

// v / |v| for any finite non-zero v.
vec3 robust_direction(vec3 v) {
    float m = max(max(abs(v.x), abs(v.y)), abs(v.z));
    return normalize(m > kRobustLarge ? v * kRobustDown : v);
}
