"""rms speed after the first 0.1 s projection by the particle's starting layer (0 the floor, 7 the
top), the jittered lattice at rest."""
import numpy as np
import pflip
from resting_tank import DX, tank, rms_speed_mm


def run(label, **params):
    sim, pos = tank(noise=0.0, **params)
    sim.step(0.1)
    v = sim.read_particles()[1]
    layer = np.clip(np.floor(pos[:, 1] / DX).astype(int), 0, 7)
    print(label, "rms|v| by start layer (mm/s):", " ".join("%.1f" % rms_speed_mm(v[layer == l]) for l in range(8)),
          "| rms vy", " ".join("%.1f" % (1000 * np.sqrt((v[layer == l, 1] ** 2).mean())) for l in range(8)))


run("default         ")
run("marker cell     ", free_surface=pflip.FreeSurface.MARKER_CELL)
run("vc 0            ", volume_correction=0.0)
run("tol 1e-6        ", pressure_tolerance=1e-6, pressure_iterations=200)
run("PIC             ", flip_ratio=0.0)
