/*
 * pflip — real-time PIC/FLIP liquid simulation on the GPU (OpenGL 4.3 compute).
 *
 * The one public header. Pure C99. Start every struct from pf_default_*(), which also sets its
 * struct_size (the ABI rules below); a zero-initialised struct (struct_size 0) means the
 * defaults for every field left zero. Every entry point validates its arguments, returns a
 * pf_result and reports failures through the logger.
 *
 * ABI rules (docs/integration.md §7). The structs that may grow (pf_sim_desc, pf_sim_params,
 * pf_stats, pf_ssf_params, pf_particle_params, pf_force_field, pf_obstacle, pf_emitter, pf_sink,
 * pf_domain_motion) start with uint32_t struct_size: sizeof the struct
 * as the caller compiled it, set by the header-inline pf_default_*() (through pf_init_*()). New
 * fields are only ever appended, so the library reads the first struct_size bytes a caller
 * compiled against an older header passes and takes the defaults for the rest, and writes no
 * more than struct_size bytes of an output struct (struct_size 0 on output: the struct's first
 * published size, so set it to sizeof to receive the fields appended since, e.g. pf_stats.liquid_volume).
 * pf_sim_desc.header_version, set to PF_VERSION by pf_default_sim_desc(), lets pf_create refuse a
 * header of another major.minor version than the library's.
 *
 * GL contract: pflip never creates a GL context. pf_create() loads GL entry points through
 * the engine's get_proc_address and uses the context current at that moment; every later
 * call on the same pf_sim must find that same context current (pflip's vertex arrays,
 * framebuffers and queries belong to it alone: a context that only shares its objects will not do).
 * Each call restores the GL state it touches (program, buffer bindings, query state).
 *
 * Frames: "world" positions, velocities and forces below are in the simulation's frame, which is
 * the world unless PF_FEATURE_DOMAIN_MOTION places the domain in it (pf_domain_motion).
 */
/**
 * @file pf.h
 * @brief The public C API of pflip (all of it).
 *
 * @defgroup pf_lifecycle Lifecycle
 * @brief Versions, result codes, loggers, descriptors, pf_create / pf_destroy, handles, the
 *        global logger and the threading rules.
 *
 * @defgroup pf_simulation Simulation
 * @brief Step parameters, particles, stepping, effects (force fields, obstacles),
 *        asynchronous readback and snapshots.
 *
 * @defgroup pf_rendering Rendering
 * @brief Drawing the liquid into the engine's frame (screen-space fluid, debug particles) and
 *        the particle buffers for engines that draw them themselves.
 *
 * @defgroup pf_stats Statistics
 * @brief Counters, GPU timings, accuracy metrics, flags and the per-pass statistics list.
 */
#ifndef PF_PF_H
#define PF_PF_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** @def PF_API
 *  Marks the library's exported functions (dllexport/dllimport on Windows, default visibility
 *  with GCC and Clang). */
#if defined(_WIN32) && defined(PF_SHARED)
#  ifdef PF_BUILDING_LIBRARY
#    define PF_API __declspec(dllexport)
#  else
#    define PF_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__)
#  define PF_API __attribute__((visibility("default")))
#else
#  define PF_API
#endif

/* PF_VERSION_MAJOR/MINOR/PATCH, PF_VERSION (major*10000 + minor*100 + patch) and
   PF_VERSION_STRING, generated from the CMake project version. */
#include <pf/pf_version.h>

/** @addtogroup pf_lifecycle
 *  @{ */
/** Result codes. Values are stable across versions. */
typedef enum pf_result {
    PF_OK = 0,                         /**< success */
    PF_ERROR_INVALID_ARGUMENT = 1,     /**< an argument was NULL, non-finite or out of range */
    PF_ERROR_GL_UNSUPPORTED = 2,       /**< no current GL 4.3 core context, or entry points missing */
    PF_ERROR_SHADER_COMPILE = 3,       /**< a shader failed to compile or link (log has details) */
    PF_ERROR_OUT_OF_MEMORY = 4,        /**< a GL or host allocation failed */
    PF_ERROR_CAPACITY = 5,             /**< the request would exceed max_particles */
    PF_ERROR_INVALID_STATE = 6,        /**< the call is not valid in the simulation's current state */
    PF_ERROR_GL = 7,                   /**< the GL reported an error during the call */
    PF_NOT_READY = 8,                  /**< not an error: pf_poll_particles' copy is still in flight */
    PF_RESULT_FORCE32 = 0x7fffffff
} pf_result;

/** Severity passed to the logger. */
typedef enum pf_log_level {
    PF_LOG_ERROR = 0,
    PF_LOG_WARNING = 1,
    PF_LOG_INFO = 2,
    PF_LOG_FORCE32 = 0x7fffffff
} pf_log_level;

/** Logger callback: level, the result code the message explains (PF_OK for info), text. */
typedef void (*pf_log_fn)(void* user, pf_log_level level, pf_result code, const char* message);

/** Logger: fn may be NULL (messages are dropped); user is passed back unchanged. */
typedef struct pf_logger {
    pf_log_fn fn;                 /**< called for each message; NULL drops them */
    void* user;                   /**< passed back to fn unchanged */
} pf_logger;

/** Any GL function pointer, as returned by eglGetProcAddress / glfwGetProcAddress. */
typedef void (*pf_gl_proc)(void);
/** The engine's GL loader: returns the entry point called name, or NULL. */
typedef pf_gl_proc (*pf_gl_get_proc_address_fn)(const char* name);

/** Program-cache load callback: copies the blob stored under key into data (capacity bytes) and
 *  returns its size; 0: no blob. A size above capacity means nothing was copied: pflip calls again
 *  with a buffer of that size. */
typedef size_t (*pf_program_load_fn)(void* user, const char* key, void* data, size_t capacity);
/** Program-cache store callback: keep size bytes of data under key (replacing any blob there). */
typedef void (*pf_program_store_fn)(void* user, const char* key, const void* data, size_t size);

/** A program-binary cache the engine keeps (docs/integration.md "Program-binary cache"): pflip
 *  loads each shader program's driver binary before compiling it and stores what it compiles.
 *  Blobs are checked before use and rebuilt when stale or damaged. Both callbacks NULL: no cache. */
typedef struct pf_program_cache {
    void* user;                   /**< passed back to load and store unchanged */
    pf_program_load_fn load;      /**< optional: fetch a blob by key (NULL: nothing is loaded) */
    pf_program_store_fn store;    /**< optional: keep a blob by key (NULL: nothing is stored) */
} pf_program_cache;

/** @} */

/** @addtogroup pf_simulation
 *  @{ */
/** How particles are splatted onto the grid (P2G). */
typedef enum pf_p2g {
    PF_P2G_FIXED_POINT = 0,  /**< 32-bit fixed-point integer atomics: bit-identical run to run,
                                  overflow detected (PF_FLAG_P2G_OVERFLOW) */
    PF_P2G_FLOAT_ATOMIC = 1, /**< float atomics (GL_NV_shader_atomic_float where present, a
                                  compare-and-swap loop elsewhere): no rounding grid or overflow,
                                  but the sums depend on the order of the atomics (not
                                  bit-identical run to run) */
    PF_P2G_SORTED_GATHER = 2, /**< particles counting-sorted by half cell every substep, then one
                                  gather per face sample summing its particles in a fixed order:
                                  no atomics on hot samples, no rounding grid or overflow, and
                                  bit-identical run to run and for any particle order (several
                                  passes more: docs/accuracy.md) */
    PF_P2G_TILED = 3,        /**< the default: particles counting-sorted by tile of 4^3 cells every
                                  substep, then one workgroup per tile sums its particles in shared
                                  memory and adds each sum to the grid once: PF_P2G_FIXED_POINT's
                                  sums bit for bit (overflow detected the same way) with far fewer
                                  global atomics; 12 bytes more per particle slot */
    PF_P2G_COUNT = 4,
    PF_P2G_FORCE32 = 0x7fffffff
} pf_p2g;

/** Where the pressure's free surface sits (pf_sim_params.free_surface; docs/design.md §4.6a). */
typedef enum pf_free_surface {
    PF_FREE_SURFACE_MARKER_CELL = 0, /**< at the centre of the first air cell (the original's): the
                                          surface moves in whole cells, which damps waves strongly
                                          (about a third of a standing wave's amplitude per period) */
    PF_FREE_SURFACE_GHOST_FLUID = 1, /**< the default: at the liquid's sub-cell surface, estimated from the
                                          particles' P2G weight on each face between a liquid and an air cell
                                          (ghost fluid, Enright et al. 2003): a standing wave loses 5-9% of its
                                          amplitude per period and keeps its period
                                          (docs/accuracy.md). Needs a converged (Krylov) solver */
    PF_FREE_SURFACE_COUNT = 2,
    PF_FREE_SURFACE_FORCE32 = 0x7fffffff
} pf_free_surface;

/** Pressure solvers, from cheapest to most accurate per iteration (docs/accuracy.md). */
typedef enum pf_pressure_solver {
    PF_PRESSURE_SOLVER_JACOBI = 0,   /**< weighted Jacobi (the original), jacobi_omega; a check every 8 sweeps */
    PF_PRESSURE_SOLVER_RBGS = 1,     /**< red-black Gauss-Seidel / SOR (sor_omega); a check every 4 iterations */
    PF_PRESSURE_SOLVER_CG = 2,       /**< conjugate gradients, no preconditioner */
    PF_PRESSURE_SOLVER_PCG = 3,      /**< conjugate gradients, Jacobi (diagonal) preconditioner */
    PF_PRESSURE_SOLVER_MGPCG = 4,    /**< conjugate gradients, multigrid V-cycle preconditioner (McAdams et al. 2010) */
    PF_PRESSURE_SOLVER_MGPCG_GALERKIN = 5, /**< MGPCG whose coarse levels are Galerkin products R A P of the fine
                                          operator, so they see the free surface and the walls: a quarter to half
                                          fewer iterations, but as built a longer frame (a setup each solve, wider
                                          coarse stencils) and about 64 bytes more GPU memory a cell
                                          (docs/notes/2026-12-06-galerkin-coarse-levels.md) */
    PF_PRESSURE_SOLVER_COUNT = 6,
    PF_PRESSURE_SOLVER_FORCE32 = 0x7fffffff
} pf_pressure_solver;

/** Grid-particle velocity transfers (G2P and P2G), cheapest first (docs/design.md §4). */
typedef enum pf_transfer {
    PF_TRANSFER_PIC_FLIP = 0,     /**< PIC/FLIP blend by params.flip_ratio (the original) */
    PF_TRANSFER_APIC = 1,         /**< affine PIC (Jiang et al. 2015): each particle carries a velocity
                                       gradient, so rotation and shear survive the transfers without
                                       FLIP's noise; params.flip_ratio is ignored. 48 bytes more GPU
                                       memory per particle slot, allocated on first use */
    PF_TRANSFER_COUNT = 2,
    PF_TRANSFER_FORCE32 = 0x7fffffff
} pf_transfer;

/** Particle advection integrators: Euler and leapfrog move a particle at its own velocity, RK2 and RK3
 *  through the grid's, RK2_OFFSET at its own along the grid's path (docs/design.md §4, §5). */
typedef enum pf_advection {
    PF_ADVECTION_EULER = 0,       /**< explicit Euler with the particle's velocity (the original) */
    PF_ADVECTION_RK2 = 1,         /**< midpoint rule through the grid velocity (2 samples per substep) */
    PF_ADVECTION_RK3 = 2,         /**< Ralston's third-order Runge-Kutta through the grid velocity
                                       (3 samples per substep) */
    PF_ADVECTION_LEAPFROG = 3,    /**< Euler's move split around the projections (drift-kick-drift): half a
                                       substep's move before a pf_step's first projection, half after its last,
                                       whole moves between, so positions and velocities still meet at the
                                       frame's end. Ballistic motion is exact and the collapse of a column
                                       lags less at large CFL (docs/accuracy.md); one extra advection pass a
                                       pf_step. For large CFLs: the substeps are also at least what the
                                       liquid's strain asks (pf_stats.strain) and at most 0.5 sqrt(cell_size /
                                       |gravity|) long, and the volume correction runs in every substep
                                       (docs/design.md §5) */
    PF_ADVECTION_RK2_OFFSET = 4,  /**< RK2's path through the grid velocity plus the particle's own difference
                                       from it at the substep's start: FLIP's velocity where the grid is uniform,
                                       bent by the grid's change along the path (walls, obstacles); holds the
                                       validation bounds at a larger cfl than Euler (docs/accuracy.md) */
    PF_ADVECTION_COUNT = 5,
    PF_ADVECTION_FORCE32 = 0x7fffffff
} pf_advection;

