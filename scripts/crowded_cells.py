#!/usr/bin/env python3
"""The most crowded cell of a dam break, frame by frame (docs/notes/2026-11-27-wall-return.md):
how many particles it holds, where inside it they sit (how many on a wall's plane), how they move,
and how full its neighbours are. dam_break_1m's tank (2 x 1 x 1 m) at N cells a metre, 8 particles
a cell, the balanced preset, through the Python client.

usage: PFLIP_LIBRARY=build/libpflip.so PYTHONPATH=python scripts/crowded_cells.py
           [--cells-per-metre 64] [--frames 97] [--from-frame 66] [--every 3] [--column X Y Z]
           [--max-substeps 16] [--cfl 1] [--advection euler|rk2|rk3]
(dam_break_10m: --cells-per-metre 128 --column 0.78125 0.78125 1)
"""
import argparse

import numpy as np

import pflip


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cells-per-metre", type=int, default=64)
    ap.add_argument("--frames", type=int, default=97)
    ap.add_argument("--from-frame", type=int, default=66)
    ap.add_argument("--every", type=int, default=3, help="report every this many frames")
    ap.add_argument("--column", type=float, nargs=3, default=(0.75, 0.75, 1.0), help="the column's size in metres")
    ap.add_argument("--max-substeps", type=int, default=16)
    ap.add_argument("--cfl", type=float, default=0.0, help="projection CFL (0: the preset's)")
    ap.add_argument("--advection", choices=["euler", "rk2", "rk3"], default=None)
    args = ap.parse_args()
    n = args.cells_per_metre
    dx = 1.0 / n
    grid = np.array([2 * n, n, n])
    ctx = pflip.frame.create_context()
    sim = pflip.Simulation(grid_size=tuple(int(g) for g in grid), cell_size=dx, max_particles=8 * int(grid.prod()))
    sim.set_quality(pflip.Quality.BALANCED)
    params = sim.params
    params.max_substeps = args.max_substeps
    if args.cfl > 0:
        params.cfl = args.cfl
    if args.advection:
        params.advection = pflip.Advection[args.advection.upper()]
    sim.params = params
    sim.fill_box((0.0, 0.0, 0.0), tuple(args.column))
    np.set_printoptions(precision=4, suppress=True, linewidth=200)
    on_wall = 0.01  # cells: the wall clamp keeps a stopped particle 1e-3 cells inside
    for frame in range(args.frames):
        sim.step(1.0 / 60.0)
        if frame < args.from_frame or (frame - args.from_frame) % args.every:
            continue
        pos, vel = sim.read_particles()
        g = pos / dx
        cell = np.clip(np.floor(g).astype(np.int64), 0, grid - 1)
        key = cell[:, 0] + grid[0] * (cell[:, 1] + grid[1] * cell[:, 2])
        keys, counts = np.unique(key, return_counts=True)
        top = int(keys[np.argmax(counts)])
        at = np.array([top % grid[0], top // grid[0] % grid[1], top // (grid[0] * grid[1])])
        inside = g[key == top] - at
        v = vel[key == top]
        st = sim.stats()
        print(f"frame {frame} substeps {st.substeps} flags {st.flags:#x} most in a cell {counts.max()} at {at}",
              flush=True)
        print("  where in the cell: min", inside.min(0), "max", inside.max(0), "median", np.median(inside, 0))
        print("  on its low x / y face (a wall's plane in cells that touch one):", int((inside[:, 0] < on_wall).sum()),
              int((inside[:, 1] < on_wall).sum()), " velocity mean", v.mean(0), "min", v.min(0), "max", v.max(0))
        count_of = dict(zip(keys.tolist(), counts.tolist()))
        beside = {}
        for i in range(3):
            for j in range(3):
                q = at + np.array([i, j, 0])
                if (q < grid).all():
                    beside[(i, j)] = count_of.get(int(q[0] + grid[0] * (q[1] + grid[1] * q[2])), 0)
        print("  its x-y neighbours (+i, +j): count", beside)
        print("  particles on the x = 0 plane:", int((g[:, 0] < on_wall).sum()), " on y = 0:",
              int((g[:, 1] < on_wall).sum()), flush=True)
    sim.close()
    ctx.release()


if __name__ == "__main__":
    main()
