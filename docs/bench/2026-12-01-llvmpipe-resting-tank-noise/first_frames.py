import sys, numpy as np, pflip
from pflip import frame
ctx = frame.create_context()
def run(label, cfl, noise, vc=0.5, frames=10, dtf=0.1, jitter=0.8, **kw):
    n=16; dx=0.1
    sim = pflip.Simulation(grid_size=(n,n,n), cell_size=dx, max_particles=n*n*n*8)
    p = sim.params; p.cfl = cfl; p.volume_correction = vc
    for k_,v_ in kw.items(): setattr(p,k_,v_)
    sim.params = p
    rng = np.random.default_rng(5); s = dx/2
    i,j,k = np.meshgrid(np.arange(32), np.arange(16), np.arange(32), indexing='ij')
    pos = np.stack([(i+0.5+jitter*(rng.random(i.shape)-0.5))*s, (j+0.5+jitter*(rng.random(i.shape)-0.5))*s, (k+0.5+jitter*(rng.random(i.shape)-0.5))*s], -1).reshape(-1,3).astype(np.float32)
    vel = rng.uniform(-noise, noise, pos.shape).astype(np.float32)
    sim.add_particles(pos, vel)
    out=[]
    for f in range(1, frames+1):
        sim.step(dtf)
        x, v = sim.read_particles()
        out.append("%.1f" % (1000*np.sqrt((v**2).sum(1).mean())))
    print(label, "rms|v| mm/s per frame:", " ".join(out))
for cfl in (1,2):
    run(f"cfl{cfl} noise0 jit0.8", cfl, 0.0)
    run(f"cfl{cfl} noise0 jit0  ", cfl, 0.0, jitter=0.0)
    run(f"cfl{cfl} noise1 jit0  ", cfl, 0.01, jitter=0.0)