/** Parameters that may change between steps (pf_set_params). Start from pf_default_sim_params().
 *  Fields marked "0 = default" take their default when zero; with struct_size set, gravity,
 *  flip_ratio, separation, pressure_solver, transfer, advection, p2g and volume_correction take
 *  zero literally, and a zero pressure_iterations or pressure_tolerance is refused as invalid
 *  (with struct_size 0, every zero field takes its default). */
typedef struct pf_sim_params {
    uint32_t struct_size;         /**< sizeof(pf_sim_params) as the caller compiled it (pf_default_sim_params()
                                       sets it); 0: a zero-initialised struct, in which every field (each
                                       element of an array) that is 0 takes its default, gravity, flip_ratio,
                                       separation, pressure_solver and volume_correction included */
    float gravity[3];             /**< body acceleration in m/s^2; default (0, -9.81, 0) */
    float flip_ratio;             /**< 0 = pure PIC, 1 = pure FLIP; default 0.95 (ignored with
                                       PF_TRANSFER_APIC) */
    uint32_t pressure_iterations; /**< most solver iterations per substep (a Jacobi sweep, a red-black pair,
                                       a CG step), 1..10000; default 40 (0 is invalid once struct_size is
                                       set) */
    float jacobi_omega;           /**< Jacobi relaxation weight in (0, 1]; 0 = default 1 (the original) */
    float cfl;                    /**< projection CFL: max cells a particle may cross per substep (one pressure
                                       projection each), (0, 16]; 0 = default 1. Within a substep particles
                                       are traced in sub-steps of at most one cell (RK2/RK3) */
    uint32_t max_substeps;        /**< upper bound on CFL substeps per pf_step, 1..64; 0 = default 16 */
    uint32_t extrapolation_layers;/**< face layers velocity is extended into air beyond the first cell of a
                                       particle's travel (ceil(cfl) - 1 more are added), 1..16; 0 = default 2 */
    uint32_t separation;          /**< 1: pressure is kept >= 0 (Gerszewski & Bargteil 2013), so liquid can
                                       pull away from walls and the lid instead of clinging to them by
                                       suction; 0: pressure of either sign (the original). 0 or 1; default 0
                                       (the accurate preset sets 1). A closed domain full of liquid
                                       (no AIR cell) has nothing to separate into and a pressure defined only
                                       up to a constant: there no sign is imposed (docs/design.md §4.6) */
    pf_pressure_solver pressure_solver; /**< which solver; default PF_PRESSURE_SOLVER_MGPCG (0, which is
                                       PF_PRESSURE_SOLVER_JACOBI once struct_size is set, takes the default
                                       only in a zero-initialised struct). Every solver
                                       stops at pressure_tolerance or after pressure_iterations; with
                                       separation the stationary ones project every update onto p >= 0 and
                                       the CG family runs active-set rounds (docs/design.md §4.6) */
    float pressure_tolerance;     /**< relative residual |b - A p| / |b| at which a solve stops, (0, 1);
                                       default 1e-3 (0 is invalid once struct_size is set). Checked on the
                                       GPU, never waited for */
    float sor_omega;              /**< over-relaxation of PF_PRESSURE_SOLVER_RBGS in (0, 2); 0 = default 1.6 */
    pf_transfer transfer;         /**< grid-particle transfer; default (0) PF_TRANSFER_PIC_FLIP */
    pf_advection advection;       /**< particle integrator; default (0) PF_ADVECTION_EULER */
    float volume_correction;      /**< particle-density volume correction in [0, 1] (docs/design.md §4.5): once
                                       per pf_step (and per 1/60 s of simulated time in longer steps; every
                                       substep with PF_ADVECTION_LEAPFROG),
                                       particles move out of FLUID cells holding more than
                                       fill_particles_per_cell along the gradient of a potential solved for
                                       the fraction volume_correction of that excess, against PIC/FLIP's slow
                                       compression. Positions only: velocities and kinetic energy are never
                                       touched. 0 = off (a zero value is taken literally, like flip_ratio);
                                       default 0.5 */
    pf_p2g p2g;                   /**< particle-to-grid scheme; default PF_P2G_TILED (0 is
                                       PF_P2G_FIXED_POINT: the same sums, more atomics) */
    float volume_loss_limit;      /**< fraction of its rest volume (particle count / fill_particles_per_cell
                                       cells) pf_stats.liquid_volume may lose before PF_FLAG_VOLUME_LOST is
                                       raised and logged, (0, 1]; 0 = default 0.1 */
    float energy_gain_limit;      /**< fraction by which kinetic + potential energy may rise above its reference
                                       (pf_stats.energy_drift; at least every particle lifted one cell) before
                                       PF_FLAG_ENERGY_GAINED is raised and logged, (0, 100]; 0 = default 0.1 */
    pf_free_surface free_surface; /**< free-surface boundary of the pressure; default PF_FREE_SURFACE_GHOST_FLUID
                                       (0, which is PF_FREE_SURFACE_MARKER_CELL once struct_size is set, takes
                                       the default only in a zero-initialised struct). The ghost fluid with
                                       Jacobi or RBGS logs a warning: stopped unconverged they add energy */
} pf_sim_params;

/** Quality presets: measured points of the accuracy-versus-time trade-off (docs/accuracy.md
 *  has their cost and accuracy on an H100). Each is a complete pf_sim_params with the default
 *  gravity; change any field afterwards. */
typedef enum pf_quality {
    PF_QUALITY_FAST = 0,         /**< MGPCG to a relative residual of 3e-3, PF_ADVECTION_RK2_OFFSET at a
                                      projection CFL of 3 (about 2.3 times cheaper than balanced; column
                                      heights less accurate), otherwise balanced (docs/accuracy.md) */
    PF_QUALITY_BALANCED = 1,     /**< the defaults (pf_default_sim_params): MGPCG to a relative residual of
                                      1e-3, separation off, PIC/FLIP 0.95, explicit Euler, volume
                                      correction 0.5, ghost-fluid free surface */
    PF_QUALITY_ACCURATE = 2,     /**< MGPCG to 1e-5 with separation (active-set rounds), APIC; in violent
                                      flows the 4 active-set rounds end near a 2% residual, so its
                                      velocities are less divergence-free than balanced's (docs/accuracy.md) */
    PF_QUALITY_COUNT = 3,
    PF_QUALITY_FORCE32 = 0x7fffffff
} pf_quality;

/** Effects a scene may call for (pf_sim_desc.features, pf_set_features). An effect that is off
 *  builds no shader program (unless named in pf_sim_desc.prepared_features) and dispatches no pass;
 *  its objects (force fields, obstacles) may still be added and edited, and act once it is turned on. */
enum {
    PF_FEATURE_FORCE_FIELDS = 1u << 0, /**< pf_add_force_field: wind, attractors/repulsors, vortices
                                            (one grid pass per substep after gravity) */
    PF_FEATURE_OBSTACLES = 1u << 1,    /**< pf_add_obstacle: boxes, spheres, capsules and SDF textures, static
                                            or moved by the engine (solid cells, faces at the obstacle's velocity,
                                            particles pushed out after advection, pf_get_obstacle_force) */
    PF_FEATURE_EMITTERS = 1u << 2,     /**< pf_add_emitter: boxes, spheres and discs adding particles at a rate,
                                            on the GPU (two passes per step; the live count is kept on the GPU) */
    PF_FEATURE_SINKS = 1u << 3,        /**< pf_add_sink: boxes and spheres removing the particles inside them,
                                            compacted on the GPU (three passes per step) */
    PF_FEATURE_DOMAIN_MOTION = 1u << 4, /**< pf_set_domain_motion: the engine places and moves the whole domain
                                             (a tank on a ship, a glass in a hand); the liquid feels its
                                             acceleration and rotation (one grid pass per substep) */
    PF_FEATURE_VORTICITY_CONFINEMENT = 1u << 5, /**< pf_set_vorticity_confinement: puts back the swirls the grid
                                                     smooths away (two grid passes per substep before the
                                                     pressure solve) */
    PF_FEATURE_WHITEWATER = 1u << 6, /**< pf_set_whitewater: spray, foam and bubbles made where the liquid
                                          traps air, breaks at crests and moves fast; carried by the liquid
                                          without acting on it, aged and removed on the GPU (four passes and two
                                          buffer copies per step), drawn by pf_render_ssf */
    PF_FEATURE_VISCOSITY = 1u << 7, /**< pf_set_viscosity: a viscous liquid, water to honey and beyond (per
                                         substep an implicit solve over the faces after the pressure
                                         projection, three passes per conjugate-gradient iteration, and the
                                         projection again) */
    PF_FEATURE_SURFACE_TENSION = 1u << 8, /**< pf_set_surface_tension: the liquid's surface pulls itself
                                               smooth and round (per substep three grid passes before the
                                               pressure solve; it may raise the substep count) */
    PF_FEATURE_ALL = PF_FEATURE_FORCE_FIELDS | PF_FEATURE_OBSTACLES | PF_FEATURE_EMITTERS |
                     PF_FEATURE_SINKS | PF_FEATURE_DOMAIN_MOTION |
                     PF_FEATURE_VORTICITY_CONFINEMENT | PF_FEATURE_WHITEWATER |
                     PF_FEATURE_VISCOSITY | PF_FEATURE_SURFACE_TENSION /**< every known feature bit */
};

/** @} */

/** @addtogroup pf_lifecycle
 *  @{ */
/** Everything pf_create needs. Start from pf_default_sim_desc(). */
typedef struct pf_sim_desc {
    uint32_t struct_size;         /**< sizeof(pf_sim_desc) as the caller compiled it (pf_default_sim_desc()
                                       sets it); 0: a zero-initialised struct, every zero field takes its
                                       default (params by the pf_sim_params rule) */
    uint32_t header_version;      /**< PF_VERSION of the header the caller compiled against (set by
                                       pf_default_sim_desc()); pf_create refuses another major.minor than
                                       pf_version()'s. 0: not checked (bindings without the C header) */
    uint32_t grid_size[3];        /**< cells per axis, each 1..1024; default 32^3 */
    float cell_size;              /**< cell edge in metres, 1e-5..1e5; default 0.05 */
    float origin[3];              /**< world position of the grid's minimum corner; the whole domain must lie
                                       within 2^16 cells of the world origin (float positions); default 0 */
    uint32_t max_particles;       /**< particle capacity, 1..2^28; default 262144 */
    float max_speed;              /**< speed bound in m/s, (0, 1e4] (particles are clamped to it; sizes the
                                       fixed-point P2G range); 0 = default 100 */
    float density;                /**< liquid density in kg/m^3 (pressure units); 0 = default 1000 */
    uint32_t fill_particles_per_cell; /**< pf_fill_box density: 1, 8, 27 or 64; 0 = default 8 */
    float fill_jitter;            /**< pf_fill_box jitter, fraction of sub-cell spacing 0..1, inside the box's
                                       outermost cell of samples (a regular lattice, so its faces are flat);
                                       default 0.8 */
    uint32_t seed;                /**< seed of pf_fill_box jitter (deterministic); default 1 */
    pf_sim_params params;         /**< step parameters */
    pf_gl_get_proc_address_fn gl_get_proc_address; /**< required: the engine's GL loader */
    pf_logger logger;             /**< optional message sink */
    uint32_t features;            /**< effects to simulate, a set of PF_FEATURE_* bits; default 0 (none:
                                       the core step only). pf_set_features changes it later */
    pf_program_cache program_cache; /**< optional program-binary cache, called during the calls that build
                                         programs (pf_create, pf_set_features, pf_set_params, pf_push,
                                         pf_restore_snapshot, the first render calls) on their thread;
                                         default none */
    uint32_t prepared_features;   /**< PF_FEATURE_* bits whose programs pf_create builds while the effects
                                       stay off, so turning them on later compiles nothing; default 0 */
} pf_sim_desc;

