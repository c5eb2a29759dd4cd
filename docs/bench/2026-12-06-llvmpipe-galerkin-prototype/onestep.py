import os, sys, numpy as np, pflip
d = np.load(sys.argv[1]); tol = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-3
ctx = pflip.frame.create_context()
for g in (0, 1):
    with pflip.Simulation(grid_size=(128, 64, 64), cell_size=1/64, max_particles=1310720) as sim:
        p = sim.params; p.pressure_iterations = 60; p.pressure_solver = pflip.PressureSolver.MGPCG_GALERKIN if g else pflip.PressureSolver.MGPCG; p.max_substeps = 1; p.pressure_tolerance = tol; p.volume_correction = 0; sim.params = p
        sim.add_particles(d['x'], d['v'])
        for k in range(3):
            sim.step(1/60)
            st = sim.stats()
            print('galerkin' if g else 'geometric', k, st.solver_iterations, st.solver_residual, flush=True)
