"""ctypes mirrors of the structs and enums of include/pf/pf.h, field for field and in order.

tests/test_layout.py compiles a C program that prints sizeof/offsetof of every struct and field
named here and compares them with ctypes, so a field added to pf.h without being added here (or
a type that differs) fails the tests instead of silently shifting memory.
"""
import ctypes
import enum

c_enum = ctypes.c_int  # C enums whose values fit in int are int-sized (every PF_*_FORCE32 does)


class Result(enum.IntEnum):
    OK = 0
    ERROR_INVALID_ARGUMENT = 1
    ERROR_GL_UNSUPPORTED = 2
    ERROR_SHADER_COMPILE = 3
    ERROR_OUT_OF_MEMORY = 4
    ERROR_CAPACITY = 5
    ERROR_INVALID_STATE = 6
    ERROR_GL = 7
    NOT_READY = 8


class LogLevel(enum.IntEnum):
    ERROR = 0
    WARNING = 1
    INFO = 2


class P2G(enum.IntEnum):
    FIXED_POINT = 0
    FLOAT_ATOMIC = 1
    SORTED_GATHER = 2
    TILED = 3


class FreeSurface(enum.IntEnum):
    MARKER_CELL = 0
    GHOST_FLUID = 1


class GpuTiming(enum.IntEnum):
    PASSES = 0
    STEP = 1
    OFF = 2
    KERNELS = 3


class PressureSolver(enum.IntEnum):
    JACOBI = 0
    RBGS = 1
    CG = 2
    PCG = 3
    MGPCG = 4
    MGPCG_GALERKIN = 5


class Transfer(enum.IntEnum):
    PIC_FLIP = 0
    APIC = 1


class Advection(enum.IntEnum):
    EULER = 0
    RK2 = 1
    RK3 = 2
    LEAPFROG = 3
    RK2_OFFSET = 4


class Quality(enum.IntEnum):
    FAST = 0
    BALANCED = 1
    ACCURATE = 2


class Pass(enum.IntEnum):
    CLEAR = 0
    P2G = 1
    GRID_FORCES = 2
    CLASSIFY = 3
    PRESSURE_SETUP = 4
    PRESSURE_SOLVE = 5
    VELOCITY_UPDATE = 6
    EXTRAPOLATE = 7
    G2P = 8
    ADVECT = 9


PASS_COUNT = 10


class RenderPass(enum.IntEnum):
    SCENE_COPY = 0
    THICKNESS = 1
    DEPTH = 2
    SMOOTH = 3
    SHADE = 4
    RESOLVE = 5
    PARTICLES = 6


RENDER_PASS_COUNT = 7


class Flag(enum.IntFlag):
    P2G_OVERFLOW = 1 << 0
    NONFINITE = 1 << 1
    SPEED_CLAMPED = 1 << 2
    SUBSTEPS_CLAMPED = 1 << 3
    VOLUME_LOST = 1 << 4
    ENERGY_GAINED = 1 << 5
    EMITTERS_FULL = 1 << 6
    WHITEWATER_FULL = 1 << 7
    BUDGET_LIMITED = 1 << 8


class Feature(enum.IntFlag):
    """PF_FEATURE_*: effects a simulation may run (SimDesc.features, Simulation.features)."""
    FORCE_FIELDS = 1 << 0
    OBSTACLES = 1 << 1
    EMITTERS = 1 << 2
    SINKS = 1 << 3
    DOMAIN_MOTION = 1 << 4
    VORTICITY_CONFINEMENT = 1 << 5
    WHITEWATER = 1 << 6
    VISCOSITY = 1 << 7
    SURFACE_TENSION = 1 << 8
    ALL = (FORCE_FIELDS | OBSTACLES | EMITTERS | SINKS | DOMAIN_MOTION | VORTICITY_CONFINEMENT | WHITEWATER | VISCOSITY
           | SURFACE_TENSION)


class ForceFieldType(enum.IntEnum):
    DIRECTIONAL = 0
    POINT = 1
    VORTEX = 2


class ObstacleShape(enum.IntEnum):
    BOX = 0
    SPHERE = 1
    CAPSULE = 2
    SDF = 3


class EmitterShape(enum.IntEnum):
    BOX = 0
    SPHERE = 1
    DISC = 2


class RateUnit(enum.IntEnum):
    PARTICLES_PER_SECOND = 0
    VOLUME_PER_SECOND = 1


