"""Shared fixtures: one headless GL context (moderngl, EGL) for the whole session, as an engine has.

Run from CTest (python.*), which points PFLIP_LIBRARY at the build's libpflip.so and
PFLIP_INCLUDE_DIRS at pf.h and the generated pf_version.h.
"""
import pytest


@pytest.fixture(scope="session")
def gl():
    import pflip

    ctx = pflip.frame.create_context()
    yield ctx
    ctx.release()


@pytest.fixture
def dam_break(gl):
    """A 1.6 x 0.8 x 0.8 m tank with a 0.4 m wide, 0.6 m high column of liquid against x = 0."""
    import pflip

    sim = pflip.Simulation(grid_size=(32, 16, 16), cell_size=0.05, max_particles=1 << 15)
    sim.fill_box((0.0, 0.0, 0.0), (0.4, 0.6, 0.8))
    yield sim
    sim.close()
