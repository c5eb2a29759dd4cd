"""Frame 45's particles of dam_break_1m (dump.py) loaded into new simulations, then FRAMES frames
of a configuration with each MGPCG: pressure iterations (the most a frame), projections and
dispatches a frame (pf_get_pass_stats; llvmpipe issues what any GL is given).
    python frames.py db1m_045.npz balanced|leapfrog FRAMES"""
import sys, numpy as np, pflip
d = np.load(sys.argv[1]); config = sys.argv[2]; frames = int(sys.argv[3])
ctx = pflip.frame.create_context()
for solver in (pflip.PressureSolver.MGPCG, pflip.PressureSolver.MGPCG_GALERKIN):
    with pflip.Simulation(grid_size=(128, 64, 64), cell_size=1/64, max_particles=1310720) as sim:
        p = sim.params
        p.pressure_iterations = 40; p.max_substeps = 16; p.pressure_solver = solver
        if config == 'leapfrog':
            p.advection = pflip.Advection.LEAPFROG; p.cfl = 8.0; p.pressure_tolerance = 1e-3
        sim.params = p
        sim.add_particles(d['x'], d['v'])
        its = []
        for f in range(frames):
            sim.step(1 / 60)
            st = sim.stats()
            its.append((st.solver_iterations, st.substeps, sum(ps.dispatches for ps in sim.pass_stats())))
        print(config, solver.name, 'iterations (most a frame), projections, dispatches:', its, 'means',
              np.mean([i[0] for i in its]), np.mean([i[2] for i in its]), flush=True)
