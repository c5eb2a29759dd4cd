// The values a solver kernel works on per cell: one problem's (float), or, in the PF_PAIR 1
// permutations, two problems with the same operator and cell types solved in the same passes
// (vec2: .x the projection's pressure, .y the volume correction's potential; docs/design.md
// §4.6, "A pair solve"). pairs_t holds neighbour values summed per axis pair (poisson.glsl's
// pair_total), sums_t a reduction kernel's sums: a vec4, or a mat2x4 (a column per problem) in a
// pair kernel that defines PF_SUMS 2 (orbit_main.glsl).
// Include before the kernel's buffer declarations.
#ifndef PF_VALUE_TYPES
#ifndef PF_PAIR
#define PF_PAIR 0
#endif
#define PF_VALUE_TYPES 1
#if PF_PAIR
#define value_t vec2
#define pairs_t mat3x2
#else
#define value_t float
#define pairs_t vec3
#endif
#if defined(PF_SUMS) && PF_SUMS == 2
#define sums_t mat2x4
#else
#define sums_t vec4
#endif
#endif
