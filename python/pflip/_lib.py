"""Finds and loads libpflip.so and declares the prototype of every pf_* function.

Search order (the first that exists wins):
  1. $PFLIP_LIBRARY: the path of the library file;
  2. next to this package (a wheel or an install that copied the library in);
  3. the source tree's build directory, when the package is used from a checkout
     (python/pflip -> ../../build/libpflip.so);
  4. the system loader: libpflip.so.<soname version>, then libpflip.so (LD_LIBRARY_PATH, ldconfig,
     an install prefix in the loader's path).
"""
import ctypes
import os
import pathlib

from . import _types as t

# The ABI this package mirrors: before 1.0 a minor release may change structs (the soname carries
# the minor), so the library's major.minor must equal this.
ABI_VERSION = (0, 3)
SONAME = "libpflip.so.%d.%d" % ABI_VERSION


def _candidates():
    env = os.environ.get("PFLIP_LIBRARY")
    if env:
        yield env, True  # explicit: an error if it does not load
        return
    here = pathlib.Path(__file__).resolve().parent
    for name in (SONAME, "libpflip.so"):
        yield str(here / name), False
    yield str(here.parent.parent / "build" / "libpflip.so"), False
    yield SONAME, None  # bare names go through the dynamic loader's search
    yield "libpflip.so", None


def _load():
    tried = []
    for path, explicit in _candidates():
        if explicit is False and not os.path.exists(path):
            continue
        try:
            return ctypes.CDLL(path)
        except OSError as e:
            if explicit:
                raise OSError(f"PFLIP_LIBRARY={path}: {e}") from e
            tried.append(f"{path}: {e}")
    raise OSError("libpflip.so not found; set PFLIP_LIBRARY to its path. Tried:\n  " + "\n  ".join(tried))


lib = _load()

_P = ctypes.POINTER
_sim = ctypes.c_void_p  # pf_sim* is opaque
_f3 = _P(ctypes.c_float)

