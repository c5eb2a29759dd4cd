"""A dam break with the Python client: simulate, render the liquid with pf_render_ssf into a
moderngl framebuffer over a simple scene, and write PNGs.

    PYTHONPATH=python python python/examples/dam_break.py --frames 90 --every 30 --out out/python

Needs numpy, moderngl and Pillow (`pip install ./python[examples]`) and libpflip.so (PFLIP_LIBRARY,
or a build in build/ when run from the source tree).
"""
import argparse
import pathlib

import numpy as np
from PIL import Image

import pflip
from pflip.camera import look_at, make_camera, perspective


def scene_backdrop(width, height):
    """The 'engine's' scene behind the liquid: a vertical gradient (sky to floor), top row first."""
    t = np.linspace(0.0, 1.0, height)[:, None, None]
    sky, floor = np.array([0.55, 0.70, 0.90]), np.array([0.30, 0.28, 0.25])
    rgb = (1 - t) * sky + t * floor
    return np.broadcast_to(rgb, (height, width, 3))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--frames", type=int, default=90)
    ap.add_argument("--every", type=int, default=30, help="write a PNG every K frames")
    ap.add_argument("--size", default="640x360")
    ap.add_argument("--out", default="out/python")
    args = ap.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    ctx = pflip.frame.create_context()  # the engine's GL 4.3 context (EGL, headless)
    print(f"pflip {pflip.__version__} on {ctx.info['GL_RENDERER']}")
    # A 1.6 x 0.8 x 0.8 m tank with a column of water against its left wall.
    with pflip.Simulation(grid_size=(32, 16, 16), cell_size=0.05, max_particles=1 << 16) as sim, \
            pflip.frame.Frame(ctx, width, height) as frame:
        sim.fill_box((0.0, 0.0, 0.0), (0.4, 0.6, 0.8))
        cam = make_camera(look_at((0.8, 1.0, 2.4), (0.8, 0.25, 0.4)), perspective(45.0, width / height, 0.1, 20.0),
                          (0, 0, width, height), 0.1, 20.0)
        ssf = pflip.SsfParams.default()
        backdrop = scene_backdrop(width, height)
        for f in range(1, args.frames + 1):
            sim.step(1.0 / 60.0)
            if f % args.every:
                continue
            # The engine draws its scene into its framebuffer (here: far depth, then a backdrop image).
            frame.clear(depth=1.0)
            frame.write_color(backdrop)
            sim.render_ssf(cam, frame.target, ssf)
            path = out / f"dam_break_{f:04d}.png"
            Image.fromarray(frame.read_color()[..., :3]).save(path)
            xyz, _ = sim.read_particles(velocities=False)
            print(f"frame {f}: {path}  centre of mass {np.round(xyz.mean(axis=0), 3)}")
        st = sim.stats()
        print(f"{st.particle_count} particles, last step {st.substeps} substeps, GPU {st.gpu_total_ms:.1f} ms")


if __name__ == "__main__":
    main()
