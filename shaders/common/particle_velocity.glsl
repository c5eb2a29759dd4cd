// The end of every G2P transfer (design.md §4.9): a non-finite velocity becomes 0 and a speed
// above max_speed is scaled down to it (both flagged); the largest speed goes to the status
// buffer for the next frame's CFL estimate. The including kernel declares status[].
#include "common/robust_length.glsl"

// Applies the guard to v, adds PF_GPU_FLAG_* bits to flags, sets speed to |v| after the guard
// and returns the factor v was multiplied by (0, max_speed / |v| or 1), so APIC can scale its
// affine vectors alike.
float limit_velocity(inout vec3 v, inout uint flags, out float speed) {
    if (any(isnan(v)) || any(isinf(v))) {
        v = vec3(0.0);
        flags |= PF_GPU_FLAG_NONFINITE;
        speed = 0.0;
        return 0.0;
    }
    speed = robust_length(v);
    if (speed > sim.max_speed) {
        float scale = sim.max_speed / speed;  // 0 when |v| is beyond float range
        v = robust_direction(v) * sim.max_speed;
        speed = sim.max_speed;
        flags |= PF_GPU_FLAG_SPEED_CLAMPED;
        return scale;
    }
    return 1.0;
}

void publish_status(float speed, uint flags) {
    if (flags != 0u) atomicOr(status[PF_STATUS_FLAGS], flags);
    // Non-negative floats order like their bit patterns.
    atomicMax(status[PF_STATUS_MAX_SPEED], floatBitsToUint(speed));
}