/** Opaque simulation handle. Several may live in one GL context. */
typedef struct pf_sim pf_sim;

/** @} */

/** @addtogroup pf_stats
 *  @{ */
/** Passes timed and counted by pf_get_stats. */
typedef enum pf_pass {
    PF_PASS_CLEAR = 0,            /**< zero the grid accumulators */
    PF_PASS_P2G = 1,              /**< particle-to-grid: the atomic splat ("p2g"), or the sorted gather's
                                       sort and gather ("p2g_sort", "p2g_gather") */
    PF_PASS_GRID_FORCES = 2,      /**< normalise face velocities, apply gravity (and force fields) */
    PF_PASS_CLASSIFY = 3,         /**< mark cells fluid / air (and solid: obstacles, PF_FEATURE_OBSTACLES) */
    PF_PASS_PRESSURE_SETUP = 4,   /**< divergence right-hand side */
    PF_PASS_PRESSURE_SOLVE = 5,   /**< the pressure solver's passes (every solver's, pf_get_pass_stats
                                       names them) */
    PF_PASS_VELOCITY_UPDATE = 6,  /**< subtract pressure gradient, free-slip walls; also holds the
                                       once-per-step accuracy metrics (pass list entry "metrics"),
                                       which measure what the projection left */
    PF_PASS_EXTRAPOLATE = 7,      /**< extend velocity into air faces */
    PF_PASS_G2P = 8,              /**< grid-to-particle transfer (PIC/FLIP blend or APIC) */
    PF_PASS_ADVECT = 9,           /**< move particles, keep them in the domain (and out of obstacles) */
    PF_PASS_COUNT = 10,
    PF_PASS_FORCE32 = 0x7fffffff
} pf_pass;

/** Passes of pf_render_ssf / pf_render_particles, timed in pf_stats.render_gpu_ms. */
typedef enum pf_render_pass {
    PF_RENDER_PASS_SCENE_COPY = 0,   /**< copy the engine's scene colour/depth (no feedback loops) */
    PF_RENDER_PASS_THICKNESS = 1,    /**< additive sphere thickness (compute path: one splat of it and the depth) */
    PF_RENDER_PASS_DEPTH = 2,        /**< nearest sphere depth, occluded by the scene depth (compute path: the
                                          splat's resolve) */
    PF_RENDER_PASS_SMOOTH = 3,       /**< depth smoothing filter (all iterations) */
    PF_RENDER_PASS_SHADE = 4,        /**< normals, refraction, absorption, Fresnel, specular */
    PF_RENDER_PASS_RESOLVE = 5,      /**< write liquid colour and depth into the engine's target */
    PF_RENDER_PASS_PARTICLES = 6,    /**< pf_render_particles sprites */
    PF_RENDER_PASS_COUNT = 7,
    PF_RENDER_PASS_FORCE32 = 0x7fffffff
} pf_render_pass;

/** Bits of pf_stats.flags: conditions detected on the GPU (sticky until pf_clear_flags). */
enum {
    PF_FLAG_P2G_OVERFLOW = 1u << 0,    /**< a fixed-point accumulator overflowed (that step's velocity there is
                                            wrong); the range is widened for later steps (logged) */
    PF_FLAG_NONFINITE = 1u << 1,       /**< a non-finite velocity was found and zeroed */
    PF_FLAG_SPEED_CLAMPED = 1u << 2,   /**< a particle exceeded max_speed and was clamped */
    PF_FLAG_SUBSTEPS_CLAMPED = 1u << 3, /**< CFL wanted more than max_substeps: particles moved more than
                                             cfl cells per substep (the step is less accurate, docs/stability.md),
                                             or surface tension's capillary limit did (it acted weaker) */
    PF_FLAG_VOLUME_LOST = 1u << 4,     /**< liquid_volume (mass over density) fell more than
                                            params.volume_loss_limit below the particles' rest volume
                                            (count / fill_particles_per_cell cells): the liquid has
                                            compressed that much */
    PF_FLAG_ENERGY_GAINED = 1u << 5,   /**< kinetic + potential energy rose more than params.energy_gain_limit
                                            above its reference (pf_stats.energy_drift) with no input: the
                                            step is numerically unsound (e.g. an unconverged pressure solve) */
    PF_FLAG_EMITTERS_FULL = 1u << 6,   /**< emitters wanted more particles than max_particles leaves room for:
                                            emission stopped at capacity (PF_FEATURE_EMITTERS) */
    PF_FLAG_WHITEWATER_FULL = 1u << 7, /**< the liquid made more whitewater than pf_whitewater.capacity holds: the
                                            rest was not made (PF_FEATURE_WHITEWATER) */
    PF_FLAG_BUDGET_LIMITED = 1u << 8   /**< to stay within pf_set_gpu_budget's milliseconds a step took fewer
                                            substeps than params.cfl asks for, or stopped a pressure solve short
                                            of params.pressure_tolerance (the step is less accurate) */
};
/* Each flag is logged once (a warning) when it is raised, and again only after pf_clear_flags. */

/** Measurements. GPU figures lag a few frames (read without stalling). */
typedef struct pf_stats {
    uint32_t struct_size;             /**< in: sizeof(pf_stats) as the caller compiled it (0: this header's);
                                           out: the bytes pf_get_stats wrote */
    uint32_t particle_count;          /**< live particles; with PF_FEATURE_EMITTERS or PF_FEATURE_SINKS on,
                                           where the GPU decides the count, those at the end of step
                                           metrics_step (read back a few steps late) */
    uint32_t max_particles;           /**< capacity */
    uint64_t steps;                   /**< pf_step calls so far */
    uint32_t substeps;                /**< substeps taken by the last pf_step */
    uint32_t flags;                   /**< PF_FLAG_* seen so far */
    float max_speed;                  /**< largest particle speed of the latest GPU readback, m/s */
    float cpu_ms;                     /**< host time spent inside the last pf_step */
    uint64_t gpu_step;                /**< which step gpu_ms belongs to (0: none measured yet) */
    uint32_t gpu_substeps;            /**< substeps of that step */
    float gpu_ms[PF_PASS_COUNT];      /**< GPU ms per pass in that step, summed over substeps */
    float gpu_total_ms;               /**< sum of gpu_ms; with PF_GPU_TIMING_STEP the whole step's time */
    uint32_t dispatches[PF_PASS_COUNT]; /**< compute dispatches per pass in the last pf_step
                                             (0 for a pass that did not run) */
    uint64_t render_frame;            /**< which render call render_gpu_ms belongs to (0: none yet) */
    float render_gpu_ms[PF_RENDER_PASS_COUNT]; /**< GPU ms per render pass of that call */
    float render_gpu_total_ms;        /**< sum of render_gpu_ms */
    float render_cpu_ms;              /**< host time inside the last render call */
    /* Accuracy metrics (docs/design.md §4.11), measured on the GPU once per pf_step and read back
     * a few steps late like max_speed, never waited for. The grid figures are those of the
     * step's last substep after its velocity update; the particle figures those of the step's
     * end. */
    uint64_t metrics_step;            /**< which pf_step the metrics below belong to (0: none measured yet) */
    float divergence_l2;              /**< RMS over FLUID cells of the discrete divergence the pressure
                                           solve left, 1/s: div = (sum of face-velocity differences) / dx */
    float divergence_max;             /**< largest |div| over FLUID cells, 1/s */
    float kinetic_energy;             /**< 0.5 m sum |v|^2 over the particles, J, with the particle mass
                                           m = density * cell_size^3 / fill_particles_per_cell */
    uint32_t fluid_cells;             /**< FLUID cells (cells holding a particle) */
    float fluid_cell_drift;           /**< fluid_cells / (fluid_cells at the first measured step) - 1; the
                                           reference restarts with the first step measured after particles
                                           are added or cleared */
    float particle_volume;            /**< particle-density volume, m^3: cell_size^3 * sum over cells of
                                           min(count / fill_particles_per_cell, 1). Particles beyond the rest
                                           count add nothing, so it falls exactly where particles clump
                                           (compression); thin sheets still count their particles */
    float particle_volume_drift;      /**< particle_volume / (particle_volume at the first measured step) - 1,
                                           same reference as fluid_cell_drift */
    /* The pressure solve of the step max_speed belongs to. */
    uint32_t solver_iterations;       /**< most pressure iterations a substep of that readback's step took */
    float solver_residual;            /**< largest final relative residual |b - A p| / |b| of its substeps
                                           (with separation: of the complementarity problem, design.md §4.6) */
    float potential_energy;           /**< m sum over the particles of -g . x, measured from the domain's corner
                                           lowest along gravity (so >= 0), J; with kinetic_energy the mechanical
                                           energy (a metrics figure: same step as metrics_step) */
    float energy_drift;               /**< (kinetic + potential) / (the same at its reference) - 1; the reference
                                           is the first step measured after particles are added or cleared, a
                                           pf_push or pf_set_params (inputs of energy) */
    float interior_density;           /**< mean particle count of the interior FLUID cells (every face neighbour
                                           FLUID, SOLID or a domain wall) / fill_particles_per_cell, a metrics
                                           figure: 1 at rest density, above 1 where the liquid is compressed;
                                           0 when no cell is interior */
    float liquid_volume;              /**< the liquid's volume at that density, m^3: the particles' rest volume
                                           (particle_count * cell_size^3 / fill_particles_per_cell) /
                                           interior_density (the rest volume when no cell is interior). Unlike
                                           particle_volume it does not count the cell-to-cell spread of particle
                                           counts (sampling noise of a disordered liquid) as lost volume
                                           (docs/design.md §4.11) */
    float liquid_volume_drift;        /**< liquid_volume / (liquid_volume at the first measured step) - 1, same
                                           reference as fluid_cell_drift */
    /* GPU memory held now; buffers made on first use (APIC's affine vectors, another P2G scheme's
     * sort buffers, an effect's records) count from then on. */
    uint64_t gpu_memory_bytes;        /**< every buffer and texture pflip made for this simulation and its
                                           rendering, bytes (the engine's objects are not counted) */
    uint64_t gpu_particle_bytes;      /**< the part of gpu_memory_bytes whose size follows max_particles:
                                           divided by max_particles, the memory of one particle slot */
    uint32_t whitewater_count;        /**< live whitewater particles at the end of step metrics_step
                                           (PF_FEATURE_WHITEWATER; 0 while it is off) */
    float render_whitewater_gpu_ms;   /**< GPU ms of the whitewater layer in render call render_frame
                                           (included in render_gpu_total_ms) */
    uint32_t viscosity_iterations;    /**< most viscosity iterations of a substep in step metrics_step
                                           (PF_FEATURE_VISCOSITY; 0 while it is off) */
    float viscosity_residual;         /**< largest final relative residual |r| / |r0| of a viscosity solve in
                                           that step: above pf_viscosity.tolerance when a solve stopped short
                                           (out of iterations, or issued fewer than it needed: the next steps
                                           issue more) (0 while it is off) */
    float strain;                     /**< the liquid's strain in step metrics_step, 1/s^2: P = (tr(G^2) - tr(G)^2) / 2
                                           of the velocity gradient G summed over interior FLUID cells, divided by
                                           fluid_cells. A straight move of dt compresses the liquid by about dt^2 P
                                           (rotation makes it negative); with PF_ADVECTION_LEAPFROG it sets a lower
                                           bound on the substeps (docs/design.md §5) */
} pf_stats;

