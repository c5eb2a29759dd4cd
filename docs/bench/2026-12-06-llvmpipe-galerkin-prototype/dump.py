"""Step dam_break_1m (balanced) on llvmpipe, save particle positions+velocities at chosen frames."""
import sys, numpy as np, pflip
frames = [int(f) for f in sys.argv[1].split(",")]
ctx = pflip.frame.create_context()
with pflip.Simulation(grid_size=(128, 64, 64), cell_size=1/64, max_particles=1310720) as sim:
    p = sim.params; p.pressure_iterations = 40; p.max_substeps = 16; sim.params = p
    sim.fill_box((0, 0, 0), (0.75, 0.75, 1.0))
    print(sim.particle_count, flush=True)
    for f in range(1, max(frames) + 1):
        sim.step(1 / 60)
        if f in frames:
            x, v = sim.read_particles()
            np.savez(f"db1m_{f:03d}.npz", x=x, v=v)
            print("saved", f, flush=True)
