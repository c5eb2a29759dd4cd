"""rms speed per frame over the first 10 frames of 0.1 s: the jittered lattice at rest, an exact
lattice at rest and an exact lattice with the velocity noise, at CFL 1 and 2."""
from resting_tank import tank, rms_speed_mm


def run(label, **args):
    sim, _ = tank(**args)
    out = []
    for _ in range(10):
        sim.step(0.1)
        out.append("%.1f" % rms_speed_mm(sim.read_particles()[1]))
    print(label, "rms|v| mm/s per frame:", " ".join(out))


for cfl in (1, 2):
    run(f"cfl{cfl} noise0 jit0.8", cfl=cfl, noise=0.0)
    run(f"cfl{cfl} noise0 jit0  ", cfl=cfl, noise=0.0, jitter=0.0)
    run(f"cfl{cfl} noise1 jit0  ", cfl=cfl, noise=0.01, jitter=0.0)