/** One entry of the per-pass statistics list (pf_get_pass_stats). The list is built at run
 *  time: it holds the core passes and those of the active solver and effects, so new passes do
 *  not change any struct. */
typedef struct pf_pass_stats {
    const char* name;             /**< stable short name ("p2g", "jacobi", ...); valid until pf_destroy */
    pf_pass group;                /**< the pf_stats.gpu_ms / dispatches entry this pass adds to */
    float gpu_ms;                 /**< GPU ms in the measured step (pf_stats.gpu_step), summed over substeps; a
                                       pass issued alongside another entry's is timed within that entry
                                       ("volume_correction_solve" within the pressure solver's) and reads 0 */
    uint32_t dispatches;          /**< compute dispatches in the last pf_step (0: did not run) */
} pf_pass_stats;

/** @} */

/** @addtogroup pf_rendering
 *  @{ */
/** The simulation's particle buffers, for engines that draw particles themselves. pf_step
 *  ends with glMemoryBarrier(VERTEX_ATTRIB_ARRAY | SHADER_STORAGE | BUFFER_UPDATE), so
 *  they may be read as vertex attributes, storage buffers or copied right after it. */
typedef struct pf_gl_buffers {
    uint32_t positions;           /**< GL buffer: vec4 per particle, xyz = world position, w = 0 */
    uint32_t velocities;          /**< GL buffer: vec4 per particle, xyz = velocity in m/s, w = 0 */
    uint32_t count;               /**< live particles (the first count entries); with PF_FEATURE_EMITTERS or
                                       PF_FEATURE_SINKS on, an upper bound: the GPU decides the live count,
                                       draw with draw_indirect instead */
    uint32_t stride;              /**< bytes between particles: 16 */
    uint32_t draw_indirect;       /**< GL buffer holding, at offset 0, a DrawArraysIndirectCommand
                                       {live count, 1, 0, 0} (glDrawArraysIndirect of the particles as
                                       points) and, at offset 16, {4, live count, 0, 0} (a 4-vertex strip
                                       instanced once per particle); kept current on the GPU, readable by
                                       glDrawArraysIndirect right after pf_step */
} pf_gl_buffers;

/** Kinds of whitewater particle (pf_whitewater_buffers.velocities, w). */
typedef enum pf_whitewater_kind {
    PF_WHITEWATER_SPRAY = 0,      /**< in the air: ballistic */
    PF_WHITEWATER_FOAM = 1,       /**< at the surface: carried by the liquid */
    PF_WHITEWATER_BUBBLE = 2,     /**< inside the liquid: rises */
    PF_WHITEWATER_KIND_FORCE32 = 0x7fffffff
} pf_whitewater_kind;

/** The whitewater's particle buffers (PF_FEATURE_WHITEWATER), for engines that draw it themselves;
 *  readable like pf_gl_buffers right after pf_step. The names stay the same until the capacity
 *  changes; turning the feature off and on again keeps them (and clears the particles). */
typedef struct pf_whitewater_buffers {
    uint32_t positions;           /**< GL buffer: vec4 per particle, xyz = position in the simulation's frame
                                       (like pf_gl_buffers), w = seconds it still lives */
    uint32_t velocities;          /**< GL buffer: vec4 per particle, xyz = velocity in m/s, w = its
                                       pf_whitewater_kind as a float */
    uint32_t capacity;            /**< particle slots in each buffer */
    uint32_t stride;              /**< bytes between particles: 16 */
    uint32_t draw_indirect;       /**< GL buffer holding, at offset 0, a DrawArraysIndirectCommand {live, 1, 0,
                                       0} (points) and, at offset 16, {4, live, 0, 0} (a 4-vertex strip per
                                       particle); the live particles are the first `live` slots */
} pf_whitewater_buffers;

/** The whitewater's buffers. PF_ERROR_INVALID_ARGUMENT for a NULL out; PF_ERROR_INVALID_STATE
 *  while PF_FEATURE_WHITEWATER is off (logged; out untouched). */
PF_API pf_result pf_get_whitewater_buffers(const pf_sim* sim, pf_whitewater_buffers* out);

/** @} */

/** @addtogroup pf_lifecycle
 *  @{ */
/** Library version, PF_VERSION of the build. */
PF_API uint32_t pf_version(void);
/** Short English text for a result code; never NULL. */
PF_API const char* pf_result_string(pf_result result);
/** Stable short name of a pass ("p2g", "pressure_solve", ...); "unknown" if out of range. */
PF_API const char* pf_pass_name(pf_pass pass);

/** Writes the default step parameters for a caller whose pf_sim_params is struct_size bytes
 *  (its struct_size field set to that): the first struct_size bytes only. PF_ERROR_INVALID_ARGUMENT
 *  for a NULL out or a struct_size below 4 or not a multiple of 4. Any thread. */
PF_API pf_result pf_init_sim_params(pf_sim_params* out, uint32_t struct_size);
/** Default step parameters, struct_size set to this header's sizeof. Any thread. */
static inline pf_sim_params pf_default_sim_params(void) {
    pf_sim_params p;
    pf_init_sim_params(&p, (uint32_t)sizeof p);
    return p;
}
/** The step parameters of a quality preset, written as pf_get_params writes (out->struct_size bytes;
 *  0: this header's); PF_ERROR_INVALID_ARGUMENT (out untouched) for an
 *  unknown quality or a NULL out. */
PF_API pf_result pf_quality_params(pf_quality quality, pf_sim_params* out);
/** Writes the default descriptor for a caller whose pf_sim_desc is struct_size bytes (see
 *  pf_init_sim_params); header_version is left 0. Any thread. */
PF_API pf_result pf_init_sim_desc(pf_sim_desc* out, uint32_t struct_size);
/** Default descriptor (32^3 grid of 5 cm cells), struct_size and header_version set for this header;
 *  the caller still sets gl_get_proc_address. Any thread. */
static inline pf_sim_desc pf_default_sim_desc(void) {
    pf_sim_desc d;
    pf_init_sim_desc(&d, (uint32_t)sizeof d);
    d.header_version = PF_VERSION;
    return d;
}

/** Create a simulation in the current GL context. *out is set only on PF_OK.
 *  PF_ERROR_INVALID_ARGUMENT (logged) also for a desc->header_version of another major.minor than
 *  the library's, or a struct_size that is not 0, at least 8 and a multiple of 4. */
PF_API pf_result pf_create(const pf_sim_desc* desc, pf_sim** out);
/** Destroy a simulation and every GL object it made. Needs its context current. PF_OK (NULL is
 *  ignored: PF_OK too); PF_ERROR_INVALID_ARGUMENT, logged through the global logger, for a handle
 *  already destroyed or not made by pf_create (nothing is read through it). */
PF_API pf_result pf_destroy(pf_sim* sim);

/** @} */

/** @addtogroup pf_simulation
 *  @{ */
/** Append n particles; xyz is 3n floats (world positions inside the domain), vel 3n floats or NULL
 *  (zero). All or nothing: on any error nothing is added. With PF_FEATURE_EMITTERS or
 *  PF_FEATURE_SINKS on (the GPU decides the live count) this and pf_fill_box wait for the GPU. */
PF_API pf_result pf_add_particles(pf_sim* sim, const float* xyz, const float* vel, uint32_t n);
/** Fill the box [lo, hi] (clipped to the domain) with jittered particles, fill_particles_per_cell per
 *  cell volume, all with velocity vel (NULL: zero); the box's outermost cell of samples is a regular
 *  lattice, so a filled tank's surface is flat and at rest. All or nothing. */
PF_API pf_result pf_fill_box(pf_sim* sim, const float lo[3], const float hi[3], const float vel[3]);
/** Remove every particle and reset the grid state; parameters are kept. */
PF_API pf_result pf_clear_particles(pf_sim* sim);

/** Advance by frame_dt seconds (0 < frame_dt <= 1) in CFL-limited substeps. */
PF_API pf_result pf_step(pf_sim* sim, float frame_dt);

/** Current step parameters: out->struct_size bytes are written (0: the first layout, 80 bytes;
 *  pf_default_sim_params() sets sizeof), and out->struct_size is set to the bytes written. */
PF_API pf_result pf_get_params(const pf_sim* sim, pf_sim_params* out);
/** Replace the step parameters; validated as in pf_create, nothing changes on error. */
PF_API pf_result pf_set_params(pf_sim* sim, const pf_sim_params* params);

/** Copy particles [first, first+count) to host memory (3 floats each; either pointer may be NULL).
 *  Waits for the GPU: meant for tests, export and gameplay queries, not every frame. */
PF_API pf_result pf_read_particles(pf_sim* sim, uint32_t first, uint32_t count, float* xyz, float* vel);
/** The live particle count, exact. With PF_FEATURE_EMITTERS or PF_FEATURE_SINKS on it waits for the
 *  GPU (pf_stats.particle_count gives it a few steps late without waiting). */
PF_API pf_result pf_get_particle_count(pf_sim* sim, uint32_t* out);
/** The GL buffers holding particles; valid until pf_destroy. Read them, do not resize or delete. */
PF_API pf_result pf_get_gl_buffers(const pf_sim* sim, pf_gl_buffers* out);

/** @} */

/** @addtogroup pf_stats
 *  @{ */
/** Counters and per-pass GPU timings (no stall: timings are from the newest finished step).
 *  out->struct_size bytes are written (0: the first layout, 240 bytes, which ends before
 *  liquid_volume; set it to sizeof(pf_stats)); out->struct_size is set to them. */
PF_API pf_result pf_get_stats(const pf_sim* sim, pf_stats* out);
/** Clear the sticky PF_FLAG_* bits. */
PF_API pf_result pf_clear_flags(pf_sim* sim);
/** Number of entries in the per-pass statistics list (it may grow when parameters or features change). */
PF_API pf_result pf_get_pass_count(const pf_sim* sim, uint32_t* out);
/** Entry `index` (< pf_get_pass_count) of the per-pass statistics list; no stall. */
PF_API pf_result pf_get_pass_stats(const pf_sim* sim, uint32_t index, pf_pass_stats* out);

/** What pf_step's GPU timer queries measure. Each timed pass group is a pair of GL_TIMESTAMP
 *  queries that the GPU executes in line with the passes: on an H100 the per-pass timing of the
 *  default costs about 1 ms of dam_break_1m's 16 ms frame (docs/performance.md), so a shipped game
 *  may time the step as a whole or not at all. Rendering is always timed per pass (a few passes). */
typedef enum pf_gpu_timing {
    PF_GPU_TIMING_PASSES = 0,  /**< the default: every pass group (pf_stats.gpu_ms, pf_get_pass_stats' gpu_ms) */
    PF_GPU_TIMING_STEP = 1,    /**< one pair around the whole step: pf_stats.gpu_total_ms only, every
                                    per-pass time 0 */
    PF_GPU_TIMING_OFF = 2,     /**< none: every simulation GPU time reads 0 (dispatch counts still kept) */
    PF_GPU_TIMING_KERNELS = 3, /**< profiling: every dispatch timed and counted under a pass-list entry
                                    "<pass>:<kernel>" added on first use (each costs a timer pair) */
    PF_GPU_TIMING_COUNT = 4,
    PF_GPU_TIMING_FORCE32 = 0x7fffffff
} pf_gpu_timing;
/** Chooses what the next steps time; times measured before read 0 from now on (pf_stats.gpu_step
 *  0 until a step of the new kind is measured). PF_ERROR_INVALID_ARGUMENT for an unknown value, and
 *  for PF_GPU_TIMING_OFF while a pf_set_gpu_budget budget is set (the budget needs the times). */
