"""pflip drawn by Panda3D's own frame, checked on Panda's pixels (headless EGL, llvmpipe in CI).

One Panda scene for the module (Panda allows one ShowBase a process): a still slab of particles
(never stepped, so every frame draws the same liquid), a crate in front of it, a crate behind it
and a card that Panda draws after the liquid. Each test toggles what it needs and compares two
frames, so nothing depends on a stored image.
"""
import ctypes

import numpy as np
import pytest

import pflip
from pflip.camera import project

SIZE = (240, 160)
SLAB_LO, SLAB_HI = (0.45, 0.05, 0.35), (1.15, 0.55, 0.45)  # pflip metres: a slab facing the camera


def lattice(lo, hi, spacing):
    axes = [np.arange(a + spacing / 2, b, spacing) for a, b in zip(lo, hi)]
    return np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3).astype(np.float32)


@pytest.fixture(scope="module")
def scene():
    from demo import LiquidScene

    xyz = lattice(SLAB_LO, SLAB_HI, LiquidScene.CELL / 2)
    s = LiquidScene(size=SIZE, crate=False, fill=lambda sim: sim.add_particles(xyz))
    s.liquid.stepping = False
    s.xyz = xyz
    s.base.cam.setPos(s.liquid.root, 0.8, 0.35, 1.5)  # close up: particles several pixels wide
    s.base.cam.lookAt(s.liquid.root, 0.8, 0.3, 0.4)
    # In front of the slab (nearer the camera), over its left part; behind it, over its right part.
    s.front = s.make_crate(pos_pflip=(0.6, 0.3, 0.7), size=0.16, color=(0.9, 0.9, 0.2, 1))
    s.back = s.make_crate(pos_pflip=(0.95, 0.3, 0.15), size=0.2, color=(1.0, 0.1, 0.1, 1))
    s.card = make_card(s)
    yield s
    s.close()


def make_card(s):
    """A flat unlit green card in the "fixed" bin after the liquid (sort 10 > the liquid's 0), in
    front of the slab's lower right corner: Panda draws it after pflip in the same buffer."""
    from panda3d.core import CardMaker

    cm = CardMaker("after_liquid")
    cm.setFrame(-0.1, 0.1, -0.1, 0.1)
    card = s.liquid.root.attachNewNode(cm.generate())
    card.setPos(1.05, 0.12, 0.62)
    card.setP(-90)  # CardMaker's card lies in x-z facing -y; pitched into pflip's x-y, facing +z
    card.setTwoSided(True)
    card.setLightOff()
    card.setColor(0.1, 0.9, 0.2, 1)
    card.setBin("fixed", 10)
    return card


def frame(s, liquid=True, front=False, back=False, card=False):
    s.liquid.drawing = liquid
    for node, shown in ((s.front, front), (s.back, back), (s.card, card)):
        node.show() if shown else node.hide()
    s.render_frame()
    return s.grab().astype(np.int16)


def changed(a, b, tol=0):
    return (np.abs(a - b) > tol).any(axis=-1)


def slab_masks(s):
    """Pixels (top row first) well inside and well outside the slab's projected particles' discs."""
    cam = s.liquid.camera()
    p = project(cam, s.xyz)
    h = SIZE[1]
    focal = np.array(cam.proj)[5] * h / 2
    r_px = s.liquid.ssf_params.particle_radius * focal / p[:, 2]
    ys, xs = np.mgrid[0:h, 0:SIZE[0]] + 0.5
    d = np.full(xs.shape, np.inf)
    for k in range(0, len(p), 256):  # the nearest disc outline, in chunks to bound memory
        q = slice(k, k + 256)
        dk = np.hypot(xs[..., None] - p[q, 0], ys[..., None] - p[q, 1]) - r_px[q]
        d = np.minimum(d, dk.min(axis=-1))
    d = d[::-1]  # GL rows are bottom-up; images here are top row first
    return d < -2.0, d > 2.0


def test_liquid_drawn_where_the_particles_project_and_nowhere_else(scene):
    without, with_liquid = frame(scene, liquid=False), frame(scene, liquid=True)
    inside, outside = slab_masks(scene)
    assert inside.sum() > 2000, "the slab must cover a real area for this test to mean anything"
    diff = changed(without, with_liquid)
    assert diff[inside].mean() > 0.95
    assert not diff[outside].any(), f"{diff[outside].sum()} pixels changed away from the liquid"


