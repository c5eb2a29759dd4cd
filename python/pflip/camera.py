"""Building a pf_camera from numpy: look-at and perspective matrices in OpenGL/glm conventions.

Matrices are 4x4 numpy arrays indexed [row, column] (M @ v transforms a column vector); pf_camera
wants them column-major, which is what Camera's constructor below writes.
"""
import numpy as np

from ._types import Camera, DepthConvention


def look_at(eye, target, up=(0.0, 1.0, 0.0)):
    """World -> eye matrix of a camera at eye looking at target (glm::lookAt, right-handed)."""
    eye, target, up = (np.asarray(v, dtype=np.float64) for v in (eye, target, up))
    f = target - eye
    f /= np.linalg.norm(f)
    s = np.cross(f, up)
    s /= np.linalg.norm(s)
    u = np.cross(s, f)
    m = np.identity(4)
    m[0, :3], m[1, :3], m[2, :3] = s, u, -f
    m[:3, 3] = -m[:3, :3] @ eye
    return m


def perspective(fovy_deg, aspect, near, far, convention=DepthConvention.STANDARD):
    """Eye -> clip matrix for a depth convention: STANDARD is glm::perspectiveNO (z in [-1, 1]),
    ZERO_TO_ONE glm::perspectiveZO, REVERSED_Z perspectiveZO with the planes swapped (near -> 1)."""
    t = 1.0 / np.tan(np.radians(fovy_deg) / 2.0)
    m = np.zeros((4, 4))
    m[0, 0], m[1, 1], m[3, 2] = t / aspect, t, -1.0
    n, f = (far, near) if convention == DepthConvention.REVERSED_Z else (near, far)
    if convention == DepthConvention.STANDARD:
        m[2, 2], m[2, 3] = -(f + n) / (f - n), -2.0 * f * n / (f - n)
    else:
        m[2, 2], m[2, 3] = f / (n - f), -f * n / (f - n)
    return m


def make_camera(view, proj, viewport, near, far, convention=DepthConvention.STANDARD):
    """A pf_camera from [row, column] numpy matrices; viewport is (x, y, width, height)."""
    cam = Camera()
    cam.view[:] = np.asarray(view, dtype=np.float32).flatten(order="F").tolist()
    cam.proj[:] = np.asarray(proj, dtype=np.float32).flatten(order="F").tolist()
    cam.viewport[:] = [int(v) for v in viewport]
    cam.near_plane, cam.far_plane = float(near), float(far)
    cam.depth_convention = int(convention)
    return cam


def project(camera, xyz):
    """Window coordinates (x, y in pixels, z the eye distance) of world points (N, 3) seen by
    camera: what a test or a tool needs to find particles on the image."""
    view = np.array(camera.view, dtype=np.float64).reshape(4, 4, order="F")
    proj = np.array(camera.proj, dtype=np.float64).reshape(4, 4, order="F")
    p = np.c_[np.asarray(xyz, dtype=np.float64), np.ones(len(xyz))]
    eye = p @ view.T
    clip = eye @ proj.T
    ndc = clip[:, :2] / clip[:, 3:4]
    x0, y0, w, h = camera.viewport
    return np.c_[x0 + (ndc[:, 0] * 0.5 + 0.5) * w, y0 + (ndc[:, 1] * 0.5 + 0.5) * h, -eye[:, 2]]
