/*
 * pflip — real-time PIC/FLIP liquid simulation on the GPU (OpenGL 4.3 compute).
 *
 * The one public header. Pure C99; every struct may be zero-initialised and then filled,
 * but start from pf_default_*() so new fields get sensible values. Every entry point
 * validates its arguments, returns a pf_result and reports failures through the logger.
 *
 * GL contract: pflip never creates a GL context. pf_create() loads GL entry points through
 * the engine's get_proc_address and uses the context current at that moment; every later
 * call on the same pf_sim must find that context (or one sharing its objects) current.
 * Each call restores the GL state it touches (program, buffer bindings, query state).
 */
#ifndef PF_PF_H
#define PF_PF_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

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

/** Library version as major*10000 + minor*100 + patch. */
#define PF_VERSION_MAJOR 0
#define PF_VERSION_MINOR 1
#define PF_VERSION_PATCH 0
#define PF_VERSION (PF_VERSION_MAJOR * 10000 + PF_VERSION_MINOR * 100 + PF_VERSION_PATCH)

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
    pf_log_fn fn;
    void* user;
} pf_logger;

/** Any GL function pointer, as returned by eglGetProcAddress / glfwGetProcAddress. */
typedef void (*pf_gl_proc)(void);
/** The engine's GL loader: returns the entry point called name, or NULL. */
typedef pf_gl_proc (*pf_gl_get_proc_address_fn)(const char* name);

/** Parameters that may change between steps (pf_set_params). Fields marked "0 = default"
 *  take their default when zero; gravity and flip_ratio take zero literally. */
typedef struct pf_sim_params {
    float gravity[3];             /**< body acceleration in m/s^2; default (0, -9.81, 0) */
    float flip_ratio;             /**< 0 = pure PIC, 1 = pure FLIP; default 0.95 */
    uint32_t pressure_iterations; /**< Jacobi iterations per substep, 1..10000; 0 = default 40 */
    float jacobi_omega;           /**< Jacobi relaxation weight in (0, 1]; 0 = default 1 (the original) */
    float cfl;                    /**< max cells a particle may cross per substep, (0, 16]; 0 = default 1 */
    uint32_t max_substeps;        /**< upper bound on CFL substeps per pf_step, 1..64; 0 = default 8 */
    uint32_t extrapolation_layers;/**< face layers velocity is extended into air, 1..16; 0 = default 2 */
} pf_sim_params;

/** Everything pf_create needs. Start from pf_default_sim_desc(). */
typedef struct pf_sim_desc {
    uint32_t grid_size[3];        /**< cells per axis, each 2..1024; default 32^3 */
    float cell_size;              /**< cell edge in metres, > 0; default 0.05 */
    float origin[3];              /**< world position of the grid's minimum corner; default 0 */
    uint32_t max_particles;       /**< particle capacity, 1..2^28; default 262144 */
    float max_speed;              /**< speed bound in m/s (particles are clamped to it; sizes the
                                       fixed-point P2G range); 0 = default 100 */
    float density;                /**< liquid density in kg/m^3 (pressure units); 0 = default 1000 */
    uint32_t fill_particles_per_cell; /**< pf_fill_box density: 1, 8, 27 or 64; 0 = default 8 */
    float fill_jitter;            /**< pf_fill_box jitter, fraction of sub-cell spacing 0..1; default 0.8 */
    uint32_t seed;                /**< seed of pf_fill_box jitter (deterministic); default 1 */
    pf_sim_params params;         /**< step parameters */
    pf_gl_get_proc_address_fn gl_get_proc_address; /**< required: the engine's GL loader */
    pf_logger logger;             /**< optional message sink */
} pf_sim_desc;

/** Opaque simulation handle. Several may live in one GL context. */
typedef struct pf_sim pf_sim;

/** Passes timed and counted by pf_get_stats. */
typedef enum pf_pass {
    PF_PASS_CLEAR = 0,            /**< zero the grid accumulators */
    PF_PASS_P2G = 1,              /**< particle-to-grid splat (fixed-point atomics) */
    PF_PASS_GRID_FORCES = 2,      /**< normalise face velocities, apply gravity */
    PF_PASS_CLASSIFY = 3,         /**< mark cells fluid / air */
    PF_PASS_PRESSURE_SETUP = 4,   /**< divergence right-hand side */
    PF_PASS_PRESSURE_SOLVE = 5,   /**< Jacobi iterations */
    PF_PASS_VELOCITY_UPDATE = 6,  /**< subtract pressure gradient, free-slip walls */
    PF_PASS_EXTRAPOLATE = 7,      /**< extend velocity into air faces */
    PF_PASS_G2P = 8,              /**< grid-to-particle PIC/FLIP blend */
    PF_PASS_ADVECT = 9,           /**< move particles, keep them in the domain */
    PF_PASS_COUNT = 10,
    PF_PASS_FORCE32 = 0x7fffffff
} pf_pass;

