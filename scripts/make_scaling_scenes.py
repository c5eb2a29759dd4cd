#!/usr/bin/env python3
"""Writes the scaling family of docs/performance.md (samples/scenes/scaling/): the dam break of
dam_break_1m (a 2 x 1 x 1 m tank, a 0.75 x 0.75 x 1 m column at 8 particles per cell) at the
resolutions that give about 0.1M, 0.5M, 1M, 2M, 5M, 10M and 20M particles. n cells per metre,
a multiple of 4 so the column is whole cells: 4.5 n^3 particles (capacity 5% above).

usage: scripts/make_scaling_scenes.py [OUTDIR]
"""
import json
import os
import sys

RESOLUTIONS = {"0.1m": 28, "0.5m": 48, "1m": 60, "2m": 76, "5m": 104, "10m": 132, "20m": 164}


def scene(label, n):
    column = 3 * n // 4
    particles = column * column * n * 8
    return {
        "name": f"scaling_{label}",
        "description": (f"Scaling family (scripts/make_scaling_scenes.py): dam break, {2 * n}x{n}x{n} cells of 1/{n} m "
                        f"(2 x 1 x 1 m tank), a 0.75 x 0.75 x 1 m column, {particles:,} particles at 8 per cell."),
        "grid": {"size": [2 * n, n, n], "cell_size": 1.0 / n, "origin": [0, 0, 0]},
        "max_particles": -(-particles * 21 // 20 // 1024) * 1024,  # 5% room, whole KiB
        "particles_per_cell": 8,
        "fill": [{"lo": [0.0, 0.0, 0.0], "hi": [0.75, 0.75, 1.0]}],
        "params": {"max_substeps": 16},
        "frame_dt": 0.016666667,
        "frames": 150,
        "camera": {"eye": [2.35, 1.75, 3.0], "target": [0.95, 0.3, 0.5], "fov": 40},
    }


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "samples", "scenes", "scaling")
    os.makedirs(out, exist_ok=True)
    for label, n in RESOLUTIONS.items():
        with open(os.path.join(out, f"scaling_{label}.json"), "w") as f:
            json.dump(scene(label, n), f, indent=2)
            f.write("\n")


if __name__ == "__main__":
    main()
