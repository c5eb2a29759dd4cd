/* Binding slots and constants shared by the C++ host code and the GLSL kernels.
 * Valid C and GLSL: only #define lines. Every kernel uses at most 8 storage blocks with
 * indices 0..7 (the GL 4.3 minimum), so kernels that never share a buffer reuse slots:
 * the particle/face group (0-7) and the pressure/extrapolation group (0, 1, 3 reused). */
#ifndef PF_SLOTS_H
#define PF_SLOTS_H

#define PF_WORKGROUP_SIZE 256

/* storage blocks: particle and face kernels */
#define PF_SLOT_PARTICLE_POS 0
#define PF_SLOT_PARTICLE_VEL 1
#define PF_SLOT_FACE_VEL 2
#define PF_SLOT_FACE_VEL_OLD 3
#define PF_SLOT_FACE_ACCUM 4
#define PF_SLOT_CELL_COUNT 5
#define PF_SLOT_CELL_TYPE 6
#define PF_SLOT_STATUS 7
/* per face: theta, where the free surface crosses the segment from a FLUID cell's centre to its
 * AIR neighbour's (1: the AIR centre, the marker-cell surface); bound by grid_forces (which
 * writes it), free_surface, velocity_update and volume_correction_move, none of which binds the
 * cell counts */
#define PF_SLOT_FACE_FRACTION 5
/* APIC affine vectors (3 vec4 per particle), bound by P2G, G2P and the effects that add or remove
 * particles: none of them binds cell_type at PF_SLOT_CELL_TYPE */
#define PF_SLOT_PARTICLE_AFFINE 6
/* APIC's G2P with obstacles (common/solid_walls.glsl): the cell types, on the slot of FLIP's old
 * face velocities, which APIC does not read */
#define PF_SLOT_APIC_CELL_TYPE 3
/* G2P in the tiled P2G's order (common/particle_order.glsl): the live particle slots grouped by
 * tile; G2P binds neither face accumulators nor cell counts */
#define PF_SLOT_PARTICLE_ORDER 4
/* storage blocks: pressure and extrapolation kernels (no particle buffers bound there) */
#define PF_SLOT_PRESSURE 0
#define PF_SLOT_PRESSURE_OUT 1
#define PF_SLOT_RHS 3
#define PF_SLOT_FACE_VALID 0
#define PF_SLOT_FACE_VALID_OUT 1
/* FLIP's G2P: the P2G sums (their weights tell how alone a particle is) */
#define PF_SLOT_G2P_FACE_ACCUM 5
/* storage blocks of the pressure-solver kernels (shaders/solvers/): they share slots 0..7 among
 * themselves; PF_SLOT_CELL_TYPE (6) and PF_SLOT_RHS (3) keep their meaning */
#define PF_SLOT_SOLVER_STATE 7   /* scalars + indirect records (solvers/common/solver_state.h) */
#define PF_SLOT_SOLVER_X 0       /* the iterate (pressure, or a multigrid level's correction) */
#define PF_SLOT_SOLVER_R 1       /* residual */
#define PF_SLOT_SOLVER_P 2       /* search direction / scratch */
#define PF_SLOT_SOLVER_Q 4       /* A p / scratch */
#define PF_SLOT_SOLVER_PARTIALS 5 /* per-workgroup partial sums (vec4) */
#define PF_SLOT_SOLVER_Z 3       /* preconditioned residual (kernels that do not read the rhs) */
#define PF_SLOT_SOLVER_STATUS 0  /* the simulation's status buffer, in the final check only */
#define PF_SLOT_SOLVER_Z_INIT 4  /* cg_init with Jacobi: the z it makes (slot Z holds the rhs there) */
#define PF_SLOT_SOLVER_P_NEXT 0  /* cg_matvec: the new search direction (CG alternates two p buffers) */
#define PF_SLOT_SOLVER_MG_START 3 /* cg_update_stored: the V-cycle's first red half-sweep (z's slot) */
#define PF_SLOT_SOLVER_WORKING_TYPE 2 /* cell types with separated cells held at p = 0 (CG family) */
/* a pair solve's second problem (solvers/common/solver_value.glsl): its right-hand side and iterate
 * (the volume correction's potential), beside the first's; cg_update_stored binds p and q on
 * slots 2 and 4, so its second iterate takes 5; the final report's second status buffer */