class SinkShape(enum.IntEnum):
    BOX = 0
    SPHERE = 1


class WhitewaterKind(enum.IntEnum):
    """pf_whitewater_kind: what a whitewater particle is (WhitewaterBuffers.velocities, w)."""
    SPRAY = 0   # in the air: ballistic
    FOAM = 1    # at the surface: carried by the liquid
    BUBBLE = 2  # inside the liquid: rises


MAX_FORCE_FIELDS = 16
MAX_OBSTACLES = 16
MAX_EMITTERS = 16
MAX_SINKS = 16
MAX_PARTICLE_REQUESTS = 16  # pf_request_particles in flight per simulation


class DepthConvention(enum.IntEnum):
    STANDARD = 0
    ZERO_TO_ONE = 1
    REVERSED_Z = 2


class SsfFilter(enum.IntEnum):
    BILATERAL = 0
    NARROW_RANGE = 1
    NONE = 2


class SsfPath(enum.IntEnum):
    COMPUTE = 0
    RASTER = 1


class ParticleColor(enum.IntEnum):
    SPEED = 0
    VELOCITY_X = 1
    VELOCITY_Y = 2
    VELOCITY_Z = 3
    HEIGHT = 4
    UNIFORM = 5


# void (*pf_log_fn)(void* user, pf_log_level level, pf_result code, const char* message)
LogFn = ctypes.CFUNCTYPE(None, ctypes.c_void_p, c_enum, c_enum, ctypes.c_char_p)
# pf_gl_proc (*pf_gl_get_proc_address_fn)(const char* name); a pf_gl_proc is only passed through.
GetProcAddressFn = ctypes.CFUNCTYPE(ctypes.c_void_p, ctypes.c_char_p)


class _Struct(ctypes.Structure):
    """repr() lists the fields, so a descriptor or stats prints readably."""

    @classmethod
    def output(cls):
        """An instance for a pf_get_* (or pf_quality_params) to fill, its struct_size this layout's:
        0 would mean the first layout, and the library would leave the newer fields out."""
        out = cls()
        if "struct_size" in dict(cls._fields_):
            out.struct_size = ctypes.sizeof(out)
        return out

    def __repr__(self):
        parts = []
        for name, *_ in self._fields_:
            value = getattr(self, name)
            if isinstance(value, ctypes.Array):
                value = list(value)
            parts.append(f"{name}={value!r}")
        return f"{type(self).__name__}({', '.join(parts)})"


class Logger(_Struct):
    _fields_ = [("fn", LogFn), ("user", ctypes.c_void_p)]


ProgramLoadFn = ctypes.CFUNCTYPE(ctypes.c_size_t, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_void_p, ctypes.c_size_t)
ProgramStoreFn = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_void_p, ctypes.c_size_t)


class ProgramCache(_Struct):
    """pf_program_cache: set through Simulation(program_cache=...) (pflip.program_cache)."""

    _fields_ = [("user", ctypes.c_void_p), ("load", ProgramLoadFn), ("store", ProgramStoreFn)]


def _lib():
    from . import _lib as lib_module  # late: _lib imports this module for the prototypes
    return lib_module.lib


class SimParams(_Struct):
    """pf_sim_params. Start from SimParams.default() or SimParams.quality(...)."""

    @classmethod
    def default(cls):
        """pf_default_sim_params()."""
        out = cls()
        _lib().pf_init_sim_params(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    @classmethod
    def quality(cls, quality):
        """pf_quality_params(quality): the preset's complete parameters."""
        out = cls.output()
        code = _lib().pf_quality_params(int(quality), ctypes.byref(out))
        if code != Result.OK:
            from .errors import PflipError
            raise PflipError("pf_quality_params", code, f"unknown quality {quality!r}")
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("gravity", ctypes.c_float * 3),
        ("flip_ratio", ctypes.c_float),
        ("pressure_iterations", ctypes.c_uint32),
        ("jacobi_omega", ctypes.c_float),
        ("cfl", ctypes.c_float),
        ("max_substeps", ctypes.c_uint32),
        ("extrapolation_layers", ctypes.c_uint32),
        ("separation", ctypes.c_uint32),
        ("pressure_solver", c_enum),
        ("pressure_tolerance", ctypes.c_float),
        ("sor_omega", ctypes.c_float),
        ("transfer", c_enum),
        ("advection", c_enum),
        ("volume_correction", ctypes.c_float),
        ("p2g", c_enum),
        ("volume_loss_limit", ctypes.c_float),
        ("energy_gain_limit", ctypes.c_float),
        ("free_surface", c_enum),
    ]