/** Bits of pf_stats.flags: conditions detected on the GPU (sticky until pf_clear_flags). */
enum {
    PF_FLAG_P2G_OVERFLOW = 1u << 0,    /**< a fixed-point accumulator would have overflowed */
    PF_FLAG_NONFINITE = 1u << 1,       /**< a non-finite velocity was found and zeroed */
    PF_FLAG_SPEED_CLAMPED = 1u << 2,   /**< a particle exceeded max_speed and was clamped */
    PF_FLAG_SUBSTEPS_CLAMPED = 1u << 3 /**< CFL wanted more than max_substeps */
};

/** Measurements. GPU figures lag a few frames (read without stalling). */
typedef struct pf_stats {
    uint32_t particle_count;          /**< live particles */
    uint32_t max_particles;           /**< capacity */
    uint64_t steps;                   /**< pf_step calls so far */
    uint32_t substeps;                /**< substeps taken by the last pf_step */
    uint32_t flags;                   /**< PF_FLAG_* seen so far */
    float max_speed;                  /**< largest particle speed of the latest GPU readback, m/s */
    float cpu_ms;                     /**< host time spent inside the last pf_step */
    uint64_t gpu_step;                /**< which step gpu_ms belongs to (0: none measured yet) */
    uint32_t gpu_substeps;            /**< substeps of that step */
    float gpu_ms[PF_PASS_COUNT];      /**< GPU ms per pass in that step, summed over substeps */
    float gpu_total_ms;               /**< sum of gpu_ms */
    uint32_t dispatches[PF_PASS_COUNT]; /**< compute dispatches per pass in the last pf_step
                                             (0 for a pass that did not run) */
} pf_stats;

/** The simulation's particle buffers, for engines that draw particles themselves. pf_step
 *  ends with glMemoryBarrier(VERTEX_ATTRIB_ARRAY | SHADER_STORAGE | BUFFER_UPDATE), so
 *  they may be read as vertex attributes, storage buffers or copied right after it. */
typedef struct pf_gl_buffers {
    uint32_t positions;           /**< GL buffer: vec4 per particle, xyz = world position, w = 0 */
    uint32_t velocities;          /**< GL buffer: vec4 per particle, xyz = velocity in m/s, w = 0 */
    uint32_t count;               /**< live particles (the first count entries) */
    uint32_t stride;              /**< bytes between particles: 16 */
} pf_gl_buffers;

/** Library version, PF_VERSION of the build. */
PF_API uint32_t pf_version(void);
/** Short English text for a result code; never NULL. */
PF_API const char* pf_result_string(pf_result result);
/** Stable short name of a pass ("p2g", "pressure_solve", ...); "unknown" if out of range. */
PF_API const char* pf_pass_name(pf_pass pass);

/** Default step parameters. */
PF_API pf_sim_params pf_default_sim_params(void);
/** Default descriptor (32^3 grid of 5 cm cells); the caller still sets gl_get_proc_address. */
PF_API pf_sim_desc pf_default_sim_desc(void);

/** Create a simulation in the current GL context. *out is set only on PF_OK. */
PF_API pf_result pf_create(const pf_sim_desc* desc, pf_sim** out);
/** Destroy a simulation and every GL object it made; NULL is ignored. Needs its context current. */
PF_API void pf_destroy(pf_sim* sim);

/** Append n particles; xyz is 3n floats (world positions inside the domain), vel 3n floats or NULL
 *  (zero). All or nothing: on any error nothing is added. */
PF_API pf_result pf_add_particles(pf_sim* sim, const float* xyz, const float* vel, uint32_t n);
/** Fill the box [lo, hi] (clipped to the domain) with jittered particles, fill_particles_per_cell per
 *  cell volume, all with velocity vel (NULL: zero). All or nothing. */
PF_API pf_result pf_fill_box(pf_sim* sim, const float lo[3], const float hi[3], const float vel[3]);
/** Remove every particle and reset the grid state; parameters are kept. */
PF_API pf_result pf_clear_particles(pf_sim* sim);

/** Advance by frame_dt seconds (0 < frame_dt <= 1) in CFL-limited substeps. */
PF_API pf_result pf_step(pf_sim* sim, float frame_dt);

/** Current step parameters. */
PF_API pf_result pf_get_params(const pf_sim* sim, pf_sim_params* out);
/** Replace the step parameters; validated as in pf_create, nothing changes on error. */
PF_API pf_result pf_set_params(pf_sim* sim, const pf_sim_params* params);

/** Copy particles [first, first+count) to host memory (3 floats each; either pointer may be NULL).
 *  Waits for the GPU: meant for tests, export and gameplay queries, not every frame. */
PF_API pf_result pf_read_particles(pf_sim* sim, uint32_t first, uint32_t count, float* xyz, float* vel);
/** The GL buffers holding particles; valid until pf_destroy. Read them, do not resize or delete. */
PF_API pf_result pf_get_gl_buffers(const pf_sim* sim, pf_gl_buffers* out);

/** Counters and per-pass GPU timings (no stall: timings are from the newest finished step). */
PF_API pf_result pf_get_stats(const pf_sim* sim, pf_stats* out);
/** Clear the sticky PF_FLAG_* bits. */
PF_API pf_result pf_clear_flags(pf_sim* sim);

#ifdef __cplusplus
}
#endif

#endif /* PF_PF_H */