#define PF_SLOT_SOLVER_RHS_SECOND 2
#define PF_SLOT_SOLVER_X_SECOND 4
#define PF_SLOT_SOLVER_UPDATE_X_SECOND 5
#define PF_SLOT_SOLVER_STATUS_SECOND 1
/* storage blocks of the multigrid kernels (shaders/solvers/mgpcg/): a level and the next coarser one */
#define PF_SLOT_MG_TYPE 6        /* the level's cell types */
#define PF_SLOT_MG_R 3           /* the level's right-hand side (the residual it corrects) */
#define PF_SLOT_MG_E 0           /* the level's correction */
#define PF_SLOT_MG_TMP 1         /* the level's residual after smoothing */
#define PF_SLOT_MG_COARSE_TYPE 2
#define PF_SLOT_MG_COARSE_R 4
#define PF_SLOT_MG_COARSE_E 5
#define PF_SLOT_MG_STENCIL 0      /* a Galerkin level's stored operator (solvers/mgpcg/galerkin.glsl), in place of its e */
#define PF_SLOT_MG_COARSE_STENCIL 1 /* the next coarser level's, as the setup makes it */
/* storage blocks of the sorted-gather P2G (pf_p2g PF_P2G_SORTED_GATHER, transfer/sorted_gather/):
 * positions 0, velocities 1, face accumulators 4 and APIC affine vectors 6 as above; its own
 * buffers on the slots those kernels leave free (none binds face velocities or the status
 * buffer, and only the counting pass binds cell counts). It sorts by half cell (2 x 2 x 2 per
 * cell). */
#define PF_SLOT_SORT_CELL_SLOT 2  /* per particle: uvec2(its half cell, its slot among that half cell's particles) */
#define PF_SLOT_SORT_HALF_COUNT 3 /* per half cell: particles (the counting pass only) */
#define PF_SLOT_SORT_HALF_START 3 /* per half cell, plus one: first index of its particles in the sorted order */
#define PF_SLOT_SORT_UNSORTED 4   /* particle indices grouped by half cell, in counting-atomic order */
#define PF_SLOT_SORT_GRID 5       /* in the sorted order: each particle's grid coordinate (vec4, w unused) */
#define PF_SLOT_SORT_PARTICLE 7   /* in the sorted order: each particle's velocity and index (vec3 + uint) */
/* the tiled P2G (pf_p2g PF_P2G_TILED, transfer/tiled/): positions, velocities, face accumulators,
 * cell counts, status and APIC affine vectors as above; the counting sort by tile on the sorted
 * gather's slots (the key is the tile instead of the half cell) */
#define PF_P2G_TILE 4             /* cells per tile edge: one workgroup sums a tile's particles */
#define PF_P2G_TILE_WINDOW 6      /* face samples per window edge: the tile's and one around it */
#define PF_SLOT_TILE_START 2      /* the splat: per tile, plus one, the first index of its particles */
#define PF_SLOT_TILE_ORDER 3      /* the splat: particle indices grouped by tile */
/* the exclusive prefix sum (transfer/common/scan_blocks.comp and scan_add.comp): items per
 * invocation and per workgroup (one block) */
#define PF_SCAN_ITEMS_PER_INVOCATION 4
#define PF_SCAN_BLOCK (PF_WORKGROUP_SIZE * PF_SCAN_ITEMS_PER_INVOCATION)
/* storage blocks of the exclusive prefix sum */
#define PF_SLOT_SCAN_IN 0
#define PF_SLOT_SCAN_OUT 1
/* storage blocks of the accuracy-metrics kernels (sim/metrics*.comp): the particle/face group's
 * slots for what they read, and the face accumulator's slot (4, unused there) for their partial sums */
#define PF_SLOT_METRICS_PARTIALS 4
/* storage blocks of the hydrostatic pressure estimate (sim/hydrostatic_start.comp) use
 * PF_SLOT_CELL_TYPE and PF_SLOT_PRESSURE */