class SimDesc(_Struct):
    """pf_sim_desc. Start from SimDesc.default(); gl_get_proc_address and logger are filled by
    Simulation."""

    @classmethod
    def default(cls):
        """pf_default_sim_desc()."""
        out = cls()
        _lib().pf_init_sim_desc(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("header_version", ctypes.c_uint32),  # 0: not checked (no C header here)
        ("grid_size", ctypes.c_uint32 * 3),
        ("cell_size", ctypes.c_float),
        ("origin", ctypes.c_float * 3),
        ("max_particles", ctypes.c_uint32),
        ("max_speed", ctypes.c_float),
        ("density", ctypes.c_float),
        ("fill_particles_per_cell", ctypes.c_uint32),
        ("fill_jitter", ctypes.c_float),
        ("seed", ctypes.c_uint32),
        ("params", SimParams),
        ("gl_get_proc_address", GetProcAddressFn),
        ("logger", Logger),
        ("features", ctypes.c_uint32),
        ("program_cache", ProgramCache),  # callbacks NULL from Python: no program-binary cache
        ("prepared_features", ctypes.c_uint32),
    ]


class Stats(_Struct):
    """pf_stats."""
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("particle_count", ctypes.c_uint32),
        ("max_particles", ctypes.c_uint32),
        ("steps", ctypes.c_uint64),
        ("substeps", ctypes.c_uint32),
        ("flags", ctypes.c_uint32),
        ("max_speed", ctypes.c_float),
        ("cpu_ms", ctypes.c_float),
        ("gpu_step", ctypes.c_uint64),
        ("gpu_substeps", ctypes.c_uint32),
        ("gpu_ms", ctypes.c_float * PASS_COUNT),
        ("gpu_total_ms", ctypes.c_float),
        ("dispatches", ctypes.c_uint32 * PASS_COUNT),
        ("render_frame", ctypes.c_uint64),
        ("render_gpu_ms", ctypes.c_float * RENDER_PASS_COUNT),
        ("render_gpu_total_ms", ctypes.c_float),
        ("render_cpu_ms", ctypes.c_float),
        ("metrics_step", ctypes.c_uint64),
        ("divergence_l2", ctypes.c_float),
        ("divergence_max", ctypes.c_float),
        ("kinetic_energy", ctypes.c_float),
        ("fluid_cells", ctypes.c_uint32),
        ("fluid_cell_drift", ctypes.c_float),
        ("particle_volume", ctypes.c_float),
        ("particle_volume_drift", ctypes.c_float),
        ("solver_iterations", ctypes.c_uint32),
        ("solver_residual", ctypes.c_float),
        ("potential_energy", ctypes.c_float),
        ("energy_drift", ctypes.c_float),
        ("interior_density", ctypes.c_float),
        ("liquid_volume", ctypes.c_float),
        ("liquid_volume_drift", ctypes.c_float),
        ("gpu_memory_bytes", ctypes.c_uint64),
        ("gpu_particle_bytes", ctypes.c_uint64),
        ("whitewater_count", ctypes.c_uint32),
        ("render_whitewater_gpu_ms", ctypes.c_float),
        ("viscosity_iterations", ctypes.c_uint32),
        ("viscosity_residual", ctypes.c_float),
        ("strain", ctypes.c_float),
    ]


class PassStatsC(_Struct):
    """pf_pass_stats (Simulation.pass_stats() returns PassStats tuples built from it)."""
    _fields_ = [
        ("name", ctypes.c_char_p),
        ("group", c_enum),
        ("gpu_ms", ctypes.c_float),
        ("dispatches", ctypes.c_uint32),
    ]


class GlBuffers(_Struct):
    """pf_gl_buffers."""
    _fields_ = [
        ("positions", ctypes.c_uint32),
        ("velocities", ctypes.c_uint32),
        ("count", ctypes.c_uint32),
        ("stride", ctypes.c_uint32),
        ("draw_indirect", ctypes.c_uint32),
    ]


