"""The resting tank the scripts here share: the tank of Volume.CorrectionKeepsANoisyTankFlatterThanWithout
(16^3 cells of 0.1 m, half full, 8 particles a cell jittered by `jitter` of the sub-cell spacing,
random velocities of up to `noise` m/s per component), built with numpy's generator."""
import numpy as np
import pflip
from pflip import frame

N, DX = 16, 0.1
_context = frame.create_context()


def tank(noise=0.01, jitter=0.8, **params):
    """A simulation of the tank with these pf_sim_params fields set; returns it and the start positions."""
    sim = pflip.Simulation(grid_size=(N, N, N), cell_size=DX, max_particles=N * N * N * 8)
    p = sim.params
    for name, value in params.items():
        setattr(p, name, value)
    sim.params = p
    rng = np.random.default_rng(5)
    s = DX / 2
    i, j, k = np.meshgrid(np.arange(32), np.arange(16), np.arange(32), indexing='ij')
    pos = np.stack([(a + 0.5 + jitter * (rng.random(i.shape) - 0.5)) * s for a in (i, j, k)], -1)
    pos = pos.reshape(-1, 3).astype(np.float32)
    vel = rng.uniform(-noise, noise, pos.shape).astype(np.float32)
    sim.add_particles(pos, vel)
    return sim, pos


def rms_speed_mm(v):
    """Root-mean-square particle speed, mm/s."""
    return 1000 * np.sqrt((v ** 2).sum(1).mean())
