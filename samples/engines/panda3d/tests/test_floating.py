"""Two-way coupling inside Panda3D: Panda drives a crate's pose into pflip each frame, and pflip's
force on it (pf_get_obstacle_force) moves the crate. A crate lighter than water must come to float
at the depth Archimedes gives, a heavier-than-half one lower; a pose Panda sets is the obstacle's.
"""
import numpy as np
import pytest

POOL = 0.25    # m of still water in the 1.6 x 1.0 x 0.8 m tank
CRATE = 0.3    # m, edge of the cube
FRAMES = 240   # 4 s at 1/60 s
CELL = 0.05    # m, LiquidScene's


@pytest.fixture(scope="module")
def scene():
    from demo import LiquidScene

    s = LiquidScene(size=(160, 96), crate=False, fill=lambda sim: sim.fill_box((0, 0, 0), (1.6, POOL, 0.8)))
    s.liquid.drawing = False  # physics only: Panda still runs the draw callback every frame
    yield s
    s.close()


def test_crates_float_where_archimedes_puts_them(scene):
    """Two crates drop in side by side and settle: the centre of one half as dense as water comes to
    rest level with the water line, one of 800 kg/m^3 0.09 m lower (submerged depth = edge * density
    / 1000)."""
    crates = []
    for density, x in ((500.0, 0.45), (800.0, 1.15)):
        crate = scene.make_crate(pos_pflip=(x, POOL + 0.1, 0.4), size=CRATE)  # just above the water
        scene.liquid.couple_box(crate, half_extents=(CRATE / 2,) * 3, mass=CRATE ** 3 * density)
        crates.append(crate)
    heights = []
    for _ in range(FRAMES):
        scene.render_frame()
        heights.append([c.getPos(scene.liquid.root)[1] for c in crates])
    h_light, h_heavy = np.array(heights).T
    # Water line: the pool raised by what the two crates displace (their submerged volumes).
    displaced = CRATE ** 2 * (CRATE * 0.5 + CRATE * 0.8)
    water = POOL + displaced / (1.6 * 0.8)
    expect_light = water + CRATE / 2 - CRATE * 0.5
    expect_heavy = water + CRATE / 2 - CRATE * 0.8
    last = slice(-60, None)  # the last second
    print(f"light {h_light[last].mean():.3f} (expect {expect_light:.3f}), heavy {h_heavy[last].mean():.3f} "
          f"(expect {expect_heavy:.3f})")
    assert h_light.min() < expect_light, "the light crate fell into the water"
    # pflip sees the crate at cell resolution (5 cm cells, the crate 6 cells wide): a cell of error.
    assert abs(h_light[last].mean() - expect_light) < CELL
    assert abs(h_heavy[last].mean() - expect_heavy) < CELL
    sink = h_light[last].mean() - h_heavy[last].mean()
    assert abs(sink - CRATE * 0.3) < 0.6 * CELL, f"the heavier crate floats {sink:.3f} m lower"
    assert np.ptp(h_light[last]) < CELL and np.ptp(h_heavy[last]) < CELL, "still bobbing"


def test_the_pose_panda_sets_is_the_obstacles(scene):
    crate = scene.make_crate(pos_pflip=(0.8, 0.6, 0.4), size=0.2)
    body = scene.liquid.couple_box(crate, half_extents=(0.1,) * 3, mass=10.0)
    scene.render_frame()
    crate.setPos(scene.liquid.root, 0.7, 0.55, 0.3)  # the engine moves it (a teleport)
    crate.setH(30)  # and turns it 30 degrees about Panda's up (Z), which is pflip's y
    scene.render_frame()  # the pose goes to pflip before the step, then the crate moves on
    o = scene.liquid.sim.obstacles[body.obstacle_id]
    np.testing.assert_allclose(o.position, (0.7, 0.55, 0.3), atol=1e-5)
    # The obstacle's rotation maps the crate's own axes into pflip's frame: its up (Panda's Z) is
    # pflip's y; its x, turned 30 degrees about the up axis, is (cos 30, 0, -sin 30) in pflip's frame.
    x, y, z, w = o.rotation
    def rotate(v):
        u = np.array([x, y, z])
        return v + 2 * np.cross(u, np.cross(u, v) + w * v)
    np.testing.assert_allclose(rotate(np.array([0.0, 0.0, 1.0])), (0, 1, 0), atol=1e-5)
    c, s_ = np.cos(np.radians(30)), np.sin(np.radians(30))
    np.testing.assert_allclose(rotate(np.array([1.0, 0.0, 0.0])), (c, 0, -s_), atol=1e-5)