class WhitewaterBuffers(_Struct):
    """pf_whitewater_buffers (Feature.WHITEWATER): GL names of the whitewater's particle buffers, for
    engines that draw it themselves. positions: vec4 per particle (xyz position, w seconds it still
    lives); velocities: vec4 (xyz m/s, w its WhitewaterKind as a float); capacity slots, stride 16
    bytes; draw_indirect holds {live, 1, 0, 0} at offset 0 and {4, live, 0, 0} at offset 16."""
    _fields_ = [
        ("positions", ctypes.c_uint32),
        ("velocities", ctypes.c_uint32),
        ("capacity", ctypes.c_uint32),
        ("stride", ctypes.c_uint32),
        ("draw_indirect", ctypes.c_uint32),
    ]


class Camera(_Struct):
    """pf_camera: matrices column-major (pflip.camera builds them from numpy)."""
    _fields_ = [
        ("view", ctypes.c_float * 16),
        ("proj", ctypes.c_float * 16),
        ("viewport", ctypes.c_int32 * 4),
        ("near_plane", ctypes.c_float),
        ("far_plane", ctypes.c_float),
        ("depth_convention", c_enum),
    ]


class RenderTarget(_Struct):
    """pf_render_target: GL object names owned by the caller."""
    _fields_ = [
        ("framebuffer", ctypes.c_uint32),
        ("scene_color", ctypes.c_uint32),
        ("scene_depth", ctypes.c_uint32),
        ("environment_cubemap", ctypes.c_uint32),
    ]


class SsfParams(_Struct):
    """pf_ssf_params. Start from SsfParams.default()."""

    @classmethod
    def default(cls):
        """pf_default_ssf_params()."""
        out = cls()
        _lib().pf_init_ssf_params(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("particle_radius", ctypes.c_float),
        ("filter", c_enum),
        ("filter_radius", ctypes.c_uint32),
        ("filter_iterations", ctypes.c_uint32),
        ("filter_depth_range", ctypes.c_float),
        ("absorption", ctypes.c_float * 3),
        ("refraction", ctypes.c_float),
        ("fresnel_f0", ctypes.c_float),
        ("specular", ctypes.c_float),
        ("shininess", ctypes.c_float),
        ("light_direction", ctypes.c_float * 3),
        ("path", c_enum),
        ("filter_world_radius", ctypes.c_float),
        ("whitewater_radius", ctypes.c_float),
        ("whitewater_opacity", ctypes.c_float),
        ("skip_whitewater", ctypes.c_uint32),
        ("spray_radius_scale", ctypes.c_float),
    ]


class ParticleParams(_Struct):
    """pf_particle_params. Start from ParticleParams.default()."""

    @classmethod
    def default(cls):
        """pf_default_particle_params()."""
        out = cls()
        _lib().pf_init_particle_params(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("particle_radius", ctypes.c_float),
        ("color_by", c_enum),
        ("range", ctypes.c_float * 2),
        ("color_low", ctypes.c_float * 3),
        ("color_high", ctypes.c_float * 3),
    ]


class ForceField(_Struct):
    """pf_force_field (PF_FEATURE_FORCE_FIELDS). Start from ForceField.default(): DIRECTIONAL with
    zero acceleration, radius 1 m. pf.h documents what each field means for each type."""

    @classmethod
    def default(cls):
        """pf_default_force_field()."""
        out = cls()
        _lib().pf_init_force_field(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("type", c_enum),
        ("position", ctypes.c_float * 3),
        ("vector", ctypes.c_float * 3),
        ("strength", ctypes.c_float),
        ("radius", ctypes.c_float),
        ("drag", ctypes.c_float),
    ]


class Obstacle(_Struct):
    """pf_obstacle (PF_FEATURE_OBSTACLES). Start from Obstacle.default(): an axis-aligned box of
    half extents 0.1 m at the origin (radius 0.1 m), at rest. rotation is a quaternion (x, y, z, w);
    velocity (m/s) and angular_velocity (rad/s, about position) move its surface. An SDF obstacle
    samples the engine's GL_TEXTURE_3D sdf_texture over the local box [-half_extents, half_extents],
    sdf_scale metres per texture unit."""

    @classmethod
    def default(cls):
        """pf_default_obstacle()."""
        out = cls()
        _lib().pf_init_obstacle(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("shape", c_enum),
        ("position", ctypes.c_float * 3),
        ("rotation", ctypes.c_float * 4),
        ("half_extents", ctypes.c_float * 3),
        ("radius", ctypes.c_float),
        ("half_height", ctypes.c_float),
        ("velocity", ctypes.c_float * 3),
        ("angular_velocity", ctypes.c_float * 3),
        ("sdf_texture", ctypes.c_uint32),
        ("sdf_scale", ctypes.c_float),
    ]


