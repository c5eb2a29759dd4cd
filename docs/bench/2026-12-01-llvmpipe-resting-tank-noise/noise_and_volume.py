"""rms speed and capped count volume at frames 10, 30, 60 and 100 of 0.1 s; `marker_cell` as the
argument runs the marker-cell surface instead of the ghost fluid."""
import sys
import numpy as np
import pflip
from resting_tank import N, DX, tank, rms_speed_mm


def run(label, **params):
    sim, _ = tank(**params)
    out = []
    for f in range(1, 101):
        sim.step(0.1)
        if f in (10, 30, 60, 100):
            x, v = sim.read_particles()
            idx = np.clip(np.floor(x / DX).astype(int), 0, N - 1)
            c = np.bincount((idx[:, 0] * N + idx[:, 1]) * N + idx[:, 2], minlength=N ** 3)
            vol = np.minimum(c, 8).sum() / len(x) - 1
            out.append(f"f{f}: vol {vol:+.4f} rms|v| {rms_speed_mm(v):.1f} mm/s")
    print(label, " | ".join(out))


if sys.argv[1:] == ["marker_cell"]:
    mc = pflip.FreeSurface.MARKER_CELL
    run("mc cfl1    ", cfl=1, free_surface=mc)
    run("mc cfl2    ", cfl=2, free_surface=mc)
    run("mc cfl1 vc0", cfl=1, volume_correction=0.0, free_surface=mc)
    run("mc cfl2 vc0", cfl=2, volume_correction=0.0, free_surface=mc)
else:
    run("cfl1      ", cfl=1)
    run("cfl2      ", cfl=2)
    run("cfl2 flip0.9025", cfl=2, flip_ratio=0.9025)
    run("cfl1 vc0  ", cfl=1, volume_correction=0.0)
    run("cfl2 vc0  ", cfl=2, volume_correction=0.0)
    run("cfl2 vc0 flip0.9025", cfl=2, volume_correction=0.0, flip_ratio=0.9025)
