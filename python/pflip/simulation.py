"""Simulation: one pf_sim, with every pf_* call that takes a simulation as a method.

All calls must happen on the thread where the simulation's GL context is current (the C API's
rule; a moderngl standalone context is current on the thread that made it).
"""
import collections
import ctypes
import logging
import warnings

import numpy as np

from . import _types as t
from ._lib import lib
from .errors import PflipError

_log = logging.getLogger("pflip")
_log.addHandler(logging.NullHandler())  # a library logs only where the application asks it to
_PY_LEVEL = {t.LogLevel.ERROR: logging.ERROR, t.LogLevel.WARNING: logging.WARNING, t.LogLevel.INFO: logging.INFO}
# Logger callbacks of simulations that were garbage-collected without close(): the C side still
# holds their address, so they must never be freed.
_orphaned_callbacks = []

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


class Simulation:
    """A pflip simulation in the GL context current now (pf_create).

    desc: a SimDesc (default: SimDesc.default()); keyword arguments set its fields, e.g.
    Simulation(grid_size=(64, 32, 32), cell_size=0.05, max_particles=1 << 18).
    get_proc_address: the GL loader, a GetProcAddressFn or a Python callable name(bytes) -> int
    (default: libEGL's eglGetProcAddress, right for moderngl's 'egl' backend).
    log: optional callable(level: LogLevel, code: Result, message: str); every message also goes
    to the Python logger "pflip".
    """

    def __init__(self, desc=None, *, get_proc_address=None, log=None, **fields):
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
            _orphaned_callbacks.append(self._log_fn)
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

    @property
    def particle_count(self):
        return self.stats().particle_count

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
        out = t.SimParams()
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
    def stats(self):
        """pf_get_stats (no stall: GPU figures lag a few steps)."""
        out = t.Stats()
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
        out = t.GlBuffers()
        self._call("pf_get_gl_buffers", ctypes.byref(out))
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