class ObstacleForce(_Struct):
    """pf_obstacle_force: the liquid's pressure force (N) and torque (N m, about the obstacle's
    position) in the step `step` (0: none measured yet), read back a few steps late."""
    _fields_ = [
        ("force", ctypes.c_float * 3),
        ("torque", ctypes.c_float * 3),
        ("step", ctypes.c_uint64),
    ]


class Emitter(_Struct):
    """pf_emitter (PF_FEATURE_EMITTERS). Start from Emitter.default(): a sphere of radius 0.1 m at
    the origin emitting nothing (rate 0). rate is in rate_unit (particles or m^3 per second)."""

    @classmethod
    def default(cls):
        """pf_default_emitter()."""
        out = cls()
        _lib().pf_init_emitter(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("shape", c_enum),
        ("position", ctypes.c_float * 3),
        ("rotation", ctypes.c_float * 4),
        ("half_extents", ctypes.c_float * 3),
        ("radius", ctypes.c_float),
        ("velocity", ctypes.c_float * 3),
        ("rate", ctypes.c_float),
        ("rate_unit", c_enum),
    ]


class Sink(_Struct):
    """pf_sink (PF_FEATURE_SINKS). Start from Sink.default(): an axis-aligned box of half extents
    0.1 m at the origin. Particles inside are removed at the end of every step."""

    @classmethod
    def default(cls):
        """pf_default_sink()."""
        out = cls()
        _lib().pf_init_sink(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("shape", c_enum),
        ("position", ctypes.c_float * 3),
        ("rotation", ctypes.c_float * 4),
        ("half_extents", ctypes.c_float * 3),
        ("radius", ctypes.c_float),
    ]


class DomainMotion(_Struct):
    """pf_domain_motion (PF_FEATURE_DOMAIN_MOTION): where the engine holds the domain and how it
    moves (world position, rotation quaternion (x, y, z, w), velocity, angular velocity). Start
    from DomainMotion.default(): at rest where the world is."""

    @classmethod
    def default(cls):
        """pf_default_domain_motion()."""
        out = cls()
        _lib().pf_init_domain_motion(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("position", ctypes.c_float * 3),
        ("rotation", ctypes.c_float * 4),
        ("velocity", ctypes.c_float * 3),
        ("angular_velocity", ctypes.c_float * 3),
    ]


class VorticityConfinement(_Struct):
    """pf_vorticity_confinement (PF_FEATURE_VORTICITY_CONFINEMENT): puts back the swirls the grid
    smooths away; strength is epsilon, dimensionless, 0..1. Start from
    VorticityConfinement.default(): strength 0.2."""

    @classmethod
    def default(cls):
        """pf_default_vorticity_confinement()."""
        out = cls()
        _lib().pf_init_vorticity_confinement(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("strength", ctypes.c_float),
    ]


class Whitewater(_Struct):
    """pf_whitewater (Feature.WHITEWATER): spray, foam and bubbles made where the liquid traps air,
    breaks at crests and moves fast; carried by the liquid without acting on it. Start from
    Whitewater.default(): capacity 262144, trapped_air_rate and wave_crest_rate 40 (particles per
    liquid cell per second), trapped_air_range 1..6 m/s, wave_crest_range 0.25..1, energy_range
    0.5..5 J/kg, lifetime 1..3 s, bubble_buoyancy 2, bubble_drag 20 /s, spray_drag 0.5 /s. pf.h
    gives each field's range."""

    @classmethod
    def default(cls):
        """pf_default_whitewater()."""
        out = cls()
        _lib().pf_init_whitewater(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("capacity", ctypes.c_uint32),
        ("trapped_air_rate", ctypes.c_float),
        ("wave_crest_rate", ctypes.c_float),
        ("trapped_air_range", ctypes.c_float * 2),
        ("wave_crest_range", ctypes.c_float * 2),
        ("energy_range", ctypes.c_float * 2),
        ("lifetime", ctypes.c_float * 2),
        ("bubble_buoyancy", ctypes.c_float),
        ("bubble_drag", ctypes.c_float),
        ("spray_drag", ctypes.c_float),
    ]


