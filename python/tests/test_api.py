"""The Python surface of the C API: errors carry the code and the library's message and leave the
simulation usable; parameters round-trip; push changes velocities locally; lifetime is explicit."""
import ctypes

import numpy as np
import pytest

import pflip
from pflip import PflipError, Result


@pytest.fixture
def sim(gl):
    s = pflip.Simulation(grid_size=(16, 16, 16), cell_size=1.0 / 16, max_particles=1 << 15)
    yield s
    s.close()


def test_invalid_step_raises_with_the_logged_reason_and_the_sim_goes_on(sim):
    sim.fill_box((0.25, 0.25, 0.25), (0.5, 0.5, 0.5))
    n = sim.particle_count
    with pytest.raises(PflipError) as e:
        sim.step(0.0)
    assert e.value.code == Result.ERROR_INVALID_ARGUMENT
    assert e.value.function == "pf_step"
    # The text is the logger's explanation, not just the generic pf_result_string.
    assert "frame_dt" in e.value.message and e.value.message != pflip.result_string(e.value.code)
    sim.step(1.0 / 60)
    assert sim.stats().steps == 1 and sim.particle_count == n


def test_capacity_error_adds_nothing(sim):
    too_many = np.full((sim.stats().max_particles + 1, 3), 0.5, np.float32)
    with pytest.raises(PflipError) as e:
        sim.add_particles(too_many)
    assert e.value.code == Result.ERROR_CAPACITY
    assert sim.particle_count == 0


def test_invalid_params_change_nothing(sim):
    before = bytes(sim.params)
    p = sim.params
    p.cfl = -1.0
    with pytest.raises(PflipError) as e:
        sim.params = p
    assert e.value.code == Result.ERROR_INVALID_ARGUMENT and "cfl" in e.value.message
    assert bytes(sim.params) == before


def test_getters_return_every_field_of_this_layout(sim):
    # A getter's struct carries this layout's struct_size: with 0 the library writes only the
    # first layout (pf_sim_params up to 80 bytes), and assigning it back reset the newer fields to
    # their defaults (free_surface here; before the fix, the getter returned 80 and MARKER_CELL
    # was lost).
    p = sim.params
    assert p.struct_size == ctypes.sizeof(pflip.SimParams)
    p.free_surface = pflip.FreeSurface.MARKER_CELL
    sim.params = p
    assert sim.params.free_surface == pflip.FreeSurface.MARKER_CELL
    for getter in ("viscosity", "surface_tension", "whitewater", "vorticity_confinement", "domain_motion"):
        value = getattr(sim, getter)
        assert value.struct_size == ctypes.sizeof(value), getter


def test_create_error_names_the_field(gl):
    with pytest.raises(PflipError) as e:
        pflip.Simulation(grid_size=(0, 16, 16))
    assert e.value.code == Result.ERROR_INVALID_ARGUMENT and "grid_size" in e.value.message


def test_unknown_quality_raises():
    with pytest.raises(PflipError) as e:
        pflip.SimParams.quality(99)
    assert e.value.code == Result.ERROR_INVALID_ARGUMENT


def test_quality_presets_round_trip(sim):
    for q in pflip.Quality:
        sim.set_quality(q)
        want = pflip.SimParams.quality(q)
        want.gravity = sim.params.gravity
        assert bytes(sim.params) == bytes(want), q


def test_added_particles_read_back_exactly(sim):
    rng = np.random.default_rng(3)
    xyz = rng.uniform(0.1, 0.9, (100, 3)).astype(np.float32)
    vel = rng.uniform(-1, 1, (100, 3)).astype(np.float32)
    sim.add_particles(xyz, vel)
    got_xyz, got_vel = sim.read_particles()
    np.testing.assert_array_equal(got_xyz, xyz)
    np.testing.assert_array_equal(got_vel, vel)
    part, none = sim.read_particles(first=10, count=5, velocities=False)
    np.testing.assert_array_equal(part, xyz[10:15])
    assert none is None
    with pytest.raises(ValueError):
        sim.add_particles(xyz[:, :2])


def test_push_moves_only_particles_within_its_radius(sim):
    p = sim.params
    p.gravity = (0.0, 0.0, 0.0)
    sim.params = p
    sim.fill_box((0.0, 0.0, 0.0), (1.0, 0.5, 1.0))
    center, radius = np.array([0.5, 0.25, 0.5]), 0.2
    sim.push(center, radius, (1.0, 0.0, 0.0))
    xyz, vel = sim.read_particles()
    d = np.linalg.norm(xyz - center, axis=1)
    assert vel[d < radius / 2, 0].min() > 0.0
    assert np.abs(vel[d > radius * 1.01]).max() == 0.0


def test_closed_simulation_refuses_calls(gl):
    s = pflip.Simulation(grid_size=(8, 8, 8))
    s.close()
    s.close()  # idempotent, as pf_destroy(NULL) is
    assert s.closed
    with pytest.raises(PflipError) as e:
        s.step()
    assert e.value.code == Result.ERROR_INVALID_STATE


def test_gl_buffers_name_real_buffers(sim, gl):
    sim.fill_box((0.0, 0.0, 0.0), (0.5, 0.5, 0.5))
    b = sim.gl_buffers()
    assert b.count == sim.particle_count and b.stride == 16
    assert b.positions != 0 and b.velocities != 0 and b.positions != b.velocities