PF_API pf_result pf_set_gpu_timing(pf_sim* sim, pf_gpu_timing timing);
/** What pf_step times now (PF_GPU_TIMING_PASSES unless changed). */
PF_API pf_result pf_get_gpu_timing(const pf_sim* sim, pf_gpu_timing* out);
/** GPU milliseconds the engine gives each pf_step; 0 (the default) means no budget. With one, a step
 *  takes no more substeps than fit, judged by the GPU time its own timer queries measured for a recent
 *  step, and when a single substep does not fit it caps the pressure solver's iterations (this needs
 *  the solve's own time: PF_GPU_TIMING_PASSES, the default, or PF_GPU_TIMING_KERNELS); whenever it
 *  does less than params ask it raises PF_FLAG_BUDGET_LIMITED. The substep counts then follow the
 *  GPU's timing, so runs are no longer reproducible. [0, 1e4]; PF_ERROR_INVALID_ARGUMENT otherwise,
 *  and for a budget while pf_set_gpu_timing is PF_GPU_TIMING_OFF (nothing would be measured). */
PF_API pf_result pf_set_gpu_budget(pf_sim* sim, float milliseconds);
/** The budget pf_set_gpu_budget set (0: none). */
PF_API pf_result pf_get_gpu_budget(const pf_sim* sim, float* milliseconds);


/** @} */

/** @addtogroup pf_lifecycle
 *  @{ */
/* ---- handles, the global logger and threading (docs/integration.md §5, §6) ----------------- */

/* Handles. A pf_sim* is an id, not a pointer: it names a slot of a process-wide registry of live
 * simulations and that slot's generation. Every call looks its handle up first, so a destroyed
 * handle (or any value pf_create did not return) gives PF_ERROR_INVALID_ARGUMENT and a message to
 * the global logger, never undefined behaviour; a slot reused by a later simulation has a new
 * generation, so an old handle does not reach it. The registry (and the global logger) is the
 * library's only global state, guarded by a mutex; each simulation's state is its own.
 *
 * Threading. pflip starts no threads. Calls on one simulation must come from the thread on which
 * its GL context is current, one at a time: every call taking a
 * pf_sim*, pf_create and pf_destroy included. Calls on different simulations in different
 * contexts may run on different threads at once. A call on a handle must not race with
 * pf_destroy of that handle on another thread. These may be called from any thread at any time:
 * pf_version, pf_result_string, pf_pass_name, pf_render_pass_name, pf_set_global_logger and the
 * pf_default_* and pf_quality_params functions. */

/** Sets the logger of messages that belong to no simulation: calls on invalid handles, a NULL
 *  pf_create descriptor, pf_quality_params errors. NULL removes it (messages are dropped, the
 *  default). The logger is copied; it may be called from any thread that makes such a call.
 *  Any thread. */
PF_API void pf_set_global_logger(const pf_logger* logger);

/** @} */

/** @addtogroup pf_simulation
 *  @{ */
/* ---- asynchronous readback (docs/integration.md §2) ------------------------------------------ */

/** Most pf_request_particles requests one simulation holds in flight at once. */
#define PF_MAX_PARTICLE_REQUESTS 16

/** Starts copying particles [first, first+count) as they are now (after the last pf_step) into a
 *  buffer of pflip's, on the GPU, without waiting; *out_ticket names the request for
 *  pf_poll_particles. The copy is fenced and flushed; with GL 4.4 / ARB_buffer_storage its buffer
 *  is persistently mapped. Later steps do not change what a request returns.
 *  PF_ERROR_INVALID_ARGUMENT for a NULL out_ticket or a range beyond the live particles (with
 *  PF_FEATURE_EMITTERS or PF_FEATURE_SINKS on, beyond pf_gl_buffers.count, the upper bound the
 *  host knows without waiting: entries past the GPU's live count are then not particles);
 *  PF_ERROR_CAPACITY when PF_MAX_PARTICLE_REQUESTS are in flight. Nothing changes on error. */
PF_API pf_result pf_request_particles(pf_sim* sim, uint32_t first, uint32_t count, uint32_t* out_ticket);
/** Collects a request without ever waiting: PF_NOT_READY (nothing written) while the GPU has not
 *  finished the copy; PF_OK once it has: 3 floats per particle written to xyz and vel (either may
 *  be NULL, both NULL discards the data) and the ticket released. PF_ERROR_INVALID_ARGUMENT (logged)
 *  for a ticket not in flight: never issued, already collected, or another simulation's. */
PF_API pf_result pf_poll_particles(pf_sim* sim, uint32_t ticket, float* xyz, float* vel);

/* ---- snapshots (docs/integration.md §2) ---------------------------------------------------- */

/* A snapshot holds everything that determines a simulation's next steps: its particles
 * (positions, velocities, APIC affine vectors), parameters, features, the effects' objects with
 * their ids, the pressure the next solve starts from, and the step logic's own state (CFL speed
 * estimate, fixed-point P2G range, solver history). Restoring it into the simulation that saved it,
 * or one created with the same grid_size, cell_size, origin, max_speed, density and
 * fill_particles_per_cell, continues bit for bit as the original did from the save (with fixed-point
 * P2G, the default; the substep counts must match too, which they do when each frame's GPU work
 * finishes before the next pf_step, as when the engine waits for vsync). Snapshots are for the same
 * build on the same machine: they carry a magic, a format number, their size and a checksum, and
 * anything else is refused. pf_stats.steps is not restored (it counts pf_step calls). */

/** Bytes pf_save_snapshot needs now (it changes with the particle count, APIC, the effects'
 *  objects). PF_ERROR_INVALID_ARGUMENT for a NULL out. */
PF_API pf_result pf_snapshot_size(const pf_sim* sim, size_t* out);
/** Writes the snapshot (pf_snapshot_size bytes) to buffer; waits for the GPU (a checkpoint, not a
 *  per-frame call). PF_ERROR_INVALID_ARGUMENT for a NULL buffer or a size below pf_snapshot_size. */
PF_API pf_result pf_save_snapshot(pf_sim* sim, void* buffer, size_t size);
/** Replaces the simulation's state by a snapshot's. PF_ERROR_INVALID_ARGUMENT, logged, for a NULL
 *  buffer, a buffer shorter than the snapshot it starts, a wrong magic, format or checksum (a
 *  corrupted buffer), or a snapshot of a simulation with another grid (see above) or with more
 *  particles than max_particles; on any error nothing changes. */
PF_API pf_result pf_restore_snapshot(pf_sim* sim, const void* buffer, size_t size);

/* ---- effects (docs/design.md §9) --------------------------------------------------------------- */

/** Turns effects on or off (a set of PF_FEATURE_* bits). Builds only the programs (none for
 *  pf_sim_desc.prepared_features) and buffers of effects turned on for the first time; particles
 *  and every other state are kept.
 *  PF_ERROR_INVALID_ARGUMENT for unknown bits; on any error nothing changes. */
PF_API pf_result pf_set_features(pf_sim* sim, uint32_t features);
/** The PF_FEATURE_* bits currently on. */
PF_API pf_result pf_get_features(const pf_sim* sim, uint32_t* out);

/** Most force fields one simulation holds. */
#define PF_MAX_FORCE_FIELDS 16
/** Most obstacles one simulation holds. */
#define PF_MAX_OBSTACLES 16
/** Most emitters one simulation holds. */
#define PF_MAX_EMITTERS 16
/** Most sinks one simulation holds. */
#define PF_MAX_SINKS 16

/** Kinds of force field (PF_FEATURE_FORCE_FIELDS). Each adds an acceleration to the liquid's
 *  grid velocity every substep, after gravity. */
typedef enum pf_force_field_type {
    PF_FORCE_FIELD_DIRECTIONAL = 0, /**< wind, everywhere: with drag 0, the uniform acceleration `vector`
                                         (m/s^2); with drag > 0, the liquid's velocity relaxes towards the
                                         wind velocity `vector` (m/s) at rate drag: du/dt = drag (vector - u),
                                         integrated exactly per substep */
    PF_FORCE_FIELD_POINT = 1,       /**< attractor (strength > 0) or repulsor (< 0) at `position`: an
                                         acceleration towards it of strength * (1 - d / radius) m/s^2 at
                                         distance d < radius, 0 beyond */
    PF_FORCE_FIELD_VORTEX = 2,      /**< swirl around the axis through `position` along `vector`: a tangential
                                         acceleration of strength * 4 (r / radius)(1 - r / radius) m/s^2 at
                                         distance r < radius from the axis (peak `strength` at radius / 2),
                                         counter-clockwise seen from the tip of `vector` for strength > 0 */
    PF_FORCE_FIELD_TYPE_COUNT = 3,
    PF_FORCE_FIELD_TYPE_FORCE32 = 0x7fffffff
} pf_force_field_type;

/** One force field. Start from pf_default_force_field(). */
typedef struct pf_force_field {
    uint32_t struct_size;         /**< sizeof(pf_force_field) as the caller compiled it (pf_default_force_field()
                                       sets it; 0: zero-initialised, every zero field takes its default) */
    pf_force_field_type type;     /**< which kind of field (the fields below it uses) */
    float position[3];            /**< POINT: the centre; VORTEX: a point on the axis (world m) */
    float vector[3];              /**< DIRECTIONAL: acceleration (m/s^2) or, with drag > 0, the wind velocity
                                       (m/s); VORTEX: the axis direction (non-zero, normalised internally) */
    float strength;               /**< POINT, VORTEX: peak acceleration in m/s^2 (sign: see the types) */
    float radius;                 /**< POINT, VORTEX: range in m, > 0 */
    float drag;                   /**< DIRECTIONAL: relaxation rate towards the wind in 1/s, >= 0 (0: vector
                                       is an acceleration) */
} pf_force_field;

/** Writes the default force field for a caller whose pf_force_field is struct_size bytes (see the ABI
 *  rules at the top): the first struct_size bytes only. PF_ERROR_INVALID_ARGUMENT for a NULL out or a
 *  struct_size below 4 or not a multiple of 4. Any thread. */
PF_API pf_result pf_init_force_field(pf_force_field* out, uint32_t struct_size);
/** Default force field: DIRECTIONAL with zero acceleration (no effect until edited), radius 1 m, struct_size set. */
static inline pf_force_field pf_default_force_field(void) {
    pf_force_field v;
    pf_init_force_field(&v, (uint32_t)sizeof v);
    return v;
}
/** Adds a force field; *out_id (may be NULL) names it for pf_set_force_field / pf_remove_force_field.
 *  PF_ERROR_INVALID_ARGUMENT for a NULL field, an unknown type, a non-finite value, a radius <= 0
 *  (POINT, VORTEX), a zero vortex axis or a negative drag; PF_ERROR_CAPACITY when
 *  PF_MAX_FORCE_FIELDS are present. Each error is logged; on any error nothing changes. */
PF_API pf_result pf_add_force_field(pf_sim* sim, const pf_force_field* field, uint32_t* out_id);
/** Replaces force field `id`; validated as in pf_add_force_field, nothing changes on error. */
PF_API pf_result pf_set_force_field(pf_sim* sim, uint32_t id, const pf_force_field* field);
/** Removes force field `id` (PF_ERROR_INVALID_ARGUMENT if there is none). */
PF_API pf_result pf_remove_force_field(pf_sim* sim, uint32_t id);

/** Shapes of obstacles (PF_FEATURE_OBSTACLES). */
typedef enum pf_obstacle_shape {
    PF_OBSTACLE_BOX = 0,          /**< half_extents along the local axes */
    PF_OBSTACLE_SPHERE = 1,       /**< radius */
    PF_OBSTACLE_CAPSULE = 2,      /**< radius around the local y segment from -half_height to +half_height */
    PF_OBSTACLE_SDF = 3,          /**< the engine's signed-distance texture sdf_texture over the local box
                                       [-half_extents, half_extents] (placed like a box) */
    PF_OBSTACLE_SHAPE_COUNT = 4,
    PF_OBSTACLE_SHAPE_FORCE32 = 0x7fffffff
} pf_obstacle_shape;

/** One obstacle. Cells whose centre lies inside are solid: free-slip walls whose faces move with the
 *  obstacle's surface (v + w x r); particles that end a substep inside are pushed out along the
 *  distance gradient and leave at least as fast as the surface along its normal. A moving obstacle
 *  is driven by the engine: pf_set_obstacle each frame with its pose and velocities. Start from
 *  pf_default_obstacle(). */
