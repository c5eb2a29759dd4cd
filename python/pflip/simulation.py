"""Simulation: one pf_sim, with every pf_* call that takes a simulation as a method.

All calls must happen on the thread where the simulation's GL context is current (the C API's
rule; a moderngl standalone context is current on the thread that made it).
"""
import collections
import ctypes
import logging
import operator
import warnings

import numpy as np

from . import _types as t
from ._lib import lib
from .errors import PflipError
from .program_cache import _Callbacks

_log = logging.getLogger("pflip")
_log.addHandler(logging.NullHandler())  # a library logs only where the application asks it to
_PY_LEVEL = {t.LogLevel.ERROR: logging.ERROR, t.LogLevel.WARNING: logging.WARNING, t.LogLevel.INFO: logging.INFO}
# Logger callbacks of simulations that were garbage-collected without close(): the C side still
# holds their address, so they must never be freed.
_orphaned_callbacks = []

class Snapshot(bytes):
    """The bytes of pf_save_snapshot, with the force fields and obstacles as Simulation lists them."""

    force_fields = {}
    obstacles = {}


PassStats = collections.namedtuple("PassStats", "name group gpu_ms dispatches")
PassStats.__doc__ = "One entry of pf_get_pass_stats: name, group (a Pass), gpu_ms, dispatches."


def _vec3(v, what):
    a = np.ascontiguousarray(v, dtype=np.float32).reshape(-1)
    if a.shape != (3,):
        raise ValueError(f"{what}: expected 3 numbers, got shape {np.shape(v)}")
    return a


def _ptr(a):
    return None if a is None else a.ctypes.data_as(ctypes.POINTER(ctypes.c_float))


def _points(v, what):
    a = np.ascontiguousarray(v, dtype=np.float32)
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"{what}: expected an (N, 3) array, got shape {a.shape}")
    return a


# Enum fields of each effect struct, which also take the enumerator's name ("sphere").
_ENUM_FIELDS = {
    t.ForceField: {"type": t.ForceFieldType},
    t.Obstacle: {"shape": t.ObstacleShape},
    t.Emitter: {"shape": t.EmitterShape, "rate_unit": t.RateUnit},
    t.Sink: {"shape": t.SinkShape},
    t.DomainMotion: {},
    t.VorticityConfinement: {},
    t.Whitewater: {},
    t.Viscosity: {},
    t.SurfaceTension: {},
}


def _u32(value, function, what):
    """value as a uint32 for a C argument; out of range raises as the library would (ctypes would
    otherwise wrap it silently)."""
    v = int(value)
    if not 0 <= v <= 0xFFFFFFFF:
        raise PflipError(function, t.Result.ERROR_INVALID_ARGUMENT, f"{what} {value!r} is not a uint32")
    return ctypes.c_uint32(v)


def _effect_struct(cls, base, fields, function):
    """A copy of base (a cls; None: cls.default()) with the keyword fields set. Array fields take
    sequences of the right length (ValueError otherwise); type / shape take their enum, an int or
    the enumerator's name ("sphere"). Values are checked by the library, not here, except that an
    unsigned field (Whitewater.capacity) out of uint32 range raises PflipError(ERROR_INVALID_ARGUMENT)
    instead of wrapping silently."""
    if base is None:
        s = cls.default()
    elif isinstance(base, cls):
        s = cls.from_buffer_copy(base)
    else:
        raise TypeError(f"{function}: expected a {cls.__name__}, got {type(base).__name__}")
    ctypes_of = dict(cls._fields_)
    for name, value in fields.items():
        if name not in ctypes_of:
            raise TypeError(f"{function}: {cls.__name__} has no field {name!r}")
        ctype = ctypes_of[name]
        if issubclass(ctype, ctypes.Array):
            a = np.asarray(value, dtype=np.float32).reshape(-1)
            if a.shape != (ctype._length_,):
                raise ValueError(f"{name}: expected {ctype._length_} numbers, got shape {np.shape(value)}")
            value = ctype(*a.tolist())
        elif name in _ENUM_FIELDS[cls] and isinstance(value, str):
            try:
                value = _ENUM_FIELDS[cls][name][value.upper()]
            except KeyError:
                names = ", ".join(m.name.lower() for m in _ENUM_FIELDS[cls][name])
                raise ValueError(f"{name}: unknown {value!r} (one of {names})") from None
        elif ctype is ctypes.c_uint32:
            value = _u32(operator.index(value), function, name).value
        setattr(s, name, value)
    return s