def test_logger_callback_receives_errors(gl):
    seen = []
    with pflip.Simulation(grid_size=(8, 8, 8), log=lambda *m: seen.append(m)) as s:
        with pytest.raises(PflipError):
            s.step(2.0)
    assert any(level == pflip.LogLevel.ERROR and code == Result.ERROR_INVALID_ARGUMENT for level, code, _ in seen)


def test_snapshot_restore_continues_bit_identically(sim):
    sim.fill_box((0.1, 0.1, 0.1), (0.5, 0.7, 0.5), velocity=(0.5, 0.0, 0.0))
    for _ in range(3):
        sim.step()
    snap = sim.save_snapshot()
    at_save = sim.read_particles()
    sim.step()
    sim.step()
    after_two = sim.read_particles()
    assert not np.array_equal(at_save[0], after_two[0])
    sim.restore_snapshot(snap)
    assert all(np.array_equal(a, b) for a, b in zip(sim.read_particles(), at_save))
    damaged = bytearray(snap)
    damaged[len(damaged) // 2] ^= 1
    with pytest.raises(PflipError) as e:
        sim.restore_snapshot(bytes(damaged))
    assert e.value.code == Result.ERROR_INVALID_ARGUMENT and "checksum" in str(e.value)
    assert all(np.array_equal(a, b) for a, b in zip(sim.read_particles(), at_save))


def test_requested_particles_equal_the_blocking_read(sim):
    sim.fill_box((0.1, 0.1, 0.1), (0.5, 0.5, 0.5))
    sim.step()
    tickets = [sim.request_particles()]
    want = [sim.read_particles()]
    sim.step()
    tickets.append(sim.request_particles(5, 20))
    want.append(sim.read_particles(5, 20))
    for ticket, expected in zip(tickets, want):
        got = None
        for _ in range(100000):
            got = sim.poll_particles(ticket)
            if got is not None:
                break
        assert got is not None
        assert all(np.array_equal(a, b) for a, b in zip(got, expected))
    with pytest.raises(PflipError):
        sim.poll_particles(tickets[0])  # collected


def test_gpu_budget(sim):
    """pf_set_gpu_budget: set and read back; out of range or with timing off it raises and the
    budget stays; a budget steps (on llvmpipe nothing is measured, so nothing is cut)."""
    assert sim.gpu_budget == 0.0
    sim.gpu_budget = 2.5
    assert sim.gpu_budget == 2.5
    for bad in (-1.0, float("nan"), 1e5):
        with pytest.raises(pflip.PflipError) as e:
            sim.gpu_budget = bad
        assert e.value.code == pflip.Result.ERROR_INVALID_ARGUMENT and e.value.function == "pf_set_gpu_budget"
        assert sim.gpu_budget == 2.5
    with pytest.raises(pflip.PflipError):
        sim.gpu_timing = pflip.GpuTiming.OFF
    sim.fill_box((0.0, 0.0, 0.0), (0.4, 0.4, 0.4))
    sim.step(1.0 / 60.0)
    sim.gpu_budget = 0.0
    sim.gpu_timing = pflip.GpuTiming.OFF
    with pytest.raises(pflip.PflipError):
        sim.gpu_budget = 1.0
    assert sim.gpu_budget == 0.0


def test_gpu_timing_modes(sim):
    """pf_set_gpu_timing: STEP times the step as a whole (total only), OFF nothing, PASSES every
    pass group (the default); unknown values raise and change nothing."""
    assert sim.gpu_timing == pflip.GpuTiming.PASSES
    sim.fill_box((0.0, 0.0, 0.0), (0.4, 0.4, 0.4))

    def measured():
        for _ in range(40):
            sim.step(1.0 / 60.0)
            sim.pass_stats()  # polls the timers
            st = sim.stats()
            if st.gpu_step > 0:
                return st
        return sim.stats()

    st = measured()
    if st.gpu_step == 0:
        pytest.skip("this GL reports no GL_TIMESTAMP bits")
    assert st.gpu_total_ms > 0 and sum(st.gpu_ms) == pytest.approx(st.gpu_total_ms, rel=1e-3)
    sim.gpu_timing = pflip.GpuTiming.STEP
    assert sim.gpu_timing == pflip.GpuTiming.STEP
    st = measured()
    assert st.gpu_total_ms > 0 and sum(st.gpu_ms) == 0
    sim.gpu_timing = pflip.GpuTiming.OFF
    st = measured()
    assert st.gpu_step == 0 and st.gpu_total_ms == 0 and st.dispatches[int(pflip.Pass.PRESSURE_SOLVE)] > 0
    sim.gpu_timing = pflip.GpuTiming.KERNELS
    assert sim.gpu_timing == pflip.GpuTiming.KERNELS
    sim.step(1.0 / 60.0)
    kernels = [p for p in sim.pass_stats() if ":" in p.name]
    assert kernels and sum(p.dispatches for p in kernels) == sum(sim.stats().dispatches)
    sim.gpu_timing = pflip.GpuTiming.OFF
    for bad in (4, -1, 1 << 40):
        with pytest.raises(pflip.PflipError) as e:
            sim.gpu_timing = bad
        assert e.value.code == pflip.Result.ERROR_INVALID_ARGUMENT and e.value.function == "pf_set_gpu_timing"
        assert sim.gpu_timing == pflip.GpuTiming.OFF
