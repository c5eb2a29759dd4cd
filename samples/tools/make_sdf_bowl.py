#!/usr/bin/env python3
"""Writes samples/scenes/bowl.npy: the signed distance of a hemispherical bowl, the SDF
asset of samples/scenes/effects_sdf.json (docs/effects.md describes the format).

The grid tiles the obstacle's local box [-h, h], h = (0.32, 0.2, 0.32) m, with 32 x 20 x 32
equal cells of 2 cm; a[i, j, k] is the distance in metres (negative inside the wall) at the
centre of cell (i, j, k): local x = -h_x + (i + 0.5) * 0.02, likewise y (j) and z (k). float16
keeps the file at 40 KiB; its rounding (< 0.25 mm here) is far below a cell.

The bowl: a spherical shell about local (0, 0.08, 0), radii 0.19 to 0.27 m, below the plane
y = 0.08 (its rim), open upwards. Exact distance of that half annulus, revolved about y.

    .venv/bin/python samples/tools/make_sdf_bowl.py [output.npy]
"""
import sys
from pathlib import Path

import numpy as np

HALF = np.array([0.32, 0.20, 0.32])
SHAPE = (32, 20, 32)
CENTRE_Y, MID_RADIUS, HALF_THICKNESS = 0.08, 0.23, 0.04


def bowl_distance(x, y, z):
    """Signed distance (m) of the bowl at local points; tests/scene/ repeats this formula."""
    rho = np.hypot(x, z)
    yc = y - CENTRE_Y
    below = np.abs(np.hypot(rho, yc) - MID_RADIUS) - HALF_THICKNESS
    # Above the rim plane the nearest point is on the rim's ring (radii 0.19..0.27 at yc = 0).
    ring = np.maximum(np.abs(rho - MID_RADIUS) - HALF_THICKNESS, 0.0)
    above = np.hypot(ring, yc)
    return np.where(yc <= 0.0, below, above)


def main():
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parents[1] / "scenes" / "bowl.npy"
    axes = [-h + (np.arange(n) + 0.5) * 2 * h / n for h, n in zip(HALF, SHAPE)]
    x, y, z = np.meshgrid(*axes, indexing="ij")  # a[i, j, k]: i along x, j along y, k along z
    grid = bowl_distance(x, y, z).astype("<f2")
    out.parent.mkdir(parents=True, exist_ok=True)
    np.save(out, grid)
    print(f"{out}: shape {grid.shape}, {grid.dtype}, distances {grid.min():.4f} .. {grid.max():.4f} m")


if __name__ == "__main__":
    main()