def test_a_model_in_front_hides_the_liquid(scene):
    base = frame(scene, liquid=False)
    crate = changed(base, frame(scene, liquid=False, front=True))  # where the front crate covers
    inside, _ = slab_masks(scene)
    covered = crate & inside
    assert covered.sum() > 150, "the front crate must overlap the slab"
    without, with_liquid = frame(scene, liquid=False, front=True), frame(scene, liquid=True, front=True)
    # The crate's own pixels (its outline's antialiasing aside) do not change when the liquid behind it is drawn.
    core = covered & ~np.roll(~covered, 1, 0) & ~np.roll(~covered, -1, 0) & ~np.roll(~covered, 1, 1) & ~np.roll(~covered, -1, 1)
    assert not changed(without, with_liquid)[core].any()
    # ... while the uncovered part of the slab shows liquid.
    assert changed(without, with_liquid)[inside & ~crate].mean() > 0.95


def test_a_model_behind_the_liquid_is_seen_through_it(scene):
    base = frame(scene, liquid=False)
    crate = changed(base, frame(scene, liquid=False, back=True))  # where the back crate is on screen
    inside, _ = slab_masks(scene)
    behind = crate & inside
    assert behind.sum() > 150, "the back crate must be behind the slab on screen"
    # With the liquid drawn, showing or hiding the red crate behind it changes the liquid's pixels
    # there (pflip refracts Panda's scene colour), and makes them redder.
    hidden, shown = frame(scene, back=False), frame(scene, back=True)
    assert changed(hidden, shown, tol=4)[behind].mean() > 0.8
    red = lambda img: img[..., 0] - (img[..., 1] + img[..., 2]) / 2  # noqa: E731
    assert red(shown)[behind].mean() > red(hidden)[behind].mean() + 20


# Controls: states pflip changes and restores, which Panda does not set again before its next
# draw, so leaving one changed must show on the card. (Panda re-applies its depth function, colour
# mask, blending and active texture unit per draw, so breaking those goes unseen; an unbound vertex
# array stays broken for later frames too. Neither kind makes a usable control.)
BREAKERS = {
    "viewport": (b"glViewport", [ctypes.c_int32] * 4, (0, 0, 8, 8)),
    "program": (b"glUseProgram", [ctypes.c_uint32], (0,)),
}


@pytest.mark.parametrize("breaker", [None] + sorted(BREAKERS), ids=lambda b: "pflip" if b is None else "control_" + b)
def test_panda_draws_correctly_after_the_liquid(scene, breaker):
    """Panda caches GL state between its draws: a card drawn after pflip must come out exactly as
    in a frame where pflip drew nothing. Each control leaves one state changed behind Panda's back
    (a draw callback between the liquid and the card), which the same comparison must catch."""
    ref = frame(scene, liquid=False, card=True)
    card = changed(frame(scene, liquid=False), ref)
    assert card.sum() > 200
    assert (ref[card][:, 1] > 150).mean() > 0.9, "the card is green"
    node = None
    if breaker is not None:
        node = scene.base.render.attachNewNode(_state_breaker(scene, *BREAKERS[breaker]))
        node.setBin("fixed", 5)
    try:
        after = frame(scene, liquid=True, card=True)
    finally:
        if node is not None:
            node.removeNode()
            frame(scene)  # Panda sets its state afresh on the next frame
    same = not changed(ref, after)[card].any()
    assert same == (breaker is None)


def _state_breaker(scene, name, argtypes, args):
    """A draw callback that calls one GL function and restores nothing."""
    from panda3d.core import CallbackNode, OmniBoundingVolume, PythonCallbackObject
    from pflip_panda import gl_loader

    fn = ctypes.CFUNCTYPE(None, *argtypes)(gl_loader(scene.base.pipe)(name))
    node = CallbackNode("breaks_state")
    node.setBounds(OmniBoundingVolume())
    node.setFinal(True)
    node.setDrawCallback(PythonCallbackObject(lambda cbdata: (fn(*args), cbdata.upcall())))
    return node


def test_render_stats_count_the_frames_panda_drew(scene):
    before = scene.liquid.frames
    frame(scene)
    frame(scene)
    assert scene.liquid.frames == before + 2
    assert scene.liquid.sim.stats().gpu_memory_bytes > 0