typedef struct pf_obstacle {
    uint32_t struct_size;         /**< sizeof(pf_obstacle) as the caller compiled it (pf_default_obstacle()
                                       sets it; 0: zero-initialised, every zero field takes its default) */
    pf_obstacle_shape shape;      /**< which shape (the size fields below it uses) */
    float position[3];            /**< centre, world m */
    float rotation[4];            /**< orientation as a quaternion (x, y, z, w), normalised internally;
                                       (0, 0, 0, 0) means the identity */
    float half_extents[3];        /**< BOX, SDF: half sizes in m, each > 0 */
    float radius;                 /**< SPHERE, CAPSULE: radius in m, > 0 */
    float half_height;            /**< CAPSULE: half length of the axis segment in m, >= 0 */
    float velocity[3];            /**< linear velocity of the centre in m/s (world); default 0 */
    float angular_velocity[3];    /**< angular velocity about the centre in rad/s (world axes); default 0 */
    uint32_t sdf_texture;         /**< SDF: the engine's GL_TEXTURE_3D (sampled, never changed or deleted: keep it
                                       alive while used), GL_R32F / GL_R16F (distances) or GL_R8 / GL_R16 (2 value
                                       - 1); its texels tile the local box evenly, linear filtering */
    float sdf_scale;              /**< SDF: metres per unit of the texture's distance, > 0; default 1 */
} pf_obstacle;

/** What the liquid does to one obstacle in one step (pf_get_obstacle_force). */
typedef struct pf_obstacle_force {
    float force[3];               /**< N (world): -sum of p n dA over the faces between the obstacle's solid
                                       cells and FLUID cells, mean over the step's substeps; p is gauge
                                       pressure (air 0), so weight and atmosphere are the engine's */
    float torque[3];              /**< N m (world) of the same pressures about the obstacle's position */
    uint64_t step;                /**< the pf_step it belongs to (0: none measured yet) */
} pf_obstacle_force;

/** Writes the default obstacle for a caller whose pf_obstacle is struct_size bytes (see the ABI
 *  rules at the top): the first struct_size bytes only. PF_ERROR_INVALID_ARGUMENT for a NULL out or a
 *  struct_size below 4 or not a multiple of 4. Any thread. */
PF_API pf_result pf_init_obstacle(pf_obstacle* out, uint32_t struct_size);
/** Default obstacle: an axis-aligned box of half extents 0.1 m at the origin (radius 0.1 m), at rest,
 *  sdf_scale 1, struct_size set. */
static inline pf_obstacle pf_default_obstacle(void) {
    pf_obstacle v;
    pf_init_obstacle(&v, (uint32_t)sizeof v);
    return v;
}
/** Adds an obstacle; *out_id (may be NULL) names it for pf_set_obstacle / pf_remove_obstacle.
 *  PF_ERROR_INVALID_ARGUMENT for a NULL obstacle, an unknown shape, a non-finite value, a box or SDF
 *  half extent or radius <= 0, a negative capsule half height, or an SDF whose sdf_scale is <= 0 or
 *  whose sdf_texture is not a 3D texture with storage in one of the four formats; PF_ERROR_CAPACITY
 *  when PF_MAX_OBSTACLES are present. Each error is logged; on any error nothing changes. */
PF_API pf_result pf_add_obstacle(pf_sim* sim, const pf_obstacle* obstacle, uint32_t* out_id);
/** Replaces obstacle `id` (moves it, say); validated as in pf_add_obstacle, nothing changes on error. */
PF_API pf_result pf_set_obstacle(pf_sim* sim, uint32_t id, const pf_obstacle* obstacle);
/** Removes obstacle `id` (PF_ERROR_INVALID_ARGUMENT if there is none). */
PF_API pf_result pf_remove_obstacle(pf_sim* sim, uint32_t id);
/** The newest force and torque of obstacle `id` read back without stalling (a few steps late, like
 *  pf_stats; out->step says which, 0 and zeros while none); PF_ERROR_INVALID_ARGUMENT if no obstacle has id. */
PF_API pf_result pf_get_obstacle_force(const pf_sim* sim, uint32_t id, pf_obstacle_force* out);

/** Shapes of emitters (PF_FEATURE_EMITTERS). */
typedef enum pf_emitter_shape {
    PF_EMITTER_BOX = 0,           /**< new particles anywhere in the box (half_extents along the local axes) */
    PF_EMITTER_SPHERE = 1,        /**< anywhere in the ball of `radius` */
    PF_EMITTER_DISC = 2,          /**< a nozzle: on the disc of `radius` facing local +y, spread over the flight
                                       of one frame from it (at `velocity`, gravity acting, which also adds to
                                       their velocity, the jet narrowing as it speeds up), so a jet leaves it
                                       unbroken, however slow */
    PF_EMITTER_SHAPE_COUNT = 3,
    PF_EMITTER_SHAPE_FORCE32 = 0x7fffffff
} pf_emitter_shape;

/** Units of pf_emitter.rate. */
typedef enum pf_rate_unit {
    PF_RATE_PARTICLES_PER_SECOND = 0, /**< particles per second */
    PF_RATE_VOLUME_PER_SECOND = 1,    /**< m^3 of liquid per second at rest density (fill_particles_per_cell
                                           particles per cell_size^3) */
    PF_RATE_UNIT_COUNT = 2,
    PF_RATE_UNIT_FORCE32 = 0x7fffffff
} pf_rate_unit;

/** One emitter: each pf_step adds rate * frame_dt particles (fractions carry over to later
 *  steps) at random points of its shape, moving at `velocity`. The new particles are written on
 *  the GPU after the live ones, without any readback; when max_particles is reached emission
 *  stops there and PF_FLAG_EMITTERS_FULL is raised. Start from pf_default_emitter(). */
typedef struct pf_emitter {
    uint32_t struct_size;         /**< sizeof(pf_emitter) as the caller compiled it (pf_default_emitter()
                                       sets it; 0: zero-initialised, every zero field takes its default) */
    pf_emitter_shape shape;       /**< box, sphere or disc */
    float position[3];            /**< centre, world m; the whole shape must lie inside the domain */
    float rotation[4];            /**< orientation as a quaternion (x, y, z, w), normalised internally;
                                       (0, 0, 0, 0) means the identity */
    float half_extents[3];        /**< BOX: half sizes in m, each > 0 */
    float radius;                 /**< SPHERE, DISC: radius in m, > 0 */
    float velocity[3];            /**< of the new particles, m/s; |velocity| <= desc.max_speed */
    float rate;                   /**< >= 0 (0 pauses the emitter), in rate_unit */
    pf_rate_unit rate_unit;       /**< particles or m^3 per second */
} pf_emitter;

/** Writes the default emitter for a caller whose pf_emitter is struct_size bytes (see the ABI
 *  rules at the top): the first struct_size bytes only. PF_ERROR_INVALID_ARGUMENT for a NULL out or a
 *  struct_size below 4 or not a multiple of 4. Any thread. */
PF_API pf_result pf_init_emitter(pf_emitter* out, uint32_t struct_size);
/** Default emitter: a sphere of radius 0.1 m at the origin emitting nothing (rate 0) at rest, struct_size set. */
static inline pf_emitter pf_default_emitter(void) {
    pf_emitter v;
    pf_init_emitter(&v, (uint32_t)sizeof v);
    return v;
}
/** Adds an emitter; *out_id (may be NULL) names it for pf_set_emitter / pf_remove_emitter.
 *  PF_ERROR_INVALID_ARGUMENT for a NULL emitter, an unknown shape or rate unit, a non-finite value,
 *  a size <= 0, a shape reaching outside the domain, a negative rate or a velocity above
 *  desc.max_speed; PF_ERROR_CAPACITY when PF_MAX_EMITTERS are present. Each error is logged; on any
 *  error nothing changes. */
PF_API pf_result pf_add_emitter(pf_sim* sim, const pf_emitter* emitter, uint32_t* out_id);
/** Replaces emitter `id` (its carried-over fraction of a particle is kept); validated as in
 *  pf_add_emitter, nothing changes on error. */
PF_API pf_result pf_set_emitter(pf_sim* sim, uint32_t id, const pf_emitter* emitter);
/** Removes emitter `id` (PF_ERROR_INVALID_ARGUMENT if there is none). */
PF_API pf_result pf_remove_emitter(pf_sim* sim, uint32_t id);

/** Shapes of sinks (PF_FEATURE_SINKS). */
typedef enum pf_sink_shape {
    PF_SINK_BOX = 0,              /**< half_extents along the local axes */
    PF_SINK_SPHERE = 1,           /**< radius */
    PF_SINK_SHAPE_COUNT = 2,
    PF_SINK_SHAPE_FORCE32 = 0x7fffffff
} pf_sink_shape;

/** One sink (a drain): at the end of every pf_step the particles inside it are removed and the
 *  survivors compacted on the GPU (the order of the survivors changes; none is lost or
 *  duplicated). It may reach outside the domain (a drain cut by the floor). Start from
 *  pf_default_sink(). */
typedef struct pf_sink {
    uint32_t struct_size;         /**< sizeof(pf_sink) as the caller compiled it (pf_default_sink()
                                       sets it; 0: zero-initialised, every zero field takes its default) */
    pf_sink_shape shape;          /**< box or sphere */
    float position[3];            /**< centre, world m; the shape must overlap the domain */
    float rotation[4];            /**< orientation as a quaternion (x, y, z, w), normalised internally;
                                       (0, 0, 0, 0) means the identity */
    float half_extents[3];        /**< BOX: half sizes in m, each > 0 */
    float radius;                 /**< SPHERE: radius in m, > 0 */
} pf_sink;

/** Writes the default sink for a caller whose pf_sink is struct_size bytes (see the ABI
 *  rules at the top): the first struct_size bytes only. PF_ERROR_INVALID_ARGUMENT for a NULL out or a
 *  struct_size below 4 or not a multiple of 4. Any thread. */
PF_API pf_result pf_init_sink(pf_sink* out, uint32_t struct_size);
/** Default sink: an axis-aligned box of half extents 0.1 m at the origin (radius 0.1 m), struct_size set. */
static inline pf_sink pf_default_sink(void) {
    pf_sink v;
    pf_init_sink(&v, (uint32_t)sizeof v);
    return v;
}
/** Adds a sink; *out_id (may be NULL) names it for pf_set_sink / pf_remove_sink.
 *  PF_ERROR_INVALID_ARGUMENT for a NULL sink, an unknown shape, a non-finite value, a size <= 0 or
 *  a shape that misses the domain; PF_ERROR_CAPACITY when PF_MAX_SINKS are present. Each error is
 *  logged; on any error nothing changes. */
PF_API pf_result pf_add_sink(pf_sim* sim, const pf_sink* sink, uint32_t* out_id);
/** Replaces sink `id`; validated as in pf_add_sink, nothing changes on error. */
PF_API pf_result pf_set_sink(pf_sim* sim, uint32_t id, const pf_sink* sink);
/** Removes sink `id` (PF_ERROR_INVALID_ARGUMENT if there is none). */
PF_API pf_result pf_remove_sink(pf_sim* sim, uint32_t id);

/** Where the engine holds the domain (PF_FEATURE_DOMAIN_MOTION). The simulation's coordinates
 *  (desc.origin, particles, every effect object) are the domain's own frame; a domain point x is
 *  at position + rotation * x in the world, where the renderer draws it. Each pf_step takes the
 *  domain's acceleration as the change of velocity and angular_velocity since the previous
 *  step over that step's frame_dt (zero for the first step after the feature is turned on), and
 *  applies gravity turned into the domain's frame plus the frame's inertial accelerations
 *  (linear, Euler, centrifugal and Coriolis) to the liquid. Start from pf_default_domain_motion(). */
typedef struct pf_domain_motion {
    uint32_t struct_size;         /**< sizeof(pf_domain_motion) as the caller compiled it (pf_default_domain_motion()
                                       sets it; 0: zero-initialised, every zero field takes its default) */
    float position[3];            /**< world position of the domain frame's origin, m */
    float rotation[4];            /**< world orientation as a quaternion (x, y, z, w), normalised internally;
                                       (0, 0, 0, 0) means the identity */
    float velocity[3];            /**< world velocity of the frame's origin, m/s */
    float angular_velocity[3];    /**< world angular velocity of the frame, rad/s, |w| <= 1000 */
} pf_domain_motion;

