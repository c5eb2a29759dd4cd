"""pflip inside Panda3D: a liquid that Panda's own frame steps and draws.

Panda3D owns the GL context, the render loop, the camera and the framebuffer. This module only
adds a node to Panda's scene graph whose draw callback (a CallbackNode, drawn in Panda's own cull
bin order) calls pf_step and pf_render_ssf on the draw thread, in Panda's context, with:

- the framebuffer Panda has bound at that moment and the GL names of Panda's scene colour and
  depth textures (the attachments of the buffer that FilterManager.renderSceneInto makes);
- Panda's camera: its lens projection and the camera's transform relative to the liquid;
- Panda's coordinate system (Z up, Y forward) converted to pflip's (Y up): the liquid's domain
  hangs under a NodePath, `root`, so it can sit anywhere in Panda's world.

Panda caches GL state between draws; pflip restores every state it touches (docs/integration.md
§4), so Panda's later draws in the same frame see exactly the state Panda believes is set.

Rigid bodies: `couple_box` makes a Panda NodePath a pflip box obstacle. Each frame the liquid reads
the node's pose from Panda, and the liquid's force (pf_get_obstacle_force) plus gravity moves the
node by a few lines of explicit integration (translation only; the body does not rotate).
"""
import ctypes
import ctypes.util

import numpy as np
from panda3d.core import CallbackNode, Mat3, OmniBoundingVolume, PythonCallbackObject

import pflip
from pflip.camera import make_camera

GL_DRAW_FRAMEBUFFER_BINDING = 0x8CA6

# Weight of the newest force reading in the body's force (see _Body.integrate).
FORCE_SMOOTHING = 0.35

# Panda's camera space (x right, y forward, z up) -> OpenGL eye space (x right, y up, -z forward).
PANDA_TO_GL_EYE = np.array([[1, 0, 0, 0], [0, 0, 1, 0], [0, -1, 0, 0], [0, 0, 0, 1]], dtype=np.float64)


def gl_loader(pipe):
    """The GL loader of Panda's pipe, as pf_create wants it: eglGetProcAddress for the EGL pipes
    (p3headlessgl, and pandagl built for EGL), glXGetProcAddressARB for GLX windows."""
    if "glx" in pipe.getType().getName().lower():
        libgl = ctypes.CDLL(ctypes.util.find_library("GL") or "libGL.so.1")
        fn = libgl.glXGetProcAddressARB
        fn.restype, fn.argtypes = ctypes.c_void_p, [ctypes.c_char_p]
        return ctypes.cast(fn, pflip._types.GetProcAddressFn)
    from pflip.egl import get_proc_address
    return get_proc_address()


def panda_mat(m):
    """A Panda Mat4 (row vectors: p' = p * M) as a [row, column] numpy matrix for column vectors."""
    return np.array([[m.getCell(r, c) for c in range(4)] for r in range(4)], dtype=np.float64).T


