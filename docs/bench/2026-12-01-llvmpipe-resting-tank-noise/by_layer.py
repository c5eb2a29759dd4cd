import sys, numpy as np, pflip
from pflip import frame
ctx = frame.create_context()
def run(label, frames=1, **kw):
    n=16; dx=0.1
    sim = pflip.Simulation(grid_size=(n,n,n), cell_size=dx, max_particles=n*n*n*8)
    p = sim.params
    for k_,v_ in kw.items(): setattr(p,k_,v_)
    sim.params = p
    rng = np.random.default_rng(5); s = dx/2; jitter=0.8
    i,j,k = np.meshgrid(np.arange(32), np.arange(16), np.arange(32), indexing='ij')
    pos = np.stack([(i+0.5+jitter*(rng.random(i.shape)-0.5))*s, (j+0.5+jitter*(rng.random(i.shape)-0.5))*s, (k+0.5+jitter*(rng.random(i.shape)-0.5))*s], -1).reshape(-1,3).astype(np.float32)
    sim.add_particles(pos, np.zeros_like(pos))
    for f in range(frames): sim.step(0.1)
    x, v = sim.read_particles()
    L = np.clip(np.floor(pos[:,1]/dx).astype(int),0,7)
    print(label, "rms|v| by start layer (mm/s):", " ".join("%.1f"%(1000*np.sqrt((v[L==l]**2).sum(1).mean())) for l in range(8)), "| rms vy", " ".join("%.1f"%(1000*np.sqrt((v[L==l,1]**2).mean())) for l in range(8)))
run("default         ")
run("marker cell     ", free_surface=pflip.FreeSurface.MARKER_CELL)
run("vc 0            ", volume_correction=0.0)
run("tol 1e-6        ", pressure_tolerance=1e-6, pressure_iterations=200)
run("PIC             ", flip_ratio=0.0)
