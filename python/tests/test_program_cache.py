"""Simulation(program_cache=...): a second simulation of the same configuration links every program
from the blobs the first stored and steps bit-identically; a damaged blob is rebuilt and stored
again; a cache that raises costs compiles, not the simulation."""
import os

import numpy as np
import pytest

import pflip


class Counting(pflip.ProgramCacheDirectory):
    def __init__(self, directory):
        super().__init__(directory)
        self.loads = self.hits = self.stores = 0

    def load(self, key):
        self.loads += 1
        blob = super().load(key)
        self.hits += blob is not None
        return blob

    def store(self, key, data):
        self.stores += 1
        super().store(key, data)


def run(cache, messages=None):
    log = (lambda level, code, message: messages.append(message)) if messages is not None else None
    with pflip.Simulation(grid_size=(16, 16, 16), cell_size=1.0 / 16, max_particles=1 << 14,
                          program_cache=cache, log=log) as sim:
        sim.fill_box((0.0, 0.0, 0.0), (0.4, 0.6, 1.0))
        for _ in range(3):
            sim.step(1.0 / 60)
        return sim.read_particles()


def offers_binaries(tmp_path):
    messages = []
    run(Counting(tmp_path / "probe"), messages)
    return not any("no program binary format" in m for m in messages)


def test_second_simulation_loads_every_program_and_steps_identically(gl, tmp_path):
    if not offers_binaries(tmp_path):
        pytest.skip("this GL offers no program binary format (Mesa: MESA_SHADER_CACHE_DISABLE is set)")
    first = Counting(tmp_path / "cache")
    pos_a, vel_a = run(first)
    assert first.stores > 10 and first.hits == 0
    assert len(os.listdir(first.directory)) == first.stores
    second = Counting(tmp_path / "cache")
    pos_b, vel_b = run(second)
    assert second.hits == first.stores and second.stores == 0
    plain_pos, plain_vel = run(None)
    assert np.array_equal(pos_b, plain_pos) and np.array_equal(vel_b, plain_vel)
    assert np.array_equal(pos_a, pos_b) and np.array_equal(vel_a, vel_b)


def test_a_damaged_blob_is_rebuilt_and_stored_again(gl, tmp_path):
    if not offers_binaries(tmp_path):
        pytest.skip("this GL offers no program binary format")
    cache = Counting(tmp_path / "cache")
    run(cache)
    name = sorted(os.listdir(cache.directory))[0]
    path = os.path.join(cache.directory, name)
    blob = bytearray(open(path, "rb").read())
    blob[-1] ^= 0xFF  # the driver's binary, after pflip's header
    open(path, "wb").write(bytes(blob))
    again = Counting(tmp_path / "cache")
    messages = []
    pos, _ = run(again, messages)
    assert again.stores == 1, "only the damaged program is compiled and stored again"
    program = name[len("pflip-"):-len("-0123456789abcdef.bin")]  # pflip-<program>-<16 hex>.bin
    assert any(f"the blob of {program} is not used" in m for m in messages), messages
    assert open(path, "rb").read() != bytes(blob)
    assert len(pos) > 0


def test_a_cache_that_raises_costs_compiles_not_the_simulation(gl, tmp_path):
    class Broken:
        def load(self, key):
            raise OSError("disk gone")

        def store(self, key, data):
            raise OSError("disk gone")

    pos, vel = run(Broken())
    plain_pos, plain_vel = run(None)
    assert np.array_equal(pos, plain_pos) and np.array_equal(vel, plain_vel)