class Simulation:
    """A pflip simulation in the GL context current now (pf_create).

    desc: a SimDesc (default: SimDesc.default()); keyword arguments set its fields, e.g.
    Simulation(grid_size=(64, 32, 32), cell_size=0.05, max_particles=1 << 18, prepared_features=Feature.ALL).
    program_cache: optional, an object with load(key) -> bytes | None and store(key, data), e.g.
    pflip.ProgramCacheDirectory(path): pflip's compiled programs are kept there and a later
    Simulation of the same configuration links them instead of compiling (docs/integration.md §11).
    get_proc_address: the GL loader, a GetProcAddressFn or a Python callable name(bytes) -> int
    (default: libEGL's eglGetProcAddress, right for moderngl's 'egl' backend).
    log: optional callable(level: LogLevel, code: Result, message: str); every message also goes
    to the Python logger "pflip".
    """

    def __init__(self, desc=None, *, get_proc_address=None, log=None, program_cache=None, **fields):
        self._handle = None
        self._errors = []
        self._user_log = log
        d = t.SimDesc.default() if desc is None else t.SimDesc.from_buffer_copy(desc)
        for name, value in fields.items():
            if name not in dict(t.SimDesc._fields_) or name in ("gl_get_proc_address", "logger"):
                raise TypeError(f"Simulation: no descriptor field {name!r}")
            setattr(d, name, value)
        if get_proc_address is None:
            from .egl import get_proc_address as egl_loader
            get_proc_address = egl_loader()
        elif not isinstance(get_proc_address, t.GetProcAddressFn):
            get_proc_address = t.GetProcAddressFn(get_proc_address)
        self._get_proc_address = get_proc_address  # C holds its address: keep it alive
        self._log_fn = t.LogFn(self._on_log)
        d.gl_get_proc_address = get_proc_address
        d.logger = t.Logger(self._log_fn, None)
        # C keeps the callbacks' addresses for the simulation's life (pf_set_features and the first
        # render calls build programs too): held here, like the logger's.
        self._program_cache = _Callbacks(program_cache) if program_cache is not None else None
        if self._program_cache is not None:
            d.program_cache = self._program_cache.struct()
        self._force_fields = {}  # id -> ForceField, as added / last set (the C API has no getter)
        self._obstacles = {}     # id -> Obstacle
        self._emitters = {}      # id -> Emitter
        self._sinks = {}         # id -> Sink
        self._requests = {}      # ticket -> particle count of pf_request_particles in flight
        handle = ctypes.c_void_p()
        self._check("pf_create", lib.pf_create(ctypes.byref(d), ctypes.byref(handle)))
        self._handle = handle
        self.desc = d

    # ---- lifetime -------------------------------------------------------------------------------
    def close(self):
        """pf_destroy: frees every GL object of the simulation (its context must be current)."""
        if self._handle is not None:
            lib.pf_destroy(self._handle)
            self._handle = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        # pf_destroy needs the GL context current on this thread, which a finaliser cannot know:
        # an unclosed simulation is leaked (with a warning), never destroyed from here.
        if getattr(self, "_handle", None) is not None:
            _orphaned_callbacks.append((self._log_fn, self._program_cache))
            warnings.warn("pflip.Simulation was not closed; its GL objects leak", ResourceWarning)

    @property
    def closed(self):
        return self._handle is None

    # ---- errors and the logger ------------------------------------------------------------------
    def _on_log(self, _user, level, code, message):
        text = message.decode("utf-8", "replace") if message else ""
        if level == t.LogLevel.ERROR:
            self._errors.append((code, text))
        _log.log(_PY_LEVEL.get(level, logging.INFO), "%s", text)
        if self._user_log is not None:
            try:
                self._user_log(t.LogLevel(level), t.Result(code), text)
            except Exception:  # an exception must not unwind through C
                _log.exception("pflip: the log callback raised")

    def _check(self, function, code):
        errors, self._errors = self._errors, []
        if code == t.Result.OK:
            return
        message = next((m for c, m in reversed(errors) if c == code), None)
        if message is None:
            message = lib.pf_result_string(code).decode()
        raise PflipError(function, code, message)

    def _call(self, function, *args):
        if self._handle is None:
            raise PflipError(function, t.Result.ERROR_INVALID_STATE, "the simulation is closed")
        self._errors = []
        self._check(function, getattr(lib, function)(self._handle, *args))

    # ---- particles ------------------------------------------------------------------------------
    def fill_box(self, lo, hi, velocity=None):
        """pf_fill_box: jittered particles in [lo, hi] (clipped to the domain)."""
        lo, hi = _vec3(lo, "lo"), _vec3(hi, "hi")
        vel = None if velocity is None else _vec3(velocity, "velocity")
        self._call("pf_fill_box", _ptr(lo), _ptr(hi), _ptr(vel))

    def add_particles(self, positions, velocities=None):
        """pf_add_particles: positions and velocities are (N, 3) arrays (velocities None: zero)."""
        xyz = _points(positions, "positions")
        vel = None if velocities is None else _points(velocities, "velocities")
        if vel is not None and vel.shape != xyz.shape:
            raise ValueError(f"velocities: shape {vel.shape} differs from positions {xyz.shape}")
        self._call("pf_add_particles", _ptr(xyz), _ptr(vel), ctypes.c_uint32(len(xyz)))

    def clear_particles(self):
        """pf_clear_particles: no particles, grid state reset, parameters kept."""
        self._call("pf_clear_particles")

    def read_particles(self, first=0, count=None, positions=True, velocities=True):
        """pf_read_particles (waits for the GPU): (positions, velocities) as (count, 3) float32
        arrays; one not asked for is None. count defaults to every live particle from first."""
        if count is None:
            count = max(self.particle_count - first, 0)
        xyz = np.empty((count, 3), np.float32) if positions else None
        vel = np.empty((count, 3), np.float32) if velocities else None
        self._call("pf_read_particles", ctypes.c_uint32(first), ctypes.c_uint32(count), _ptr(xyz), _ptr(vel))
        return xyz, vel

    def request_particles(self, first=0, count=None):
        """pf_request_particles: starts a fenced copy of particles [first, first + count) as they
        are now and returns its ticket at once (count defaults to every live particle from first)."""
        if count is None:
            count = max(self.particle_count - first, 0)
        ticket = ctypes.c_uint32()
        self._call("pf_request_particles", ctypes.c_uint32(first), ctypes.c_uint32(count), ctypes.byref(ticket))
        self._requests[ticket.value] = count
        return ticket.value

    def poll_particles(self, ticket, positions=True, velocities=True):
        """pf_poll_particles, never waiting: None while the copy is in flight, else (positions,
        velocities) as in read_particles, and the ticket is released."""
        if ticket not in self._requests:
            raise PflipError("pf_poll_particles", t.Result.ERROR_INVALID_ARGUMENT, f"ticket {ticket} is not in flight")
        count = self._requests[ticket]
        xyz = np.empty((count, 3), np.float32) if positions else None
        vel = np.empty((count, 3), np.float32) if velocities else None
        if self._handle is None:
            raise PflipError("pf_poll_particles", t.Result.ERROR_INVALID_STATE, "the simulation is closed")
        self._errors = []
        code = lib.pf_poll_particles(self._handle, ctypes.c_uint32(ticket), _ptr(xyz), _ptr(vel))
        if code == t.Result.NOT_READY:
            return None
        self._check("pf_poll_particles", code)
        del self._requests[ticket]
        return xyz, vel

    def save_snapshot(self):
        """pf_save_snapshot: everything that determines the next steps, as bytes (waits for the GPU)."""
        size = ctypes.c_size_t()
        self._call("pf_snapshot_size", ctypes.byref(size))
        buf = ctypes.create_string_buffer(size.value)
        self._call("pf_save_snapshot", buf, ctypes.c_size_t(size.value))
        snap = Snapshot(buf.raw)
        snap.force_fields = dict(self._force_fields)  # the Python-side mirrors of the object lists
        snap.obstacles = dict(self._obstacles)
        return snap

    def restore_snapshot(self, data):
        """pf_restore_snapshot: back to the state save_snapshot returned; a damaged or foreign
        snapshot raises PflipError and changes nothing."""
        raw = bytes(data)
        buf = ctypes.create_string_buffer(raw, len(raw))
        self._call("pf_restore_snapshot", buf, ctypes.c_size_t(len(raw)))
        if isinstance(data, Snapshot):  # plain bytes leave the force_fields / obstacles mirrors as they are
            self._force_fields = dict(data.force_fields)
            self._obstacles = dict(data.obstacles)

    @property
    def particle_count(self):
        """pf_get_particle_count: the exact live count (waits for the GPU while emitters or sinks
        are on)."""
        out = ctypes.c_uint32()
        self._call("pf_get_particle_count", ctypes.byref(out))
        return out.value

    def push(self, center, radius, dv):
        """pf_push: add velocity dv to the particles within radius of center (smooth fall-off)."""
        self._call("pf_push", _ptr(_vec3(center, "center")), ctypes.c_float(radius), _ptr(_vec3(dv, "dv")))

    # ---- stepping and parameters ----------------------------------------------------------------
    def step(self, frame_dt=1.0 / 60.0):
        """pf_step: advance frame_dt seconds (0 < frame_dt <= 1) in CFL substeps."""
        self._call("pf_step", ctypes.c_float(frame_dt))

    @property
    def params(self):
        """pf_get_params (a copy: change it and assign it back)."""
        out = t.SimParams.output()
        self._call("pf_get_params", ctypes.byref(out))
        return out

    @params.setter
    def params(self, value):
        """pf_set_params: validated; nothing changes when it raises."""
        self._call("pf_set_params", ctypes.byref(value))

    def set_quality(self, quality):
        """The parameters of a quality preset (pf_quality_params), keeping this gravity."""
        p = t.SimParams.quality(quality)
        p.gravity = self.params.gravity
        self.params = p

    # ---- measurements ---------------------------------------------------------------------------
    @property
    def gpu_timing(self):
        """pf_get_gpu_timing: what pf_step's GPU timer queries measure (a GpuTiming)."""
        out = t.c_enum()
        self._call("pf_get_gpu_timing", ctypes.byref(out))
        return t.GpuTiming(out.value)

    @gpu_timing.setter
    def gpu_timing(self, value):
        """pf_set_gpu_timing: GpuTiming.PASSES (every pass group), STEP (the step as a whole:
        stats().gpu_total_ms only), OFF or KERNELS (profiling: every dispatch under a pass_stats()
        entry "<pass>:<kernel>"); an unknown value raises PflipError(ERROR_INVALID_ARGUMENT)."""
        v = int(value)
        if not 0 <= v <= 0x7FFFFFFF:  # a C enum's range: the library sees the rest
            raise PflipError("pf_set_gpu_timing", t.Result.ERROR_INVALID_ARGUMENT, f"timing {value!r} is not a pf_gpu_timing")
        self._call("pf_set_gpu_timing", t.c_enum(v))

    @property
    def gpu_budget(self):
        """pf_get_gpu_budget: the GPU milliseconds each step may take (0: no budget)."""
        out = ctypes.c_float()
        self._call("pf_get_gpu_budget", ctypes.byref(out))
        return out.value

    @gpu_budget.setter
    def gpu_budget(self, milliseconds):
        """pf_set_gpu_budget: steps take no more substeps than fit, cap the solver when one does
        not, and raise Flag.BUDGET_LIMITED when they do less than the parameters ask; 0 removes the
        budget. Out of [0, 1e4], or with GPU timing off: PflipError(ERROR_INVALID_ARGUMENT)."""
        self._call("pf_set_gpu_budget", ctypes.c_float(milliseconds))

    def stats(self):
        """pf_get_stats (no stall: GPU figures lag a few steps)."""
        out = t.Stats.output()
        self._call("pf_get_stats", ctypes.byref(out))
        return out

    def clear_flags(self):
        """pf_clear_flags: clear the sticky Flag bits of stats().flags."""
        self._call("pf_clear_flags")

    def pass_stats(self):
        """pf_get_pass_count / pf_get_pass_stats: the runtime pass list as PassStats tuples."""
        n = ctypes.c_uint32()
        self._call("pf_get_pass_count", ctypes.byref(n))
        out = []
        entry = t.PassStatsC()
        for i in range(n.value):
            self._call("pf_get_pass_stats", ctypes.c_uint32(i), ctypes.byref(entry))
            out.append(PassStats(entry.name.decode(), t.Pass(entry.group), entry.gpu_ms, entry.dispatches))
        return out

    def gl_buffers(self):
        """pf_get_gl_buffers: the GL names of the particle buffers (vec4 per particle)."""
        out = t.GlBuffers.output()
        self._call("pf_get_gl_buffers", ctypes.byref(out))
        return out

    # ---- effects (force fields, obstacles) -----------------------------------------------------
    @property
    def features(self):
        """pf_get_features: the Feature bits on now."""
        out = ctypes.c_uint32()
        self._call("pf_get_features", ctypes.byref(out))
        return t.Feature(out.value)

    @features.setter
    def features(self, value):
        """pf_set_features: turn effects on or off (a set of Feature bits). Particles and every other
        state are kept; unknown bits raise PflipError(ERROR_INVALID_ARGUMENT) and change nothing."""
        self.set_features(value)

    def set_features(self, features):
        """pf_set_features (the features property's setter)."""
        self._call("pf_set_features", _u32(features, "pf_set_features", "features"))

    @property
    def force_fields(self):
        """{id: ForceField} of the fields added and not removed, as last added or set (copies)."""
        return {i: t.ForceField.from_buffer_copy(f) for i, f in self._force_fields.items()}

    def add_force_field(self, field=None, **fields):
        """pf_add_force_field: field (a ForceField; default ForceField.default()) with the keyword
        fields set, e.g. add_force_field(vector=(2, 0, 0)) for a wind of 2 m/s^2 along +x or
        add_force_field(type="point", position=c, strength=6, radius=0.5). Returns its id. Bad values
        raise PflipError(ERROR_INVALID_ARGUMENT), a full set (MAX_FORCE_FIELDS) ERROR_CAPACITY; on
        any error nothing changes. Fields act while Feature.FORCE_FIELDS is on."""
        f = _effect_struct(t.ForceField, field, fields, "pf_add_force_field")
        out = ctypes.c_uint32()
        self._call("pf_add_force_field", ctypes.byref(f), ctypes.byref(out))
        self._force_fields[out.value] = f
        return out.value

    def set_force_field(self, field_id, field=None, **fields):
        """pf_set_force_field: replace field field_id by field (default: the field as it is now) with
        the keyword fields set, e.g. set_force_field(i, strength=3). Validated as in add_force_field;
        an unknown id raises PflipError(ERROR_INVALID_ARGUMENT)."""
        fid = _u32(field_id, "pf_set_force_field", "id")
        base = self._force_fields.get(fid.value) if field is None else field
        f = _effect_struct(t.ForceField, base, fields, "pf_set_force_field")
        self._call("pf_set_force_field", fid, ctypes.byref(f))
        self._force_fields[fid.value] = f

    def remove_force_field(self, field_id):
        """pf_remove_force_field; an unknown id raises PflipError(ERROR_INVALID_ARGUMENT). Ids are
        not reused."""
        fid = _u32(field_id, "pf_remove_force_field", "id")
        self._call("pf_remove_force_field", fid)
        self._force_fields.pop(fid.value, None)

    @property
    def obstacles(self):
        """{id: Obstacle} of the obstacles added and not removed, as last added or set (copies)."""
        return {i: t.Obstacle.from_buffer_copy(o) for i, o in self._obstacles.items()}

    def add_obstacle(self, obstacle=None, **fields):
        """pf_add_obstacle: obstacle (an Obstacle; default Obstacle.default()) with the keyword fields
        set, e.g. add_obstacle(shape="sphere", position=(0.4, 0.3, 0.4), radius=0.1). Returns its id.
        Bad values raise PflipError(ERROR_INVALID_ARGUMENT), a full set (MAX_OBSTACLES)
        ERROR_CAPACITY; on any error nothing changes. Obstacles act while Feature.OBSTACLES is on."""
        o = _effect_struct(t.Obstacle, obstacle, fields, "pf_add_obstacle")
        out = ctypes.c_uint32()
        self._call("pf_add_obstacle", ctypes.byref(o), ctypes.byref(out))
        self._obstacles[out.value] = o
        return out.value

    def set_obstacle(self, obstacle_id, obstacle=None, **fields):
        """pf_set_obstacle: replace (move, resize) obstacle obstacle_id; obstacle defaults to the
        obstacle as it is now, e.g. set_obstacle(i, position=p). Validated as in add_obstacle."""
        oid = _u32(obstacle_id, "pf_set_obstacle", "id")
        base = self._obstacles.get(oid.value) if obstacle is None else obstacle
        o = _effect_struct(t.Obstacle, base, fields, "pf_set_obstacle")
        self._call("pf_set_obstacle", oid, ctypes.byref(o))
        self._obstacles[oid.value] = o

    def remove_obstacle(self, obstacle_id):
        """pf_remove_obstacle; an unknown id raises PflipError(ERROR_INVALID_ARGUMENT). Ids are not
        reused."""
        oid = _u32(obstacle_id, "pf_remove_obstacle", "id")
        self._call("pf_remove_obstacle", oid)
        self._obstacles.pop(oid.value, None)

    # Emitters and sinks share one implementation: (struct, C noun, host dict) per kind.
    def _add_object(self, kind, cls, base, fields, store):
        s = _effect_struct(cls, base, fields, f"pf_add_{kind}")
        out = ctypes.c_uint32()
        self._call(f"pf_add_{kind}", ctypes.byref(s), ctypes.byref(out))
        store[out.value] = s
        return out.value

    def _set_object(self, kind, cls, object_id, base, fields, store):
        oid = _u32(object_id, f"pf_set_{kind}", "id")
        s = _effect_struct(cls, store.get(oid.value) if base is None else base, fields, f"pf_set_{kind}")
        self._call(f"pf_set_{kind}", oid, ctypes.byref(s))
        store[oid.value] = s

    def _remove_object(self, kind, object_id, store):
        oid = _u32(object_id, f"pf_remove_{kind}", "id")
        self._call(f"pf_remove_{kind}", oid)
        store.pop(oid.value, None)

    @property
    def emitters(self):
        """{id: Emitter} of the emitters added and not removed, as last added or set (copies)."""
        return {i: t.Emitter.from_buffer_copy(e) for i, e in self._emitters.items()}

    def add_emitter(self, emitter=None, **fields):
        """pf_add_emitter: emitter (an Emitter; default Emitter.default()) with the keyword fields set,
        e.g. add_emitter(shape="disc", position=p, radius=0.05, velocity=(0, -2, 0), rate=0.001,
        rate_unit="volume_per_second"). Returns its id. Bad values raise
        PflipError(ERROR_INVALID_ARGUMENT), a full set ERROR_CAPACITY; on any error nothing changes.
        Emitters act while Feature.EMITTERS is on."""
        return self._add_object("emitter", t.Emitter, emitter, fields, self._emitters)

    def set_emitter(self, emitter_id, emitter=None, **fields):
        """pf_set_emitter: replace emitter emitter_id (default: as it is now) with the keyword fields set."""
        self._set_object("emitter", t.Emitter, emitter_id, emitter, fields, self._emitters)

    def remove_emitter(self, emitter_id):
        """pf_remove_emitter; an unknown id raises PflipError(ERROR_INVALID_ARGUMENT)."""
        self._remove_object("emitter", emitter_id, self._emitters)

    @property
    def sinks(self):
        """{id: Sink} of the sinks added and not removed, as last added or set (copies)."""
        return {i: t.Sink.from_buffer_copy(k) for i, k in self._sinks.items()}

    def add_sink(self, sink=None, **fields):
        """pf_add_sink: sink (a Sink; default Sink.default()) with the keyword fields set, e.g.
        add_sink(position=(0.5, 0.0, 0.5), half_extents=(0.1, 0.05, 0.1)). Returns its id. Sinks
        act while Feature.SINKS is on."""
        return self._add_object("sink", t.Sink, sink, fields, self._sinks)

    def set_sink(self, sink_id, sink=None, **fields):
        """pf_set_sink: replace sink sink_id (default: as it is now) with the keyword fields set."""
        self._set_object("sink", t.Sink, sink_id, sink, fields, self._sinks)

    def remove_sink(self, sink_id):
        """pf_remove_sink; an unknown id raises PflipError(ERROR_INVALID_ARGUMENT)."""
        self._remove_object("sink", sink_id, self._sinks)

    @property
    def domain_motion(self):
        """pf_get_domain_motion: where the domain is held and how it moves (a DomainMotion)."""
        out = t.DomainMotion.output()
        self._call("pf_get_domain_motion", ctypes.byref(out))
        return out

    def set_domain_motion(self, motion=None, **fields):
        """pf_set_domain_motion: motion (a DomainMotion; default: as it is now) with the keyword
        fields set, e.g. set_domain_motion(velocity=(1, 0, 0)). Acts while Feature.DOMAIN_MOTION is on;
        the liquid feels the change of velocity since the previous step as an acceleration."""
        m = _effect_struct(t.DomainMotion, self.domain_motion if motion is None else motion, fields,
                           "pf_set_domain_motion")
        self._call("pf_set_domain_motion", ctypes.byref(m))

    @property
    def vorticity_confinement(self):
        """pf_get_vorticity_confinement: the vorticity confinement last set (a VorticityConfinement)."""
        out = t.VorticityConfinement.output()
        self._call("pf_get_vorticity_confinement", ctypes.byref(out))
        return out

    def set_vorticity_confinement(self, confinement=None, **fields):
        """pf_set_vorticity_confinement: confinement (a VorticityConfinement; default: as it is now)
        with the keyword fields set, e.g. set_vorticity_confinement(strength=0.5). Acts while
        Feature.VORTICITY_CONFINEMENT is on. A non-finite strength or one outside 0..1 raises
        PflipError(ERROR_INVALID_ARGUMENT) and changes nothing."""
        c = _effect_struct(t.VorticityConfinement, self.vorticity_confinement if confinement is None else confinement,
                           fields, "pf_set_vorticity_confinement")
        self._call("pf_set_vorticity_confinement", ctypes.byref(c))

    @property
    def viscosity(self):
        """pf_get_viscosity: the viscosity last set (a Viscosity)."""
        out = t.Viscosity.output()
        self._call("pf_get_viscosity", ctypes.byref(out))
        return out

    def set_viscosity(self, settings=None, **fields):
        """pf_set_viscosity: settings (a Viscosity; default: as they are now) with the keyword fields
        set, e.g. set_viscosity(viscosity=5.0, iterations=100). Acts while Feature.VISCOSITY is on
        (it may be set while off). A viscosity that is not finite, not above 0 or above 1e5 Pa s,
        iterations outside 1..1000, a tolerance outside 1e-8..0.5, free_slip other than 0 or 1 or
        coupling_rounds outside 1..16 raises PflipError(ERROR_INVALID_ARGUMENT) and changes nothing;
        a negative iterations, free_slip or coupling_rounds, or one beyond uint32, raises the same
        (without reaching the library). A struct of another kind or a field Viscosity lacks raises
        TypeError."""
        v = _effect_struct(t.Viscosity, self.viscosity if settings is None else settings, fields,
                           "pf_set_viscosity")
        self._call("pf_set_viscosity", ctypes.byref(v))

    @property
    def surface_tension(self):
        """pf_get_surface_tension: the surface tension last set (a SurfaceTension)."""
        out = t.SurfaceTension.output()
        self._call("pf_get_surface_tension", ctypes.byref(out))
        return out

    def set_surface_tension(self, settings=None, **fields):
        """pf_set_surface_tension: settings (a SurfaceTension; default: as they are now) with the
        keyword fields set, e.g. set_surface_tension(tension=12.5). Acts while
        Feature.SURFACE_TENSION is on (it may be set while off). A tension that is not finite, below
        0 or above 1000 N/m raises PflipError(ERROR_INVALID_ARGUMENT) and changes nothing. A struct
        of another kind or a field SurfaceTension lacks raises TypeError."""
        st = _effect_struct(t.SurfaceTension, self.surface_tension if settings is None else settings, fields,
                            "pf_set_surface_tension")
        self._call("pf_set_surface_tension", ctypes.byref(st))

    @property
    def whitewater(self):
        """pf_get_whitewater: the whitewater parameters last set (a Whitewater)."""
        out = t.Whitewater.output()
        self._call("pf_get_whitewater", ctypes.byref(out))
        return out

    def set_whitewater(self, whitewater=None, **fields):
        """pf_set_whitewater: whitewater (a Whitewater; default: as it is now) with the keyword fields
        set, e.g. set_whitewater(capacity=65536, lifetime=(0.5, 2.0)). Acts while Feature.WHITEWATER
        is on (it may be set while off). A field outside its range in pf.h (capacity 1..2^23, rates
        0..10000, ranges 0 <= [0] < [1], lifetime 0 < [0] <= [1] <= 1000, ...) or not finite raises
        PflipError(ERROR_INVALID_ARGUMENT) and changes nothing. A new capacity clears the whitewater."""
        w = _effect_struct(t.Whitewater, self.whitewater if whitewater is None else whitewater, fields,
                           "pf_set_whitewater")
        self._call("pf_set_whitewater", ctypes.byref(w))

    def whitewater_buffers(self):
        """pf_get_whitewater_buffers: the GL names of the whitewater's particle buffers (a
        WhitewaterBuffers), for an engine that draws it itself. While Feature.WHITEWATER is off it
        raises PflipError(ERROR_INVALID_STATE)."""
        out = t.WhitewaterBuffers.output()
        self._call("pf_get_whitewater_buffers", ctypes.byref(out))
        return out

    def obstacle_force(self, obstacle_id):
        """pf_get_obstacle_force: the newest ObstacleForce of obstacle obstacle_id (force in N, torque
        in N m about its position, and the step it belongs to; step 0 while none was read back). Never
        waits: it is a few steps late. An unknown id raises PflipError(ERROR_INVALID_ARGUMENT)."""
        oid = _u32(obstacle_id, "pf_get_obstacle_force", "id")
        out = t.ObstacleForce.output()
        self._call("pf_get_obstacle_force", oid, ctypes.byref(out))
        return out

    # ---- rendering ------------------------------------------------------------------------------
    def render_ssf(self, camera, target, params=None):
        """pf_render_ssf: the liquid into target (a RenderTarget) over its scene, seen by camera."""
        self._call("pf_render_ssf", ctypes.byref(camera), ctypes.byref(target),
                   None if params is None else ctypes.byref(params))

    def render_particles(self, camera, target, params=None):
        """pf_render_particles: every particle as a sphere sprite (debug view)."""
        self._call("pf_render_particles", ctypes.byref(camera), ctypes.byref(target),
                   None if params is None else ctypes.byref(params))