/* storage blocks of the effects (shaders/effects/<name>/): each effect's own list of objects on
 * slot 3, which none of their kernels uses otherwise (they bind particles 0-1, face velocities 2,
 * face accumulators 4, cell types 6) */
#define PF_SLOT_FORCE_FIELDS 3
#define PF_SLOT_OBSTACLES 3
#define PF_SLOT_EMITTERS 3
#define PF_SLOT_SINKS 3
/* the live-count record (PF_COUNT_* words below) of emitters and sinks, on the cell-count slot
 * none of their kernels uses, and the sinks' compaction lists and counters */
#define PF_SLOT_PARTICLE_COUNT 5
#define PF_SLOT_SINK_HOLES 2
#define PF_SLOT_SINK_MOVERS 4
#define PF_SLOT_SINK_STATE 7
/* the obstacles' force sums (obstacle_forces.comp binds cell types 6, pressure 0, records 3) */
#define PF_SLOT_OBSTACLE_FORCES 5
/* the volume correction's displacement potential: written by its setup (which binds the
 * pressure 0, rhs 3, counts 5, cell types 6) and read by its particle move (positions 0, cell
 * types 6) */
#define PF_SLOT_VOLUME_POTENTIAL_OUT 1
#define PF_SLOT_VOLUME_POTENTIAL 3
/* the vorticity confinement's per-cell vorticity (vec4: w, |w|), on the effects' slot 3: written
 * by vorticity.comp (face velocities 2, cell types 6), read by confinement_force.comp */
#define PF_SLOT_VORTICITY 3
/* storage blocks of the whitewater kernels (shaders/effects/whitewater/): last step's particles
 * in (0, 1), face velocities 2, the liquid fraction around each cell 3, this step's particles
 * out (4, 5), cell types 6 and the state record (PF_WW_* words below) 7; the status buffer on 0
 * in the kernels that read no particles (emit, commit) */
#define PF_SLOT_WW_IN_POS 0
#define PF_SLOT_WW_IN_VEL 1
#define PF_SLOT_WW_FRACTION 3
#define PF_SLOT_WW_OUT_POS 4
#define PF_SLOT_WW_OUT_VEL 5
#define PF_SLOT_WW_STATE 7
#define PF_SLOT_WW_STATUS 0
/* storage blocks of the viscosity kernels (shaders/effects/viscosity/): the stresses at cell
 * centres 0 and at cell corners 1 (edges), the CG search direction 2 (the stress pass's input:
 * face velocities there in the first pass of a solve), the residual 3, per face the mass weight
 * and inverse diagonal 4, per-workgroup partial sums 5, A p 6 (cell types there in the kernels
 * that bind no A p), the state record 7 (effects/viscosity/viscosity_state.h); the update binds
 * the face velocities on 0; the first stress pass reads the faces' velocities as walls and
 * obstacles set them after classify on the residual's slot 3 */
#define PF_SLOT_VISC_SIGMA_CELL 0
#define PF_SLOT_VISC_SIGMA_NODE 1
#define PF_SLOT_VISC_P 2
#define PF_SLOT_VISC_R 3
#define PF_SLOT_VISC_COEF 4
#define PF_SLOT_VISC_PARTIALS 5
#define PF_SLOT_VISC_Q 6
#define PF_SLOT_VISC_STATE 7
#define PF_SLOT_VISC_X 0
#define PF_SLOT_VISC_SOLID_VEL 3
/* and the coupling rounds' update (visc_couple_update.comp): the face velocities 0, the next
 * round's input per face 2, the round's viscous velocities before its projection 3, cell types 6 */
#define PF_SLOT_VISC_TARGET 2
#define PF_SLOT_VISC_BEFORE 3
/* the surface tension's liquid fraction per cell, raw and smoothed: the raw one written by
 * st_fraction.comp (which binds the face accumulators 4) and read by st_liquid.comp (cell types
 * 6), which writes the smoothed one, read by st_force.comp (face velocities 2, face fractions 5,
 * cell types 6) */
