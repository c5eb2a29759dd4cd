"""The GL loader pf_create needs, taken from libEGL, for contexts made through EGL (moderngl's
'egl' backend, or the engine's own).

pflip calls eglGetProcAddress itself: its C address is handed over as desc.gl_get_proc_address, so
no Python runs while the library loads GL.
"""
import ctypes
import ctypes.util

from ._types import GetProcAddressFn

_egl = None


def _libegl():
    global _egl
    if _egl is None:
        name = ctypes.util.find_library("EGL") or "libEGL.so.1"
        _egl = ctypes.CDLL(name)
        _egl.eglGetProcAddress.restype = ctypes.c_void_p
        _egl.eglGetProcAddress.argtypes = [ctypes.c_char_p]
    return _egl


def get_proc_address():
    """eglGetProcAddress as a pf_gl_get_proc_address_fn (same C signature, no Python wrapper)."""
    return ctypes.cast(_libegl().eglGetProcAddress, GetProcAddressFn)

