"""Share of dam_break_1m's tank (at N cells a metre: 2N x N x N) that a fine-level pass over
active tiles would visit, leapfrog at CFL 8 on Mesa llvmpipe, every 20 frames: FLUID cells (a cell
holding a particle), 4^3 and 8^3 tiles holding one, x rows holding one, and the reduction kernels'
orbit workgroups (256 mirror orbits, x fastest) holding one.
    PFLIP_LIBRARY=build/libpflip.so PYTHONPATH=python .venv/bin/python tile_fractions.py 32
"""
import sys, numpy as np, pflip
N = int(sys.argv[1]) if len(sys.argv) > 1 else 32
nx, ny, nz = 2*N, N, N
dx = 1.0 / N
ctx = pflip.frame.create_context()
with pflip.Simulation(grid_size=(nx, ny, nz), cell_size=dx, max_particles=8*nx*ny*nz) as sim:
    sim.fill_box((0, 0, 0), (0.75, 0.75, 1.0))
    pp = sim.params
    pp.advection = 3  # PF_ADVECTION_LEAPFROG
    pp.cfl = 8.0
    sim.params = pp
    for f in range(1, 121):
        sim.step(1/60)
        if f % 20: continue
        xyz, _ = sim.read_particles(velocities=False)
        ijk = np.clip((xyz / dx).astype(int), 0, [nx-1, ny-1, nz-1])
        occ = np.zeros((nx, ny, nz), bool); occ[ijk[:,0], ijk[:,1], ijk[:,2]] = True
        def tiles(t):
            o = occ.reshape(nx//t, t, ny//t, t, nz//t, t).any(axis=(1,3,5))
            return o.mean()
        rows = occ.any(axis=0).mean()
        # orbit workgroups: orbits (nx/2, ny, nz/2) x-fastest, 256 per group
        orb = occ[:nx//2] | occ[nx//2:][::-1]
        orb = orb[:, :, :nz//2] | orb[:, :, nz//2:][:, :, ::-1]
        flat = orb.transpose(2,1,0).reshape(-1)
        wg = flat.reshape(-1, 256).any(axis=1).mean()
        print(f"frame {f}: cells {occ.mean():.3f} tiles4 {tiles(4):.3f} tiles8 {tiles(8):.3f} xrows {rows:.3f} orbit-wg {wg:.3f}", flush=True)