#define PF_SLOT_ST_FRACTION 1
#define PF_SLOT_ST_LIQUID 3
/* storage block of the generic fill kernel */
#define PF_SLOT_FILL 0
/* highest storage slot any kernel uses, plus one: the state guard saves 0..PF_SLOT_COUNT-1 */
#define PF_SLOT_COUNT 8

/* explicit uniform locations of the fill kernel */
#define PF_LOC_FILL_COUNT 0
#define PF_LOC_FILL_VALUE 1

/* explicit uniform locations of the push kernel */
#define PF_LOC_PUSH_CENTER_RADIUS 0
#define PF_LOC_PUSH_DV_MAX_SPEED 1
#define PF_LOC_PUSH_COUNT 2

/* explicit uniform locations of the prefix-sum kernels: items of the level, and word offsets of
 * its input, its output and its block totals */
#define PF_LOC_SCAN_COUNT 0
#define PF_LOC_SCAN_IN_OFFSET 1
#define PF_LOC_SCAN_OUT_OFFSET 2
#define PF_LOC_SCAN_SUMS_OFFSET 3

/* explicit uniform location of the metrics reduction: workgroups (partial-sum pairs) to add */
#define PF_LOC_METRICS_GROUPS 0

/* explicit uniform location of the effects' kernels: how many objects of the effect's list are live */
#define PF_LOC_EFFECT_COUNT 0
/* explicit uniform locations of the emit kernels (emitters use PF_LOC_EFFECT_COUNT too) */
#define PF_LOC_EMIT_TOTAL 1     /* particles this step's emitters ask for */
#define PF_LOC_EMIT_SEED 2      /* desc.seed: shifts each emitter's point sequence */
#define PF_LOC_EMIT_CAPACITY 3  /* max_particles */
/* explicit uniform locations of the domain-motion kernel: accelerations in the domain's frame */
#define PF_LOC_DOMAIN_LINEAR 0   /* R^T (g - A) - g: gravity turned into the frame, minus the frame's
                                    linear acceleration, less the gravity the core already added */
#define PF_LOC_DOMAIN_OMEGA 1    /* angular velocity (xyz) */
#define PF_LOC_DOMAIN_ALPHA 2    /* angular acceleration (xyz) */
/* explicit uniform location of the vorticity confinement's force kernel: epsilon */
#define PF_LOC_VORTICITY_STRENGTH 0
/* explicit uniform location of the surface tension's force kernel: sigma, N/m */
#define PF_LOC_ST_TENSION 0
/* explicit uniform locations of the whitewater kernels */
#define PF_LOC_WW_CAPACITY 0   /* uint: particle slots */
#define PF_LOC_WW_MOTION 1     /* vec4: frame dt, bubble buoyancy, bubble drag, spray drag */
#define PF_LOC_WW_LIMITS_A 2   /* vec4: trapped-air range, wave-crest range */
#define PF_LOC_WW_LIMITS_B 3   /* vec4: energy range, lifetime range */
#define PF_LOC_WW_RATES 4      /* vec4: trapped-air and wave-crest particles per cell this step, 0, 0 */
#define PF_LOC_WW_SEED 5       /* uint: the step number mixed with desc.seed (new numbers every step) */
/* The whitewater's state record (uints): two DrawArraysIndirectCommand records of the live
 * particles (like PF_COUNT_*), the count of the step's output while it is being built, then a
 * DispatchIndirectCommand of one invocation per live particle (the per-particle passes). */
#define PF_WW_LIVE 0
#define PF_WW_STRIP_RECORD 4
#define PF_WW_INSTANCES 5
#define PF_WW_NEXT 8
#define PF_WW_GROUPS 9
#define PF_WW_WORDS 12

/* The live-count record (8 words), kept on the GPU: two DrawArraysIndirectCommand records, so
 * engines and the renderer draw exactly the live particles without reading the count back.
 * [0..3] {live, 1, 0, 0}: points; [4..7] {4, live, 0, 0}: a 4-vertex strip per particle. */
#define PF_COUNT_LIVE 0
#define PF_COUNT_STRIP_RECORD 4  /* first word of the strip record */
#define PF_COUNT_INSTANCES 5
#define PF_COUNT_WORDS 8
/* explicit uniform location of obstacle_forces.comp: the weight of this substep in the step's mean */
#define PF_LOC_OBSTACLE_FORCE_WEIGHT 1