/** Writes the default domain motion for a caller whose pf_domain_motion is struct_size bytes (see the ABI
 *  rules at the top): the first struct_size bytes only. PF_ERROR_INVALID_ARGUMENT for a NULL out or a
 *  struct_size below 4 or not a multiple of 4. Any thread. */
PF_API pf_result pf_init_domain_motion(pf_domain_motion* out, uint32_t struct_size);
/** The domain at rest where the world is (identity pose, no motion), struct_size set. */
static inline pf_domain_motion pf_default_domain_motion(void) {
    pf_domain_motion v;
    pf_init_domain_motion(&v, (uint32_t)sizeof v);
    return v;
}
/** Sets where the domain is and how it moves, for the next pf_step and the renderer. It may be
 *  set while PF_FEATURE_DOMAIN_MOTION is off (it acts once it is on). PF_ERROR_INVALID_ARGUMENT
 *  for NULL, a non-finite value or |angular_velocity| > 1000 rad/s (logged; nothing changes). */
PF_API pf_result pf_set_domain_motion(pf_sim* sim, const pf_domain_motion* motion);
/** The domain motion last set (pf_default_domain_motion() if never). */
PF_API pf_result pf_get_domain_motion(const pf_sim* sim, pf_domain_motion* out);

/** Vorticity confinement (PF_FEATURE_VORTICITY_CONFINEMENT; Fedkiw, Stam & Jensen 2001): each
 *  substep, before the pressure solve, the liquid gets the acceleration strength * dx * (N x w),
 *  where w is the vorticity (the curl of the grid velocity) at a cell centre and N the unit vector
 *  toward larger |w|, so swirls the grid's interpolation would smooth away keep spinning. Only
 *  cells whose six neighbours are liquid take part (no force at the surface or the walls). It adds
 *  energy: PF_FLAG_ENERGY_GAINED measures from the step it was last on. Start from
 *  pf_default_vorticity_confinement(). */
typedef struct pf_vorticity_confinement {
    uint32_t struct_size;         /**< sizeof(pf_vorticity_confinement) as the caller compiled it
                                       (pf_default_vorticity_confinement() sets it; 0: zero-initialised, every
                                       zero field takes its default) */
    float strength;               /**< epsilon, dimensionless, 0..1; default 0.2. Stable up to 1 at frame dt
                                       1/30 s; above about 0.3 it can spin a coarse vortex up beyond its
                                       starting energy (docs/effects.md) */
} pf_vorticity_confinement;

/** Writes the default vorticity confinement for a caller whose pf_vorticity_confinement is struct_size
 *  bytes (see the ABI rules at the top): the first struct_size bytes only. PF_ERROR_INVALID_ARGUMENT for
 *  a NULL out or a struct_size below 4 or not a multiple of 4. Any thread. */
PF_API pf_result pf_init_vorticity_confinement(pf_vorticity_confinement* out, uint32_t struct_size);
/** Strength 0.2, struct_size set. */
static inline pf_vorticity_confinement pf_default_vorticity_confinement(void) {
    pf_vorticity_confinement v;
    pf_init_vorticity_confinement(&v, (uint32_t)sizeof v);
    return v;
}
/** Sets the confinement's strength for the next pf_step. It may be set while
 *  PF_FEATURE_VORTICITY_CONFINEMENT is off (it acts once it is on). PF_ERROR_INVALID_ARGUMENT for NULL,
 *  a non-finite strength or one outside 0..1 (logged; nothing changes). */
PF_API pf_result pf_set_vorticity_confinement(pf_sim* sim, const pf_vorticity_confinement* confinement);
/** The vorticity confinement last set (pf_default_vorticity_confinement() if never). */
PF_API pf_result pf_get_vorticity_confinement(const pf_sim* sim, pf_vorticity_confinement* out);

/** Whitewater (PF_FEATURE_WHITEWATER; after Ihmsen et al. 2012, "Unified spray, foam and bubbles
 *  for particle-based fluids", with the potentials measured on the grid). Once per step every
 *  liquid cell makes, on average, (trapped_air_rate * I_ta + wave_crest_rate * I_wc) * I_k * dt
 *  particles, where I_ta (air trapped where neighbouring cells move into each other), I_wc (a
 *  convex surface moving outward) and I_k (kinetic energy) are potentials in 0..1 set by the
 *  ranges below. A particle is spray where little liquid surrounds it (ballistic, air drag),
 *  foam at the surface (carried by the liquid) and a bubble inside (buoyant, dragged toward the
 *  liquid's velocity); it lives for a random time within lifetime. Whitewater never acts on the
 *  liquid and is not part of snapshots (a restore clears it). Start from pf_default_whitewater(). */
typedef struct pf_whitewater {
    uint32_t struct_size;         /**< sizeof(pf_whitewater) as the caller compiled it (pf_default_whitewater()
                                       sets it; 0: zero-initialised, every zero field takes its default) */
    uint32_t capacity;            /**< most whitewater particles, 1..2^23; default 262144 (64 bytes of GPU memory
                                       each). Changing it clears the whitewater */
    float trapped_air_rate;       /**< particles per liquid cell per second at full trapped-air and kinetic
                                       potential, 0..10000; default 40 */
    float wave_crest_rate;        /**< particles per liquid cell per second at full wave-crest and kinetic
                                       potential, 0..10000; default 40 */
    float trapped_air_range[2];   /**< m/s: the summed velocity difference of a cell's approaching neighbours
                                       mapped to I_ta 0..1, 0 <= [0] < [1]; default 1..6 */
    float wave_crest_range[2];    /**< the surface's curvature times the cell size (a ridge of radius r cells
                                       has 1/r) mapped to I_wc 0..1, 0 <= [0] < [1]; default 0.25..1 */
    float energy_range[2];        /**< J/kg: half the squared speed mapped to I_k 0..1, 0 <= [0] < [1];
                                       default 0.5..5 */
    float lifetime[2];            /**< seconds, shortest and longest, 0 < [0] <= [1] <= 1000; default 1..3 */
    float bubble_buoyancy;        /**< a bubble's upward acceleration in units of gravity's, 0..100; default 2 */
    float bubble_drag;            /**< 1/s: how fast a bubble takes the liquid's velocity, 0..1000; default 20 */
    float spray_drag;             /**< 1/s: the air's drag on spray, 0..1000; default 0.5 */
} pf_whitewater;

/** Writes the default whitewater for a caller whose pf_whitewater is struct_size bytes (see the ABI
 *  rules at the top). PF_ERROR_INVALID_ARGUMENT for a NULL out or a struct_size below 4 or not a
 *  multiple of 4. Any thread. */
PF_API pf_result pf_init_whitewater(pf_whitewater* out, uint32_t struct_size);
/** The defaults above, struct_size set. */
static inline pf_whitewater pf_default_whitewater(void) {
    pf_whitewater w;
    pf_init_whitewater(&w, (uint32_t)sizeof w);
    return w;
}
/** Sets the whitewater parameters for the next pf_step. It may be set while PF_FEATURE_WHITEWATER is
 *  off (it acts once it is on). PF_ERROR_INVALID_ARGUMENT for NULL or any field outside its range
 *  (logged; nothing changes). */
PF_API pf_result pf_set_whitewater(pf_sim* sim, const pf_whitewater* whitewater);
/** The whitewater parameters last set (pf_default_whitewater() if never). */
PF_API pf_result pf_get_whitewater(const pf_sim* sim, pf_whitewater* out);

/** Viscosity (PF_FEATURE_VISCOSITY; the variational form of Batty & Bridson 2008): each substep,
 *  after the pressure projection, the face velocities u* become the u that minimises
 *  (rho/2)|u - u*|^2 + dt * mu * |strain rate of u|^2 over the liquid, solved implicitly by
 *  conjugate gradients (Jacobi-preconditioned) on the GPU, so it is stable at any viscosity and time
 *  step and only removes energy. The liquid sticks to the domain's walls and to obstacles unless
 *  free_slip is set; its free surface is stress-free (shear stress where a cell edge touches air is
 *  left out). The projection then runs again, so the velocities stay divergence-free (its cost is
 *  pass entry viscosity_projection; coupling_rounds repeats the solve and the projection, nearer the
 *  coupled step). The solve has its own state: it never writes the pressure
 *  solver's status (pf_stats.viscosity_iterations and viscosity_residual report it). Start from
 *  pf_default_viscosity(). */
typedef struct pf_viscosity {
    uint32_t struct_size;         /**< sizeof(pf_viscosity) as the caller compiled it (pf_default_viscosity()
                                       sets it; 0: zero-initialised, every zero field takes its default) */
    float viscosity;              /**< dynamic viscosity mu in Pa s, above 0 and at most 1e5; default 1
                                       (about glycerine's). Water is 1e-3, olive oil 0.08, honey 2..10, molten lava
                                       1e2..1e4 */
    uint32_t iterations;          /**< most conjugate-gradient iterations per substep, 1..1000; default 60
                                       (each is three passes; a solve stops on the GPU once it meets the
                                       tolerance, and steps issue what recent solves needed plus a margin) */
    float tolerance;              /**< relative residual at which the solve stops, 1e-8..0.5; default 1e-3
                                       (a poured rope coils steadily only near 1e-6: docs/effects.md) */
    uint32_t free_slip;           /**< 0 (default): the liquid sticks to the domain's walls and to obstacles (no
                                       slip); 1: it slides along them (no shear stress at a wall) */
    uint32_t coupling_rounds;     /**< rounds of the viscous solve and the projection per substep, 1..16; default
                                       1 (the solve, then the projection once). Each further round feeds the
                                       projection's pressure back into the viscous solve (Uzawa's iteration),
                                       nearer the coupled Stokes step: splitting the two loses accuracy once
                                       nu dt / dx^2 is above 1 (docs/effects.md). Each round costs one more
                                       solve and projection */
} pf_viscosity;

/** Writes the default viscosity for a caller whose pf_viscosity is struct_size bytes (see the ABI
 *  rules at the top): the first struct_size bytes only. PF_ERROR_INVALID_ARGUMENT for a NULL out or a
 *  struct_size below 4 or not a multiple of 4. Any thread. */
PF_API pf_result pf_init_viscosity(pf_viscosity* out, uint32_t struct_size);
/** Viscosity 1 Pa s, 60 iterations, tolerance 1e-3, no slip, 1 coupling round, struct_size set. */
static inline pf_viscosity pf_default_viscosity(void) {
    pf_viscosity v;
    pf_init_viscosity(&v, (uint32_t)sizeof v);
    return v;
}
/** Sets the viscosity for the next pf_step. It may be set while PF_FEATURE_VISCOSITY is off (it acts
 *  once it is on). PF_ERROR_INVALID_ARGUMENT for NULL, a viscosity not finite, not above 0 or above
 *  1e5 Pa s, iterations outside 1..1000, a tolerance outside 1e-8..0.5, free_slip other than 0 or 1,
 *  or coupling_rounds outside 1..16 (logged; nothing changes). More than one coupling round makes
 *  8 bytes of GPU memory per face on first use: PF_ERROR_OUT_OF_MEMORY or PF_ERROR_GL if that fails
 *  (logged; nothing changes). */
PF_API pf_result pf_set_viscosity(pf_sim* sim, const pf_viscosity* viscosity);
/** The viscosity last set (pf_default_viscosity() if never). */
PF_API pf_result pf_get_viscosity(const pf_sim* sim, pf_viscosity* out);

