#!/usr/bin/env python3
"""What sets a dam break's substep count, frame by frame
(docs/notes/2026-11-27-kernel-profile-and-gaps.md):
the fastest particles (how many exceed 1.5 times the speed of free fall from the column's top, and
where the fastest are) and the most crowded cells. dam_break_1m's tank (2 x 1 x 1 m) and column
(0.75 x 0.75 x 1 m) at N cells a metre, 8 particles a cell, the balanced preset, through the
Python client (any GL the client finds: llvmpipe here).

usage: PFLIP_LIBRARY=build/libpflip.so PYTHONPATH=python scripts/dam_break_speeds.py
           [--cells-per-metre 64] [--frames 50] [--max-substeps 64] [--column X Y Z] [--from-frame F]
(dam_break_10m: --cells-per-metre 128 --column 0.78125 0.78125 1 --max-substeps 16)
"""
import argparse

import numpy as np

import pflip


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cells-per-metre", type=int, default=64)
    ap.add_argument("--frames", type=int, default=50)
    ap.add_argument("--max-substeps", type=int, default=64, help="high enough that CFL alone decides")
    ap.add_argument("--column", type=float, nargs=3, default=(0.75, 0.75, 1.0), help="the column's size in metres")
    ap.add_argument("--from-frame", type=int, default=0, help="print frames from this one on")
    args = ap.parse_args()
    n = args.cells_per_metre
    dx = 1.0 / n
    ctx = pflip.frame.create_context()
    sim = pflip.Simulation(grid_size=(2 * n, n, n), cell_size=dx, max_particles=8 * 2 * n * n * n)
    sim.set_quality(pflip.Quality.BALANCED)
    params = sim.params
    params.max_substeps = args.max_substeps
    sim.params = params
    sim.fill_box((0.0, 0.0, 0.0), tuple(args.column))
    free_fall = np.sqrt(2.0 * 9.81 * args.column[1])
    grid = np.array([2 * n, n, n])
    print(f"{2 * n}x{n}x{n} cells, {sim.particle_count} particles; free fall from the column's top "
          f"{free_fall:.2f} m/s")
    print("frame substeps flags  max m/s  >1.5 free fall  fastest at (m)       most in a cell (at cell)")
    for frame in range(args.frames):
        sim.step(1.0 / 60.0)
        if frame < args.from_frame:
            continue
        pos, vel = sim.read_particles()
        speed = np.linalg.norm(vel, axis=1)
        fastest = int(np.argmax(speed))
        cell = np.clip(np.floor(pos / dx).astype(np.int64), 0, grid - 1)
        key = cell[:, 0] + grid[0] * (cell[:, 1] + grid[1] * cell[:, 2])
        keys, counts = np.unique(key, return_counts=True)
        crowded = int(keys[np.argmax(counts)])
        at = (int(crowded % grid[0]), int(crowded // grid[0] % grid[1]), int(crowded // (grid[0] * grid[1])))
        st = sim.stats()
        print(f"{frame:5d} {st.substeps:8d} {st.flags:#6x} {speed.max():8.2f} {int((speed > 1.5 * free_fall).sum()):15d}  "
              f"({pos[fastest, 0]:.2f}, {pos[fastest, 1]:.2f}, {pos[fastest, 2]:.2f})   {counts.max():4d} {at}",
              flush=True)
    sim.close()
    ctx.release()


if __name__ == "__main__":
    main()