/* uniform block with the per-step constants (common/sim.glsl, src/sim/sim_uniforms.h) */
#define PF_UBO_SIM 0

/* cell types: a cell's word holds its kind in the low 2 bits (read it with PF_CELL_KIND). Above
 * them a FLUID cell beside AIR carries the ghost-fluid free surface's extra diagonal of the
 * pressure operator, sum over its AIR faces of (1/theta - 1), in units of 1/PF_CELL_SURFACE_ONE
 * (common/free_surface.glsl) */
#define PF_CELL_AIR 0
#define PF_CELL_FLUID 1
#define PF_CELL_SOLID 2
#define PF_CELL_KIND(word) ((word) & 3u)
#define PF_CELL_SURFACE_SHIFT 2
#define PF_CELL_SURFACE_ONE 65536.0

/* status buffer words, read back a frame late */
#define PF_STATUS_FLAGS 0
#define PF_STATUS_MAX_SPEED 1
#define PF_STATUS_SOLVER_ITERATIONS 2  /* most pressure iterations of a substep in the step */
#define PF_STATUS_SOLVER_RESIDUAL 3    /* largest final relative residual (float bits) */
#define PF_STATUS_SOLVER_FIRST_ROUND 4 /* most iterations of a solve's first round */
#define PF_STATUS_SOLVER_LATER_ROUNDS 5 /* most iterations of one later round (active-set rounds) */
/* accuracy metrics of the step (its last substep's grid, its final particle velocities), written
 * once per step by sim/metrics_finish.comp; floats as bits unless noted */
#define PF_STATUS_DIVERGENCE_L2 6      /* RMS of div u over FLUID cells after the projection, 1/s */
#define PF_STATUS_DIVERGENCE_MAX 7     /* max |div u| over FLUID cells, 1/s */
#define PF_STATUS_KINETIC_ENERGY 8     /* 0.5 m sum |v|^2 over the particles, J */
#define PF_STATUS_FLUID_CELLS 9        /* FLUID cells (uint) */
#define PF_STATUS_PARTICLE_VOLUME 10   /* dx^3 sum over cells of min(count / rest count, 1), m^3 */
#define PF_STATUS_POTENTIAL_ENERGY 11  /* m sum -g . (x - origin) over the particles, J */
#define PF_STATUS_PARTICLE_COUNT 12    /* live particles at the step's end (uint) */
#define PF_STATUS_INTERIOR_DENSITY 13 /* mean count / rest over interior FLUID cells (0: none) */
#define PF_STATUS_WHITEWATER_COUNT 14 /* live whitewater particles at the step's end (uint) */
#define PF_STATUS_VISCOSITY_ITERATIONS 15 /* most viscosity iterations of a substep in the step (uint) */
#define PF_STATUS_VISCOSITY_RESIDUAL 16 /* largest final relative residual of a viscosity solve (float bits) */
#define PF_STATUS_VISCOSITY_PROJECTION_RESIDUAL 17 /* the viscosity's second projection: largest final residual */
#define PF_STATUS_VISCOSITY_PROJECTION_ITERATIONS 18 /* and most iterations of its solves' first round */
#define PF_STATUS_STRAIN 19 /* sum of the strain P over interior FLUID cells / FLUID cells, 1/s^2 */
#define PF_STATUS_CORRECTION_RESIDUAL 20 /* the volume correction's solves: largest final residual */
#define PF_STATUS_CORRECTION_ITERATIONS 21 /* and most iterations of their first round */
#define PF_STATUS_CORRECTION_RAN 22 /* 1 where the step ran the correction (the two above are its) */
#define PF_STATUS_WORDS 23

/* status flag bits; equal to PF_FLAG_* in pf.h (checked by static_assert) */
#define PF_GPU_FLAG_P2G_OVERFLOW 1u
#define PF_GPU_FLAG_NONFINITE 2u
#define PF_GPU_FLAG_SPEED_CLAMPED 4u
#define PF_GPU_FLAG_EMITTERS_FULL 64u
#define PF_GPU_FLAG_WHITEWATER_FULL 128u

#endif
