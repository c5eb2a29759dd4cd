"""A Panda3D scene with pflip's liquid in it: a dam break in a glass-less tank that knocks a
floating crate (Panda's stock models/box.egg) around, the crate occluding the liquid and seen
through it. Panda owns the window or offscreen buffer, the camera and the render loop.

    python samples/engines/panda3d/demo.py                       # a window (needs a display)
    python samples/engines/panda3d/demo.py --offscreen --frames 120 --out shots/
                                                                   # headless EGL, PNGs every 30 frames

The library is found through $PFLIP_LIBRARY (or the source tree's build/), the Python client
through PYTHONPATH=python (docs/integration.md, "Panda3D").
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def configure_panda(offscreen, size):
    """Panda's PRC settings: a GL 4.3 core context (pflip's minimum), and the headless EGL pipe
    when there is no display. Must run before ShowBase is imported."""
    from panda3d.core import loadPrcFileData
    lines = ["gl-version 4 3", "audio-library-name null", "textures-power-2 none",
             "win-size %d %d" % size, "sync-video false", "notify-level-device fatal"]
    if offscreen:
        lines += ["load-display p3headlessgl", "window-type offscreen"]
    loadPrcFileData("pflip-panda3d", "\n".join(lines))


class LiquidScene:
    """The demo's scene, also what the tests drive: base (a ShowBase), liquid (a PandaLiquid),
    crate (the floating box's NodePath) and grab() (the frame as an RGB numpy image, top row first).

    fill: a callable fill(sim) run once the simulation exists (default: the dam break, a column at
    x = 0 beside a pool); crate: whether the floating crate is made and coupled."""

    TANK = (32, 20, 16)     # cells
    CELL = 0.05             # m: the tank is 1.6 x 1.0 x 0.8 m

    def __init__(self, offscreen=True, size=(480, 320), fill=None, crate=True, frame_dt=1.0 / 60.0):
        configure_panda(offscreen, size)
        from direct.filter.FilterManager import FilterManager
        from direct.showbase.ShowBase import ShowBase
        from panda3d.core import AmbientLight, CardMaker, DirectionalLight, Texture

        import pflip
        from pflip_panda import PandaLiquid

        self.base = base = ShowBase(windowType="offscreen" if offscreen else None)
        base.disableMouse()
        base.setBackgroundColor(0.55, 0.7, 0.9, 1)
        base.camLens.setNearFar(0.1, 20.0)
        base.camLens.setFov(50)

        # Panda renders the scene into its own FBO with a colour and a depth texture (the usual
        # Panda3D post-processing set-up); the window shows the colour texture on a quad.
        self.color_tex, self.depth_tex = Texture("scene_color"), Texture("scene_depth")
        self.filters = FilterManager(base.win, base.cam)
        quad = self.filters.renderSceneInto(colortex=self.color_tex, depthtex=self.depth_tex)
        quad.setColor(1, 1, 1, 1)  # FilterManager tints the quad (1, 0.5, 0.5) until given a shader
        self.scene_buffer = self.filters.buffers[0]

        sun = DirectionalLight("sun")
        sun.setColor((0.9, 0.9, 0.85, 1))
        sun_np = base.render.attachNewNode(sun)
        sun_np.setHpr(30, -50, 0)
        amb = AmbientLight("ambient")
        amb.setColor((0.35, 0.35, 0.4, 1))
        base.render.setLight(sun_np)
        base.render.setLight(base.render.attachNewNode(amb))


        params = pflip.SsfParams.default()
        params.particle_radius = 0.5 * self.CELL
        self.liquid = PandaLiquid(base, self.scene_buffer, self.color_tex, self.depth_tex, frame_dt=frame_dt,
                                  ssf_params=params, grid_size=self.TANK, cell_size=self.CELL,
                                  max_particles=1 << 17)
        self.liquid.on_first_draw(fill or self.dam_break)
        # Panda's world is Z-up; the tank's corner is at root (pflip's frame, y up). The camera and
        # the floor are placed in pflip's coordinates through root.
        root = self.liquid.root
        lx, ly, lz = (n * self.CELL for n in self.TANK)
        base.cam.setPos(root, lx / 2, 1.3, lz + 2.2)
        base.cam.lookAt(root, lx / 2, 0.3, lz / 2)
        cm = CardMaker("floor")
        cm.setFrame(-1, lx + 1, -lz - 3, 1)  # a card lies in its x-z plane, facing its -y
        floor = root.attachNewNode(cm.generate())
        floor.setP(180)  # facing pflip's +y (up), covering z in [-1, lz + 3]
        floor.setColor(0.45, 0.42, 0.38, 1)
        self.crate = None
        if crate:
            self.crate = self.make_crate(pos_pflip=(1.15, 0.28, 0.4), size=0.3)
            self.liquid.couple_box(self.crate, half_extents=(0.15, 0.15, 0.15), mass=0.3 ** 3 * 500.0)

    @staticmethod
    def dam_break(sim):
        sim.fill_box((0, 0, 0), (0.5, 0.7, 0.8))
        sim.fill_box((0.5, 0, 0), (1.6, 0.25, 0.8))

    def make_crate(self, pos_pflip, size, color=(0.8, 0.25, 0.1, 1)):
        """Panda's stock unit box (corner at its origin), centred on a parent node placed at a
        point of pflip's world."""
        crate = self.base.render.attachNewNode("crate")
        model = self.base.loader.loadModel("models/box")
        model.reparentTo(crate)
        model.setPos(-0.5, -0.5, -0.5)
        model.setColor(*color)
        crate.setScale(size)
        crate.setPos(self.liquid.root, *pos_pflip)
        return crate

    def render_frame(self):
        self.base.graphicsEngine.renderFrame()

    def grab(self):
        """The window's image after the last frame (Panda's screenshot: the scene buffer's colour,
        liquid included, shown on FilterManager's quad): (h, w, 3) uint8, top row first."""
        import numpy as np
        tex = self.base.win.getScreenshot()
        img = np.frombuffer(bytes(tex.getRamImageAs("RGB")), dtype=np.uint8)
        return img.reshape(tex.getYSize(), tex.getXSize(), 3)[::-1].copy()

    def close(self):
        self.liquid.close()
        self.filters.cleanup()
        self.base.destroy()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--offscreen", action="store_true", help="headless EGL (p3headlessgl), no window")
    ap.add_argument("--frames", type=int, default=0, help="stop after N frames (0: run until closed)")
    ap.add_argument("--size", default="960x540", help="WxH of the window or buffer")
    ap.add_argument("--out", default="", help="write the frame every --every frames as PNG here")
    ap.add_argument("--every", type=int, default=30, help="frames between PNGs (with --out)")
    a = ap.parse_args()
    try:
        size = tuple(int(v) for v in a.size.split("x"))
        assert len(size) == 2 and min(size) > 0
    except (ValueError, AssertionError):
        ap.error(f"--size: expected WxH, got {a.size!r}")
    if a.offscreen and a.frames <= 0:
        ap.error("--offscreen needs --frames N")
    scene = LiquidScene(offscreen=a.offscreen, size=size)
    if a.out:
        os.makedirs(a.out, exist_ok=True)
    if a.frames <= 0:
        scene.base.run()
        return
    from panda3d.core import Filename
    for frame in range(1, a.frames + 1):
        scene.render_frame()
        if a.out and frame % a.every == 0:
            path = os.path.join(a.out, "panda3d_%04d.png" % frame)
            if not scene.base.win.saveScreenshot(Filename.fromOsSpecific(path)):
                sys.exit(f"demo: could not write {path}")
            print(path)
    st = scene.liquid.sim.stats()
    print(f"{scene.liquid.frames} frames, {st.particle_count} particles, flags {st.flags:#x}, "
          f"crate at {[round(v, 3) for v in scene.crate.getPos(scene.liquid.root)]} (pflip's frame)")
    scene.close()


if __name__ == "__main__":
    main()