/** Surface tension (PF_FEATURE_SURFACE_TENSION; the ghost-fluid pressure jump of Kang, Fedkiw & Liu
 *  2000): across the free surface the pressure jumps by tension * kappa, kappa the surface's mean
 *  curvature (twice it: 2/R on a sphere of radius R), taken from the particles' density smoothed
 *  over about two cells, so a blob rounds up, a small drop stays round and ripples shorter than the
 *  capillary length oscillate. Features smaller than about two cells are not resolved (kappa is
 *  clamped to 2 / cell_size). The liquid meets walls and obstacles at a right angle. The jump is
 *  explicit: a substep is kept at most half of Brackbill's capillary limit
 *  sqrt(density * cell_size^3 / (4 pi tension)) (Brackbill, Kothe & Zemach 1992) long, so a large
 *  tension on a fine grid costs substeps; where max_substeps cannot cover it, the step uses the
 *  largest tension its substeps are stable at and raises PF_FLAG_SUBSTEPS_CLAMPED. Start from
 *  pf_default_surface_tension(). */
typedef struct pf_surface_tension {
    uint32_t struct_size;         /**< sizeof(pf_surface_tension) as the caller compiled it
                                       (pf_default_surface_tension() sets it; 0: zero-initialised, every
                                       zero field takes its default) */
    float tension;                /**< surface tension coefficient sigma in N/m, 0..1000; default 0.072
                                       (water against air; at game scales a drop rounds visibly only at
                                       tens of N/m: the capillary length sqrt(sigma / (density g)) is
                                       2.7 mm for water) */
} pf_surface_tension;

/** Writes the default surface tension for a caller whose pf_surface_tension is struct_size bytes
 *  (see the ABI rules at the top): the first struct_size bytes only. PF_ERROR_INVALID_ARGUMENT for a
 *  NULL out or a struct_size below 4 or not a multiple of 4. Any thread. */
PF_API pf_result pf_init_surface_tension(pf_surface_tension* out, uint32_t struct_size);
/** Tension 0.072 N/m, struct_size set. */
static inline pf_surface_tension pf_default_surface_tension(void) {
    pf_surface_tension t;
    pf_init_surface_tension(&t, (uint32_t)sizeof t);
    return t;
}
/** Sets the surface tension for the next pf_step. It may be set while PF_FEATURE_SURFACE_TENSION is
 *  off (it acts once it is on). PF_ERROR_INVALID_ARGUMENT for NULL or a tension not finite, below 0
 *  or above 1000 N/m (logged; nothing changes). */
PF_API pf_result pf_set_surface_tension(pf_sim* sim, const pf_surface_tension* tension);
/** The surface tension last set (pf_default_surface_tension() if never). */
PF_API pf_result pf_get_surface_tension(const pf_sim* sim, pf_surface_tension* out);

/** @} */

/** @addtogroup pf_rendering
 *  @{ */
/* ---- rendering into the engine's frame ----------------------------------------------------- */

/** How the engine maps depth: the projection matrix plus the clip-space depth range. */
typedef enum pf_depth_convention {
    PF_DEPTH_STANDARD = 0,       /**< GL default: NDC z in [-1, 1], window depth 0 = near, 1 = far */
    PF_DEPTH_ZERO_TO_ONE = 1,    /**< glClipControl(.., GL_ZERO_TO_ONE): window depth = NDC z, 0 = near */
    PF_DEPTH_REVERSED_Z = 2,     /**< glClipControl(.., GL_ZERO_TO_ONE) with a reversed projection: 1 = near */
    PF_DEPTH_FORCE32 = 0x7fffffff
} pf_depth_convention;

/** The engine's camera for this frame. Matrices are column-major (OpenGL/glm layout). */
typedef struct pf_camera {
    float view[16];              /**< world -> eye */
    float proj[16];              /**< eye -> clip, matching depth_convention */
    int32_t viewport[4];         /**< x, y, width, height in target pixels (width, height 1..16384) */
    float near_plane;            /**< eye distance of the near plane, > 0; nothing nearer is drawn */
    float far_plane;             /**< eye distance of the far plane, > near_plane; nothing farther is drawn */
    pf_depth_convention depth_convention; /**< how proj maps depth */
} pf_camera;

/** Where pflip draws, and the engine's scene it draws over. All objects stay the engine's:
 *  pflip reads them, never resizes or deletes them. */
typedef struct pf_render_target {
    uint32_t framebuffer;        /**< FBO to draw into (0 = default framebuffer); needs a depth attachment
                                      if depth is to be written */
    uint32_t scene_color;        /**< GL_TEXTURE_2D, single-sampled: the scene behind the liquid (refraction);
                                      may be the target's own colour attachment (it is copied first) */
    uint32_t scene_depth;        /**< GL_TEXTURE_2D depth texture of the scene (occlusion), or 0 for none */
    uint32_t environment_cubemap;/**< GL_TEXTURE_CUBE_MAP reflected by the liquid, or 0 for the built-in sky */
} pf_render_target;

/** Depth smoothing filters of pf_render_ssf. */
typedef enum pf_ssf_filter {
    PF_SSF_FILTER_BILATERAL = 0,     /**< the original's separable bilateral filter */
    PF_SSF_FILTER_NARROW_RANGE = 1,  /**< Truong & Yuksel 2018 narrow-range filter */
    PF_SSF_FILTER_NONE = 2,          /**< raw sphere depth */
    PF_SSF_FILTER_FORCE32 = 0x7fffffff
} pf_ssf_filter;

/** Which GPU path runs the screen-space passes (both give the same image). */
typedef enum pf_ssf_path {
    PF_SSF_PATH_COMPUTE = 0,     /**< compute shaders: splatting with image atomics, filters, shading
                                      (fast on compute-heavy GPUs) */
    PF_SSF_PATH_RASTER = 1,      /**< sphere sprites for splatting, fragment shaders on full-screen
                                      triangles for filters and shading */
    PF_SSF_PATH_FORCE32 = 0x7fffffff
} pf_ssf_path;

/** Look and quality of pf_render_ssf. Start from pf_default_ssf_params(). */
typedef struct pf_ssf_params {
    uint32_t struct_size;        /**< sizeof(pf_ssf_params) as the caller compiled it (pf_default_ssf_params()
                                      sets it); 0: every zero field takes its default */
    float particle_radius;       /**< sphere radius in metres, > 0; 0 = default (0.5 cell size) */
    pf_ssf_filter filter;        /**< depth smoothing filter */
    uint32_t filter_radius;      /**< largest filter half-width in pixels, 1..64 (filter_world_radius sets it
                                      per pixel); 0 = default 32 */
    uint32_t filter_iterations;  /**< filter applications, 1..16; 0 = default 1 (bilateral) / 2 (narrow range) */
    float filter_depth_range;    /**< depth difference in metres treated as the same surface, > 0;
                                      0 = default (2 particle radii) */
    float absorption[3];         /**< Beer-Lambert absorption per metre of liquid, RGB, >= 0; default (2.5, 0.84,
                                      0.42) (the thickness is the liquid's depth, not the summed spheres') */
    float refraction;            /**< screen-space refraction offset per unit normal, in fractions of the view */
    float fresnel_f0;            /**< reflectance at normal incidence (water 0.02), 0..1 */
    float specular;              /**< strength of the sun highlight, >= 0 */
    float shininess;             /**< Blinn-Phong exponent of the highlight, 1..10000 */
    float light_direction[3];    /**< world direction towards the sun (normalised internally), non-zero */
    pf_ssf_path path;            /**< compute or raster path (same image) */
    float filter_world_radius;   /**< filter half-width in metres on the liquid: each pixel's half-width in
                                      pixels follows its distance, 1..filter_radius, so the surface is as
                                      smooth at every resolution and distance; > 0; 0 = default (one cell
                                      size) */
    float whitewater_radius;     /**< radius in metres of a whitewater particle's sprite, > 0; 0 = default
                                      (0.25 cell size) */
    float whitewater_opacity;    /**< opacity of one whitewater sprite at its centre, 0..1; 0 = default 0.5 */
    uint32_t skip_whitewater;    /**< nonzero: pf_render_ssf leaves whitewater out (an engine drawing it itself
                                      from pf_get_whitewater_buffers); default 0: drawn while
                                      PF_FEATURE_WHITEWATER is on */
    float spray_radius_scale;    /**< radius of spray (a particle with fewer than half a cell's rest count of
                                      particles in its cell and the six beside it) over particle_radius, in
                                      (0, 1]; 1 draws spray like the rest; 0 = default 0.5 */
} pf_ssf_params;

/** What colours the debug sprites of pf_render_particles. */
typedef enum pf_particle_color {
    PF_PARTICLE_COLOR_SPEED = 0,       /**< |v| */
    PF_PARTICLE_COLOR_VELOCITY_X = 1,  /**< v.x (signed) */
    PF_PARTICLE_COLOR_VELOCITY_Y = 2,  /**< v.y (signed) */
    PF_PARTICLE_COLOR_VELOCITY_Z = 3,  /**< v.z (signed) */
    PF_PARTICLE_COLOR_HEIGHT = 4,      /**< world y */
    PF_PARTICLE_COLOR_UNIFORM = 5,     /**< one colour: color_low */
    PF_PARTICLE_COLOR_FORCE32 = 0x7fffffff
} pf_particle_color;

/** Debug particle view. Start from pf_default_particle_params(). */
typedef struct pf_particle_params {
    uint32_t struct_size;        /**< sizeof(pf_particle_params) as the caller compiled it
                                      (pf_default_particle_params() sets it); 0: every zero field takes its
                                      default */
    float particle_radius;       /**< sprite radius in metres; 0 = default (0.5 cell size) */
    pf_particle_color color_by;  /**< what the colour shows */
    float range[2];              /**< value mapped to color_low .. color_high (range[0] != range[1]) */
    float color_low[3];          /**< RGB at range[0] */
    float color_high[3];         /**< RGB at range[1] */
} pf_particle_params;

/** Writes the default liquid look for a caller whose pf_ssf_params is struct_size bytes (see
 *  pf_init_sim_params). Any thread. */
PF_API pf_result pf_init_ssf_params(pf_ssf_params* out, uint32_t struct_size);
/** Writes the default debug view for a caller whose pf_particle_params is struct_size bytes. Any thread. */
PF_API pf_result pf_init_particle_params(pf_particle_params* out, uint32_t struct_size);
/** Default liquid look: clear water, narrow-range filter one cell wide, compute path. Any thread. */
static inline pf_ssf_params pf_default_ssf_params(void) {
    pf_ssf_params p;
    pf_init_ssf_params(&p, (uint32_t)sizeof p);
    return p;
}
/** Default debug view: coloured by speed 0..3 m/s, blue to white. Any thread. */
static inline pf_particle_params pf_default_particle_params(void) {
    pf_particle_params p;
    pf_init_particle_params(&p, (uint32_t)sizeof p);
    return p;
}
/** Stable short name of a render pass ("thickness", "smooth", ...); "unknown" if out of range. */
PF_API const char* pf_render_pass_name(pf_render_pass pass);

/** Draws the liquid with screen-space fluid rendering into target->framebuffer over the engine's
 *  scene: colour where there is liquid (the rest of the framebuffer is untouched) and, if the
 *  target has a depth attachment, the liquid's depth there. params may be NULL (defaults). */
PF_API pf_result pf_render_ssf(pf_sim* sim, const pf_camera* camera, const pf_render_target* target,
                               const pf_ssf_params* params);
/** Draws every particle as a shaded sphere sprite, depth-tested against the target's depth buffer
 *  (target->scene_color, scene_depth and environment_cubemap are ignored). params may be NULL. */
PF_API pf_result pf_render_particles(pf_sim* sim, const pf_camera* camera, const pf_render_target* target,
                                     const pf_particle_params* params);

/** @} */

/** @addtogroup pf_simulation
 *  @{ */
/* ---- interaction ---------------------------------------------------------------------------- */

/** Adds velocity dv (m/s) to the particles within radius of center, falling off smoothly to 0 at
 *  the rim (splashes, a hand in the water). Takes effect at once on the GPU; speeds stay <= max_speed. */
PF_API pf_result pf_push(pf_sim* sim, const float center[3], float radius, const float dv[3]);

/** @} */

#ifdef __cplusplus
}
#endif

#endif /* PF_PF_H */
