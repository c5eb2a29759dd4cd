"""A GL context and an engine-style render target made with moderngl (optional dependency).

pflip never creates a GL context: like an engine, this module makes one (moderngl's standalone
EGL context, GL 4.3 core or newer) and a framebuffer with a colour and a depth texture that
pf_render_ssf draws into, then reads the image back as numpy.
"""
import numpy as np

from ._types import RenderTarget


def create_context(**kwargs):
    """A headless moderngl context through EGL, GL 4.3 core at least (current on this thread)."""
    import moderngl

    kwargs.setdefault("backend", "egl")
    kwargs.setdefault("require", 430)
    return moderngl.create_standalone_context(**kwargs)


class Frame:
    """Colour (RGBA8) and depth (32-bit float) textures in one framebuffer: the engine's frame.

    target is the RenderTarget for pf_render_ssf: the colour texture doubles as the scene behind
    the liquid (pflip copies it before drawing, so this is no feedback loop) and the depth texture
    occludes the liquid and receives its depth.
    """

    def __init__(self, ctx, width, height):
        self.ctx, self.width, self.height = ctx, int(width), int(height)
        self.color = ctx.texture((self.width, self.height), 4, dtype="f1")
        self.depth = ctx.depth_texture((self.width, self.height))
        self.fbo = ctx.framebuffer(color_attachments=[self.color], depth_attachment=self.depth)

    @property
    def target(self):
        return RenderTarget(self.fbo.glo, self.color.glo, self.depth.glo, 0)

    def clear(self, color=(0.0, 0.0, 0.0, 1.0), depth=1.0):
        """The scene: one colour everywhere at the given window depth (1.0: far, standard depth)."""
        self.fbo.clear(*color, depth=depth)

    def write_color(self, image):
        """Upload the scene's colour: (height, width, 3 or 4), uint8 or floats in [0, 1], top row
        first (the depth is left as it is)."""
        img = np.asarray(image)
        if img.dtype != np.uint8:
            img = (np.clip(img, 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8)
        if img.shape[:2] != (self.height, self.width) or img.shape[2] not in (3, 4):
            raise ValueError(f"expected ({self.height}, {self.width}, 3 or 4), got {img.shape}")
        if img.shape[2] == 3:
            img = np.dstack([img, np.full(img.shape[:2], 255, np.uint8)])
        self.color.write(np.ascontiguousarray(img[::-1]).tobytes())

    def read_color(self):
        """(height, width, 4) uint8, top row first (as an image file stores it)."""
        data = np.frombuffer(self.color.read(), dtype=np.uint8).reshape(self.height, self.width, 4)
        return data[::-1].copy()

    def read_depth(self):
        """(height, width) float32 window depth, top row first."""
        data = np.frombuffer(self.depth.read(), dtype=np.float32).reshape(self.height, self.width)
        return data[::-1].copy()

    def release(self):
        for obj in (self.fbo, self.color, self.depth):
            obj.release()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.release()
