/* The per-substep uniform block, declared once for GLSL (common/sim.glsl: `sim.<name>`) and
 * C++ (src/sim/sim_uniforms.h: pf::SimUniforms). Each PF_UNIFORM(type, name) line becomes a
 * member of both. Only 4-byte scalars (float, int, uint) and 16-byte vectors (vec4, ivec4,
 * uvec4) are allowed, and a vector must start at a multiple of 16 bytes: then the std140
 * offsets equal the C++ offsets (static_assert in sim_uniforms.h, and a test compares every
 * member against the offset the GL reports). */
PF_UNIFORM(ivec4, grid)               /* nx, ny, nz, cell count */
PF_UNIFORM(ivec4, face_count)         /* faces of the u, v, w lattices, and their total */
PF_UNIFORM(vec4, origin)              /* world position of the grid's minimum corner (xyz) */
PF_UNIFORM(vec4, gravity)             /* body acceleration in m/s^2 (xyz) */
PF_UNIFORM(float, dx)                 /* cell edge, m */
PF_UNIFORM(float, dt)                 /* substep length, s */
PF_UNIFORM(float, density)            /* liquid density, kg/m^3 (pressure in pascals) */
PF_UNIFORM(float, max_speed)          /* particle speed bound, m/s */
PF_UNIFORM(float, momentum_scale)     /* fixed-point P2G: S_m = 2^20 / max_speed */
PF_UNIFORM(float, weight_scale)       /* fixed-point P2G: S_w = 2^20 */
PF_UNIFORM(float, inv_momentum_scale) /* 1 / S_m */
PF_UNIFORM(float, inv_weight_scale)   /* 1 / S_w */
PF_UNIFORM(float, flip_ratio)         /* 0 = PIC, 1 = FLIP */
PF_UNIFORM(uint, particle_count)      /* live particles */
PF_UNIFORM(uint, separation)          /* 1: pressure is kept >= 0 (liquid may leave walls) */
PF_UNIFORM(float, rest_particles)     /* particles per cell at rest density (desc.fill_particles_per_cell) */
PF_UNIFORM(float, volume_correction)  /* pressure setup: fraction of a cell's excess particle density removed per substep */
PF_UNIFORM(uint, ghost_fluid)        /* 1: the free surface sits where the particles put it (PF_FREE_SURFACE_GHOST_FLUID) */
PF_UNIFORM(float, drift_dt)           /* length of this pass's particle move, s: dt, or dt/2 for a leapfrog half move */
PF_UNIFORM(float, correction_reach)   /* the volume correction's largest move, cells an axis */
PF_UNIFORM(uint, p2g_float_sums)      /* 1: the P2G sums are floats, else fixed point (FLIP's G2P reads the weights) */
PF_UNIFORM(uint, pad_1)               /* pads the block to a multiple of 16 bytes */
PF_UNIFORM(uint, pad_2)
PF_UNIFORM(uint, pad_3)
