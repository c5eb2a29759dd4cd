"""pflip for Python: the C API of libpflip.so through ctypes.

    import pflip
    ctx = pflip.frame.create_context()                 # or any current GL 4.3 core context
    with pflip.Simulation(grid_size=(32, 16, 16)) as sim:
        sim.fill_box((0, 0, 0), (0.5, 0.6, 0.8))
        sim.step(1 / 60)
        positions, velocities = sim.read_particles()    # (N, 3) float32

Errors raise PflipError (code: a Result, message: the library's log text). The library is found
through $PFLIP_LIBRARY, next to this package, the source tree's build/ or the system loader
(pflip._lib explains the order).
"""
from . import camera, frame
from ._lib import ABI_VERSION, lib, version
from ._types import (MAX_EMITTERS, MAX_FORCE_FIELDS, MAX_OBSTACLES, MAX_SINKS, Advection, Camera, DepthConvention,
                     DomainMotion, Emitter, EmitterShape, Feature, Flag, ForceField, FreeSurface, ForceFieldType, GlBuffers, GpuTiming, LogLevel, Obstacle, ObstacleForce,
                     ObstacleShape, P2G, ParticleColor, ParticleParams, Pass, PressureSolver, Quality, RateUnit,
                     RenderPass, RenderTarget, Result, SimDesc, SimParams, Sink, SinkShape, SsfFilter, SsfParams,
                     SsfPath, Stats, SurfaceTension, Transfer, Viscosity, VorticityConfinement, Whitewater,
                     WhitewaterBuffers, WhitewaterKind)
from .errors import PflipError
from .program_cache import ProgramCacheDirectory
from .simulation import PassStats, Simulation

__version__ = "%d.%d.%d" % version()


def result_string(code):
    """pf_result_string: short English text for a result code."""
    return lib.pf_result_string(int(code)).decode()


def pass_name(p):
    """pf_pass_name: stable short name of a pass."""
    return lib.pf_pass_name(int(p)).decode()


def render_pass_name(p):
    """pf_render_pass_name: stable short name of a render pass."""
    return lib.pf_render_pass_name(int(p)).decode()


__all__ = [
    "ABI_VERSION", "Advection", "Camera", "DepthConvention", "Feature", "Flag", "ForceField", "ForceFieldType", "FreeSurface",
    "GlBuffers", "GpuTiming", "LogLevel", "MAX_FORCE_FIELDS", "MAX_OBSTACLES", "Obstacle", "ObstacleForce", "ObstacleShape", "P2G",
    "ParticleColor", "ParticleParams", "Pass", "PassStats", "PflipError", "PressureSolver", "ProgramCacheDirectory", "Quality",
    "RenderPass", "RenderTarget", "Result", "SimDesc", "SimParams", "Simulation", "SsfFilter", "SsfParams",
    "SsfPath", "Stats", "SurfaceTension", "Transfer", "Viscosity", "VorticityConfinement", "Whitewater",
    "WhitewaterBuffers", "WhitewaterKind",
    "camera", "frame", "pass_name", "render_pass_name", "result_string", "version",
]
