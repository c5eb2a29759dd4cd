import sys, numpy as np, pflip
from pflip import frame
ctx = frame.create_context()
def run(label, cfl, vc=0.5, frames=100, flip=None, adv="EULER", tol=None, fs=None):
    n=16; dx=0.1
    sim = pflip.Simulation(grid_size=(n,n,n), cell_size=dx, max_particles=n*n*n*8)
    p = sim.params; p.cfl = cfl; p.volume_correction = vc; p.advection = getattr(pflip.Advection, adv)
    if flip is not None: p.flip_ratio = flip
    if tol is not None: p.pressure_tolerance = tol
    if fs is not None: p.free_surface = fs
    sim.params = p
    rng = np.random.default_rng(5); s = dx/2
    i,j,k = np.meshgrid(np.arange(32), np.arange(16), np.arange(32), indexing='ij')
    pos = np.stack([(i+0.5+0.8*(rng.random(i.shape)-0.5))*s, (j+0.5+0.8*(rng.random(i.shape)-0.5))*s, (k+0.5+0.8*(rng.random(i.shape)-0.5))*s], -1).reshape(-1,3).astype(np.float32)
    vel = rng.uniform(-0.01, 0.01, pos.shape).astype(np.float32)
    sim.add_particles(pos, vel)
    out=[]
    for f in range(1, frames+1):
        sim.step(0.1)
        if f in (10, 30, 60, 100):
            x, v = sim.read_particles()
            idx = np.clip(np.floor(x/dx).astype(int), 0, n-1)
            c = np.bincount((idx[:,0]*n+idx[:,1])*n+idx[:,2], minlength=n**3)
            vol = np.minimum(c,8).sum()/len(x)-1
            out.append(f"f{f}: vol {vol:+.4f} rms|v| {1000*np.sqrt((v**2).sum(1).mean()):.1f} mm/s")
    print(label, " | ".join(out))
run("mc cfl1    ", 1, fs=pflip.FreeSurface.MARKER_CELL)
run("mc cfl2    ", 2, fs=pflip.FreeSurface.MARKER_CELL)
run("mc cfl1 vc0", 1, vc=0, fs=pflip.FreeSurface.MARKER_CELL)
run("mc cfl2 vc0", 2, vc=0, fs=pflip.FreeSurface.MARKER_CELL)
