// Stateless numbers for kernels that place new things (emitters): the PCG output hash
// (Jarzynski and Olano 2020, "Hash Functions for GPU Rendering") and an evenly filling point
// sequence. Both are pure functions of their inputs: runs are reproducible.
uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Point n of the 3D R-sequence (Roberts 2018: additive recurrence by the powers of the inverse
// plastic number), shifted by `shift` (a Cranley-Patterson rotation, in 2^-32 units): a
// low-discrepancy sequence, so any run of consecutive points fills the unit cube evenly
// (random points clump: a cell would hold Poisson(8) instead of about 8). Fixed point in 32-bit
// integers, whose wrap-around is the fractional part: exact for every n.
vec3 r3_point(uint n, uvec3 shift) {
    uvec3 u = uvec3(n) * uvec3(3518319155u, 2882110345u, 2360945575u) + shift;
    return vec3(u >> 8u) * (1.0 / 16777216.0);
}
