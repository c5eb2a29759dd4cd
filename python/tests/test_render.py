"""pf_render_ssf and pf_render_particles into a moderngl framebuffer, as an engine calls them:
liquid appears where the particles' spheres project, the engine's frame is untouched elsewhere, and
scene depth in front of the liquid hides it."""
import numpy as np
import pytest

import pflip
from pflip.camera import look_at, make_camera, perspective, project

W, H, RADIUS = 128, 96, 0.05
BACKGROUND = (0.2, 0.3, 0.4, 1.0)


@pytest.fixture
def scene(gl):
    """Two clumps of particles in a 1 m cube (not stepped), a camera facing them, an engine frame."""
    rng = np.random.default_rng(7)
    xyz = np.concatenate([rng.uniform(0.25, 0.4, (40, 3)), rng.uniform(0.6, 0.7, (15, 3))]).astype(np.float32)
    sim = pflip.Simulation(grid_size=(16, 16, 16), cell_size=1.0 / 16, max_particles=1024)
    sim.add_particles(xyz)
    cam = make_camera(look_at((0.5, 0.5, 1.8), (0.5, 0.5, 0.5)), perspective(40.0, W / H, 0.1, 10.0),
                      (0, 0, W, H), 0.1, 10.0)
    frame = pflip.frame.Frame(gl, W, H)
    frame.clear(BACKGROUND, depth=1.0)
    yield sim, xyz, cam, frame
    frame.release()
    sim.close()


def signed_distance_to_discs(cam, xyz, radius):
    """Per pixel (rows bottom-up, as GL stores them): distance in pixels from the pixel centre to
    the nearest projected sphere's outline, negative inside it."""
    p = project(cam, xyz)
    focal = np.array(cam.proj)[5] * H / 2  # proj[1][1]: pixels per unit of y / z
    r_px = radius * focal / p[:, 2]
    ys, xs = np.mgrid[0:H, 0:W] + 0.5
    d = np.hypot(xs[..., None] - p[:, 0], ys[..., None] - p[:, 1]) - r_px
    return d.min(axis=-1)


def render(sim, cam, frame, how):
    if how == "ssf":
        params = pflip.SsfParams.default()
        params.particle_radius = RADIUS
        params.absorption[:] = [20.0, 5.0, 1.0]  # strongly tinted, so liquid never matches the background
        sim.render_ssf(cam, frame.target, params)
    else:
        params = pflip.ParticleParams.default()
        params.particle_radius = RADIUS
        sim.render_particles(cam, frame.target, params)


@pytest.mark.parametrize("how", ["ssf", "particles"])
def test_liquid_where_particles_project_and_background_elsewhere(scene, how):
    sim, xyz, cam, frame = scene
    color0, depth0 = frame.read_color()[::-1], frame.read_depth()[::-1]
    render(sim, cam, frame, how)
    color1, depth1 = frame.read_color()[::-1], frame.read_depth()[::-1]
    d = signed_distance_to_discs(cam, xyz, RADIUS)
    inside, outside = d < -1.5, d > 1.5  # a pixel and a half of margin for the outline's rasterisation
    assert inside.sum() > 200, "the spheres must cover a real area for this test to mean anything"

    # Away from every sphere the engine's frame is exactly as it was.
    assert (color1[outside] == color0[outside]).all()
    assert (depth1[outside] == depth0[outside]).all()
    # Inside the discs: liquid depth, nearer than the far plane, and a colour that is not the scene's.
    assert (depth1[inside] < depth0[inside]).all()
    changed = (color1[inside] != color0[inside]).any(axis=-1)
    assert changed.mean() > 0.95


def test_scene_in_front_hides_the_liquid(scene):
    sim, xyz, cam, frame = scene
    frame.clear(BACKGROUND, depth=0.0)  # the engine's scene covers everything at the near plane
    color0, depth0 = frame.read_color(), frame.read_depth()
    render(sim, cam, frame, "ssf")
    assert (frame.read_color() == color0).all() and (frame.read_depth() == depth0).all()


def test_render_stats_are_reported(scene):
    sim, xyz, cam, frame = scene
    render(sim, cam, frame, "ssf")
    render(sim, cam, frame, "ssf")
    st = sim.stats()
    assert st.render_cpu_ms > 0.0
