// The sum over a Galerkin stencil (galerkin.glsl) of the kernel's `value_t term(ivec3 o)`, one
// mirror orbit at a time: ((o) + (x-mirror)) + ((z-mirror) + (both)), orbits in a fixed order,
// so mirrored inputs give bit-mirrored sums (as poisson.glsl's pair_total). The kernel defines
// term() before including this file.
value_t galerkin_sum() {
    value_t total = value_t(0.0);
    for (int oz = 0; oz <= kRadius; ++oz) {
        for (int oy = -kRadius; oy <= kRadius; ++oy) {
            for (int ox = 0; ox <= kRadius; ++ox) {
                if (!orbit_used(ivec3(ox, oy, oz))) continue;
                value_t a = term(ivec3(ox, oy, oz));
                value_t b = ox > 0 ? term(ivec3(-ox, oy, oz)) : value_t(0.0);
                value_t c = oz > 0 ? term(ivec3(ox, oy, -oz)) : value_t(0.0);
                value_t d = ox > 0 && oz > 0 ? term(ivec3(-ox, oy, -oz)) : value_t(0.0);
                total += (a + b) + (c + d);
            }
        }
    }
    return total;
}
