"""The engine's side of pf_program_cache from Python: keep pflip's compiled shader programs between
runs so that a later Simulation of the same configuration links them instead of compiling
(docs/integration.md §11).

Any object with load(key) -> bytes | None and store(key, data) serves; ProgramCacheDirectory keeps
one file per key. pflip checks every blob it loads and rebuilds a bad one, so a cache may hand it
anything: a stale, damaged or foreign blob costs a compile, not an error.
"""
import ctypes
import logging
import os
import tempfile

from . import _types as t

_log = logging.getLogger("pflip")


class ProgramCacheDirectory:
    """Blobs as files, <directory>/<key>.bin (the key is safe as a file name); created if missing.
    A store writes a temporary file and renames it, so a reader never sees half a blob."""

    def __init__(self, directory):
        self.directory = os.fspath(directory)
        os.makedirs(self.directory, exist_ok=True)

    def _path(self, key):
        return os.path.join(self.directory, key + ".bin")

    def load(self, key):
        try:
            with open(self._path(key), "rb") as f:
                return f.read()
        except FileNotFoundError:
            return None

    def store(self, key, data):
        fd, temp = tempfile.mkstemp(dir=self.directory, suffix=".tmp")
        try:
            with os.fdopen(fd, "wb") as f:
                f.write(data)
            os.replace(temp, self._path(key))
        except BaseException:
            if os.path.exists(temp):
                os.unlink(temp)
            raise


class _Callbacks:
    """The C callbacks of one simulation over a Python cache object. An exception in the cache is
    logged and taken as a miss (load) or a skipped store: it must not unwind through C."""

    def __init__(self, cache):
        self.cache = cache
        self.load_fn = t.ProgramLoadFn(self._load)
        self.store_fn = t.ProgramStoreFn(self._store)

    def struct(self):
        return t.ProgramCache(None, self.load_fn, self.store_fn)

    def _load(self, _user, key, data, capacity):
        try:
            blob = self.cache.load(key.decode())
        except Exception:  # noqa: BLE001 - reported, and pflip compiles instead
            _log.exception("program cache: load(%s) failed; the program is compiled", key.decode())
            return 0
        if not blob:
            return 0
        blob = bytes(blob)
        if len(blob) <= capacity:
            ctypes.memmove(data, blob, len(blob))
        return len(blob)  # above capacity: pflip asks again with a buffer this large

    def _store(self, _user, key, data, size):
        try:
            self.cache.store(key.decode(), ctypes.string_at(data, size))
        except Exception:  # noqa: BLE001
            _log.exception("program cache: store(%s) failed; the blob is not kept", key.decode())