_PROTOTYPES = {
    # name: (restype, argtypes)
    "pf_version": (ctypes.c_uint32, []),
    "pf_result_string": (ctypes.c_char_p, [t.c_enum]),
    "pf_pass_name": (ctypes.c_char_p, [t.c_enum]),
    "pf_render_pass_name": (ctypes.c_char_p, [t.c_enum]),
    "pf_init_sim_params": (t.c_enum, [_P(t.SimParams), ctypes.c_uint32]),
    "pf_quality_params": (t.c_enum, [t.c_enum, _P(t.SimParams)]),
    "pf_init_sim_desc": (t.c_enum, [_P(t.SimDesc), ctypes.c_uint32]),
    "pf_init_ssf_params": (t.c_enum, [_P(t.SsfParams), ctypes.c_uint32]),
    "pf_init_particle_params": (t.c_enum, [_P(t.ParticleParams), ctypes.c_uint32]),
    "pf_create": (t.c_enum, [_P(t.SimDesc), _P(_sim)]),
    "pf_destroy": (t.c_enum, [_sim]),
    "pf_set_global_logger": (None, [_P(t.Logger)]),
    "pf_add_particles": (t.c_enum, [_sim, _f3, _f3, ctypes.c_uint32]),
    "pf_fill_box": (t.c_enum, [_sim, _f3, _f3, _f3]),
    "pf_clear_particles": (t.c_enum, [_sim]),
    "pf_step": (t.c_enum, [_sim, ctypes.c_float]),
    "pf_get_params": (t.c_enum, [_sim, _P(t.SimParams)]),
    "pf_set_params": (t.c_enum, [_sim, _P(t.SimParams)]),
    "pf_read_particles": (t.c_enum, [_sim, ctypes.c_uint32, ctypes.c_uint32, _f3, _f3]),
    "pf_request_particles": (t.c_enum, [_sim, ctypes.c_uint32, ctypes.c_uint32, _P(ctypes.c_uint32)]),
    "pf_poll_particles": (t.c_enum, [_sim, ctypes.c_uint32, _f3, _f3]),
    "pf_snapshot_size": (t.c_enum, [_sim, _P(ctypes.c_size_t)]),
    "pf_save_snapshot": (t.c_enum, [_sim, ctypes.c_void_p, ctypes.c_size_t]),
    "pf_restore_snapshot": (t.c_enum, [_sim, ctypes.c_void_p, ctypes.c_size_t]),
    "pf_get_gl_buffers": (t.c_enum, [_sim, _P(t.GlBuffers)]),
    "pf_get_whitewater_buffers": (t.c_enum, [_sim, _P(t.WhitewaterBuffers)]),
    "pf_get_stats": (t.c_enum, [_sim, _P(t.Stats)]),
    "pf_clear_flags": (t.c_enum, [_sim]),
    "pf_get_pass_count": (t.c_enum, [_sim, _P(ctypes.c_uint32)]),
    "pf_get_pass_stats": (t.c_enum, [_sim, ctypes.c_uint32, _P(t.PassStatsC)]),
    "pf_set_gpu_timing": (t.c_enum, [_sim, t.c_enum]),
    "pf_get_gpu_timing": (t.c_enum, [_sim, _P(t.c_enum)]),
    "pf_set_gpu_budget": (t.c_enum, [_sim, ctypes.c_float]),
    "pf_get_gpu_budget": (t.c_enum, [_sim, _P(ctypes.c_float)]),
    "pf_render_ssf": (t.c_enum, [_sim, _P(t.Camera), _P(t.RenderTarget), _P(t.SsfParams)]),
    "pf_render_particles": (t.c_enum, [_sim, _P(t.Camera), _P(t.RenderTarget), _P(t.ParticleParams)]),
    "pf_push": (t.c_enum, [_sim, _f3, ctypes.c_float, _f3]),
    "pf_set_features": (t.c_enum, [_sim, ctypes.c_uint32]),
    "pf_get_features": (t.c_enum, [_sim, _P(ctypes.c_uint32)]),
    "pf_init_force_field": (t.c_enum, [_P(t.ForceField), ctypes.c_uint32]),
    "pf_add_force_field": (t.c_enum, [_sim, _P(t.ForceField), _P(ctypes.c_uint32)]),
    "pf_set_force_field": (t.c_enum, [_sim, ctypes.c_uint32, _P(t.ForceField)]),
    "pf_remove_force_field": (t.c_enum, [_sim, ctypes.c_uint32]),
    "pf_init_obstacle": (t.c_enum, [_P(t.Obstacle), ctypes.c_uint32]),
    "pf_add_obstacle": (t.c_enum, [_sim, _P(t.Obstacle), _P(ctypes.c_uint32)]),
    "pf_set_obstacle": (t.c_enum, [_sim, ctypes.c_uint32, _P(t.Obstacle)]),
    "pf_remove_obstacle": (t.c_enum, [_sim, ctypes.c_uint32]),
    "pf_init_emitter": (t.c_enum, [_P(t.Emitter), ctypes.c_uint32]),
    "pf_add_emitter": (t.c_enum, [_sim, _P(t.Emitter), _P(ctypes.c_uint32)]),
    "pf_set_emitter": (t.c_enum, [_sim, ctypes.c_uint32, _P(t.Emitter)]),
    "pf_remove_emitter": (t.c_enum, [_sim, ctypes.c_uint32]),
    "pf_init_sink": (t.c_enum, [_P(t.Sink), ctypes.c_uint32]),
    "pf_add_sink": (t.c_enum, [_sim, _P(t.Sink), _P(ctypes.c_uint32)]),
    "pf_set_sink": (t.c_enum, [_sim, ctypes.c_uint32, _P(t.Sink)]),
    "pf_remove_sink": (t.c_enum, [_sim, ctypes.c_uint32]),
    "pf_get_particle_count": (t.c_enum, [_sim, _P(ctypes.c_uint32)]),
    "pf_init_domain_motion": (t.c_enum, [_P(t.DomainMotion), ctypes.c_uint32]),
    "pf_set_domain_motion": (t.c_enum, [_sim, _P(t.DomainMotion)]),
    "pf_get_domain_motion": (t.c_enum, [_sim, _P(t.DomainMotion)]),
    "pf_init_vorticity_confinement": (t.c_enum, [_P(t.VorticityConfinement), ctypes.c_uint32]),
    "pf_set_vorticity_confinement": (t.c_enum, [_sim, _P(t.VorticityConfinement)]),
    "pf_get_vorticity_confinement": (t.c_enum, [_sim, _P(t.VorticityConfinement)]),
    "pf_init_whitewater": (t.c_enum, [_P(t.Whitewater), ctypes.c_uint32]),
    "pf_set_whitewater": (t.c_enum, [_sim, _P(t.Whitewater)]),
    "pf_get_whitewater": (t.c_enum, [_sim, _P(t.Whitewater)]),
    "pf_init_viscosity": (t.c_enum, [_P(t.Viscosity), ctypes.c_uint32]),
    "pf_set_viscosity": (t.c_enum, [_sim, _P(t.Viscosity)]),
    "pf_get_viscosity": (t.c_enum, [_sim, _P(t.Viscosity)]),
    "pf_init_surface_tension": (t.c_enum, [_P(t.SurfaceTension), ctypes.c_uint32]),
    "pf_set_surface_tension": (t.c_enum, [_sim, _P(t.SurfaceTension)]),
    "pf_get_surface_tension": (t.c_enum, [_sim, _P(t.SurfaceTension)]),
    "pf_get_obstacle_force": (t.c_enum, [_sim, ctypes.c_uint32, _P(t.ObstacleForce)]),
}

for _name, (_res, _args) in _PROTOTYPES.items():
    _fn = getattr(lib, _name)
    _fn.restype = _res
    _fn.argtypes = _args


def version():
    """(major, minor, patch) of the loaded library (pf_version())."""
    v = lib.pf_version()
    return v // 10000, v // 100 % 100, v % 100


def _check_abi():
    major, minor, patch = version()
    if (major, minor) != ABI_VERSION:
        raise ImportError(
            f"pflip: the loaded library {getattr(lib, '_name', '?')} is version {major}.{minor}.{patch}; "
            f"this package mirrors the {ABI_VERSION[0]}.{ABI_VERSION[1]} ABI")


_check_abi()