class Viscosity(_Struct):
    """pf_viscosity (Feature.VISCOSITY): a viscous liquid, solved implicitly each substep after the
    pressure projection (which then runs again). viscosity is the dynamic viscosity in Pa s (water 1e-3, honey 2..10), above 0
    and at most 1e5; iterations 1..1000 caps the conjugate-gradient iterations of a substep;
    tolerance 1e-8..0.5 is the relative residual that ends the solve; free_slip 1 lets the liquid
    slide along walls and obstacles (0: it sticks); coupling_rounds 1..16 repeats the viscous solve
    and the projection, feeding the pressure back (more rounds: nearer the coupled Stokes step).
    Start from Viscosity.default(): 1 Pa s, 60 iterations, tolerance 1e-3, no slip, 1 round."""

    @classmethod
    def default(cls):
        """pf_default_viscosity()."""
        out = cls()
        _lib().pf_init_viscosity(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("viscosity", ctypes.c_float),
        ("iterations", ctypes.c_uint32),
        ("tolerance", ctypes.c_float),
        ("free_slip", ctypes.c_uint32),
        ("coupling_rounds", ctypes.c_uint32),
    ]


class SurfaceTension(_Struct):
    """pf_surface_tension (Feature.SURFACE_TENSION): the liquid's surface pulls itself smooth and
    round, a pressure jump of tension times the surface's curvature (three grid passes a substep; a
    large tension on a fine grid raises the substep count). tension is the coefficient in N/m,
    0..1000 (water 0.072; at game scales a drop rounds visibly only at tens of N/m). Start from
    SurfaceTension.default(): 0.072 N/m."""

    @classmethod
    def default(cls):
        """pf_default_surface_tension()."""
        out = cls()
        _lib().pf_init_surface_tension(ctypes.byref(out), ctypes.sizeof(out))  # sets struct_size
        return out

    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("tension", ctypes.c_float),
    ]


# C name of each mirrored struct, for the layout test.
C_NAMES = {
    Logger: "pf_logger",
    ProgramCache: "pf_program_cache",
    SimParams: "pf_sim_params",
    SimDesc: "pf_sim_desc",
    Stats: "pf_stats",
    PassStatsC: "pf_pass_stats",
    GlBuffers: "pf_gl_buffers",
    WhitewaterBuffers: "pf_whitewater_buffers",
    Camera: "pf_camera",
    RenderTarget: "pf_render_target",
    SsfParams: "pf_ssf_params",
    ParticleParams: "pf_particle_params",
    ForceField: "pf_force_field",
    Obstacle: "pf_obstacle",
    Emitter: "pf_emitter",
    Sink: "pf_sink",
    DomainMotion: "pf_domain_motion",
    VorticityConfinement: "pf_vorticity_confinement",
    Whitewater: "pf_whitewater",
    Viscosity: "pf_viscosity",
    SurfaceTension: "pf_surface_tension",
    ObstacleForce: "pf_obstacle_force",
}

# Enums mirrored above with the C prefix of their values, for the layout test (values checked too).
C_ENUMS = {
    Result: "PF_", LogLevel: "PF_LOG_", P2G: "PF_P2G_", FreeSurface: "PF_FREE_SURFACE_", PressureSolver: "PF_PRESSURE_SOLVER_",
    Transfer: "PF_TRANSFER_", Advection: "PF_ADVECTION_", Quality: "PF_QUALITY_", Pass: "PF_PASS_",
    RenderPass: "PF_RENDER_PASS_", Flag: "PF_FLAG_", DepthConvention: "PF_DEPTH_",
    SsfFilter: "PF_SSF_FILTER_", SsfPath: "PF_SSF_PATH_", ParticleColor: "PF_PARTICLE_COLOR_",
    Feature: "PF_FEATURE_", ForceFieldType: "PF_FORCE_FIELD_", ObstacleShape: "PF_OBSTACLE_",
    EmitterShape: "PF_EMITTER_", RateUnit: "PF_RATE_", SinkShape: "PF_SINK_", GpuTiming: "PF_GPU_TIMING_",
    WhitewaterKind: "PF_WHITEWATER_",
}
C_CONSTANTS = {"PF_PASS_COUNT": PASS_COUNT, "PF_RENDER_PASS_COUNT": RENDER_PASS_COUNT,
               "PF_MAX_FORCE_FIELDS": MAX_FORCE_FIELDS, "PF_MAX_OBSTACLES": MAX_OBSTACLES,
               "PF_MAX_EMITTERS": MAX_EMITTERS, "PF_MAX_SINKS": MAX_SINKS,
               "PF_MAX_PARTICLE_REQUESTS": MAX_PARTICLE_REQUESTS}