class PandaLiquid:
    """A pflip simulation stepped and drawn by Panda3D.

    base: the ShowBase. scene_buffer, color_tex, depth_tex: the offscreen buffer the scene renders
    into and its colour and depth textures (FilterManager.renderSceneInto gives them). sim_desc
    fields are keyword arguments (grid_size, cell_size, max_particles, ...). The domain's corner is
    at root's origin; root is parented to base.render with pflip's +y along Panda's +z.
    """

    def __init__(self, base, scene_buffer, color_tex, depth_tex, *, frame_dt=1.0 / 60.0, ssf_params=None,
                 draw_sort=0, **sim_fields):
        self.base, self.buffer, self.color_tex, self.depth_tex = base, scene_buffer, color_tex, depth_tex
        self.frame_dt = frame_dt
        self.ssf_params = ssf_params if ssf_params is not None else pflip.SsfParams.default()
        self.stepping = True      # pf_step once per drawn frame
        self.drawing = True       # pf_render_ssf once per drawn frame
        self.bodies = []          # [_Body], moved by the liquid's force each frame
        self.sim = None
        self._sim_fields = sim_fields
        self._setup_calls = []    # work for the first draw, when Panda's context is current
        self.frames = 0
        self._gl_get_integerv = None

        # pflip's world (y up) under Panda's (z up): a pitch of +90 degrees maps y to z, z to -y.
        self.root = base.render.attachNewNode("pflip_liquid")
        self.root.setP(90)
        node = CallbackNode("pflip_draw")
        node.setDrawCallback(PythonCallbackObject(self._draw))
        # Draw after the opaque scene (it must be in the colour and depth textures) and before
        # whatever the engine draws later in the "fixed" bin. An infinite bound keeps it from
        # being culled: the liquid moves and the node has no geometry of its own.
        node.setBounds(OmniBoundingVolume())
        node.setFinal(True)
        self.node = self.root.attachNewNode(node)
        self.node.setBin("fixed", draw_sort)
        self.node.setDepthWrite(False)

    # ---- set-up that needs the GL context (run on the first draw) -------------------------------
    def on_first_draw(self, fn):
        """fn(sim) runs in the first draw callback, right after pf_create (fill particles there)."""
        self._setup_calls.append(fn)

    def couple_box(self, nodepath, half_extents, mass):
        """Makes nodepath (a box of half_extents in metres along its own axes, centred on its origin)
        a pflip obstacle that the liquid pushes, from the next drawn frame on: mass in kg; gravity is
        the simulation's."""
        body = _Body(nodepath, np.asarray(half_extents, dtype=np.float64), float(mass))
        self.bodies.append(body)
        return body

    # ---- the draw callback ----------------------------------------------------------------------
    def _draw(self, cbdata):
        gsg = self.base.win.getGsg()
        if self.sim is None:
            self._create()
        if self.stepping:
            self._sync_bodies_before_step()
            self.sim.step(self.frame_dt)
            self._move_bodies()
        if self.drawing:
            self.sim.render_ssf(self.camera(), self.target(gsg), self.ssf_params)
        self.frames += 1
        cbdata.upcall()  # the node's own geometry: none, but Panda expects the call

    def _create(self):
        loader = gl_loader(self.base.pipe)
        self.sim = pflip.Simulation(get_proc_address=loader, **self._sim_fields)
        get = ctypes.cast(loader(b"glGetIntegerv"), ctypes.CFUNCTYPE(None, ctypes.c_uint32,
                                                                     ctypes.POINTER(ctypes.c_int32)))
        self._gl_get_integerv = get
        for fn in self._setup_calls:
            fn(self.sim)

    def target(self, gsg):
        """The pf_render_target of this draw: Panda's bound framebuffer and its textures' GL names."""
        fbo = ctypes.c_int32(0)
        self._gl_get_integerv(GL_DRAW_FRAMEBUFFER_BINDING, ctypes.byref(fbo))
        t = pflip.RenderTarget()
        t.framebuffer = fbo.value
        t.scene_color = self._gl_name(self.color_tex, gsg)
        t.scene_depth = self._gl_name(self.depth_tex, gsg)
        return t

    @staticmethod
    def _gl_name(tex, gsg):
        return tex.prepareNow(0, gsg.getPreparedObjects(), gsg).getNativeId()

    def camera(self):
        """pf_camera of Panda's camera: view = Panda->GL eye axes times the camera's transform
        from the liquid's frame; proj = Panda's lens projection (clip z in [-1, 1]: the standard
        convention) taking GL eye coordinates."""
        cam = self.base.cam
        lens = cam.node().getLens()
        view = PANDA_TO_GL_EYE @ panda_mat(self.root.getMat(cam))
        proj = panda_mat(lens.getProjectionMat()) @ np.linalg.inv(PANDA_TO_GL_EYE)
        w, h = self.buffer.getXSize(), self.buffer.getYSize()
        return make_camera(view, proj, (0, 0, w, h), lens.getNear(), lens.getFar(),
                           pflip.DepthConvention.STANDARD)

    # ---- rigid bodies ---------------------------------------------------------------------------
    def _sync_bodies_before_step(self):
        for body in self.bodies:
            if body.obstacle_id is None:  # coupled since the last draw: pflip learns of it now
                body.cell_size = self.sim.desc.cell_size
                body.obstacle_id = self.sim.add_obstacle(shape="box", **body.pose_in(self.root),
                                                         half_extents=body.half_extents.tolist())
                self.sim.features = self.sim.features | pflip.Feature.OBSTACLES
            else:
                self.sim.set_obstacle(body.obstacle_id, **body.pose_in(self.root))

    def _move_bodies(self):
        gravity = np.array(self.sim.params.gravity, dtype=np.float64)
        d = self.sim.desc
        domain = np.array(d.origin, dtype=np.float64), np.array(d.origin) + np.array(d.grid_size) * d.cell_size
        for body in self.bodies:
            body.integrate(self.sim.obstacle_force(body.obstacle_id), gravity, self.frame_dt, self.root, domain)

    def close(self):
        """pf_destroy (call while Panda's context is current, e.g. before base.destroy())."""
        if self.sim is not None:
            self.sim.close()
            self.sim = None
        self.node.removeNode()
        self.root.removeNode()


class _Body:
    """A Panda node moved by the liquid: its velocity lives here, in pflip's (y-up) frame."""

    def __init__(self, nodepath, half_extents, mass):
        self.node, self.half_extents, self.mass = nodepath, half_extents, mass
        self.velocity = np.zeros(3)
        self.cell_size = 0.0  # the simulation's, set when it is created
        self.obstacle_id = None
        self.last_force_step = 0
        self.force = np.zeros(3)

    def pose_in(self, root):
        """position, rotation (x, y, z, w) and velocity in root's frame (pflip's world)."""
        p = self.node.getPos(root)
        q = self.node.getQuat(root)  # Panda's (r, i, j, k)
        return {"position": [p[0], p[1], p[2]], "rotation": [q.getI(), q.getJ(), q.getK(), q.getR()],
                "velocity": self.velocity.tolist()}

    def integrate(self, reading, gravity, dt, root, domain):
        """Semi-implicit Euler with the newest liquid force. pflip reads forces back a few steps
        late without stalling, and an explicit coupling with a late force overshoots for a light
        body (its added mass is comparable to its own), so the force is low-pass filtered over
        about 3 frames. The body stays inside the domain, a cell away from its walls (a body flush
        with a wall would shut the liquid out from under it): a wall stops its velocity into it."""
        if reading.step != 0 and reading.step != self.last_force_step:
            self.force += FORCE_SMOOTHING * (np.array(reading.force, dtype=np.float64) - self.force)
            self.last_force_step = reading.step
        self.velocity += (self.force / self.mass + gravity) * dt
        p = np.array(self.node.getPos(root)) + self.velocity * dt
        rot = Mat3()
        self.node.getQuat(root).extractToMatrix(rot)  # rows: the body's axes in root's frame
        reach = np.abs(np.array(rot)).T @ self.half_extents  # the body's half size along root's axes
        gap = self.cell_size
        lo, hi = domain[0] + reach + gap, domain[1] - reach - gap
        hit = (p < lo) | (p > hi)
        p = np.clip(p, lo, hi)
        self.velocity[hit] = 0.0
        self.node.setPos(root, *p)
