// The ghost-fluid free surface (Enright, Nguyen, Gibou & Fedkiw 2003; docs/design.md §4.6a):
// where a FLUID cell meets an AIR cell, the pressure's zero sits at theta along the segment
// between their centres instead of at the AIR centre (theta = 1, the marker-cell surface). The
// operator's diagonal gains 1/theta - 1 per AIR face and the face's pressure gradient is divided
// by theta, so the pressure follows the surface's sub-cell position.
#include "common/slots.h"

// Smallest theta: a surface that barely enters a FLUID cell pins its pressure near 0 without an
// unbounded coefficient.
const float kMinSurfaceFraction = 0.05;

// Theta of a face from its P2G weight sum over the rest count (trilinear weights of liquid at
// rest density sum to the rest count): for a flat surface s cells past the face, the hat kernel
// gives r = (1 + s)^2 / 2 for s <= 0 and 1 - (1 - s)^2 / 2 above; inverted, theta = 1/2 + s.
float surface_fraction(float weight_ratio) {
    float r = clamp(weight_ratio, 0.0, 1.0);
    float s = r <= 0.5 ? sqrt(2.0 * r) - 1.0 : 1.0 - sqrt(2.0 * (1.0 - r));
    return clamp(0.5 + s, kMinSurfaceFraction, 1.0);
}

// The extra diagonal a FLUID cell's type word carries (0 for any other word).
float surface_extra_diagonal(uint word) { return float(word >> PF_CELL_SURFACE_SHIFT) / PF_CELL_SURFACE_ONE; }

// A FLUID word carrying `extra`.
uint fluid_word(float extra) {
    return uint(PF_CELL_FLUID) | (uint(extra * PF_CELL_SURFACE_ONE + 0.5) << PF_CELL_SURFACE_SHIFT);
}
