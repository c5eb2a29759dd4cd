import numpy as np, sys
sys.path.insert(0, __import__('os').path.dirname(__file__) or '.')
from mg import *
from run import types_from_particles, div_rhs
d = np.load(sys.argv[1]); dims = (128, 64, 64); dx = 1/64
types, cnt = types_from_particles(d['x'], dims, dx)
rng = np.random.default_rng(1)
b1 = None
for a in (1.0, 1.5, 2.0):
    lv = build_hybrid(types, 'ua', alpha=a)
    lv[0].alpha = 1.0
    if b1 is None:
        b1 = rng.standard_normal(lv[0].A.shape[0]); b2 = div_rhs(d['x'], d['v'], dims, dx, lv[0].coords)
    for om in (0.6, 0.8):
        for cp in (4, 8):
            cfg = dict(omega=om, coarse_pairs=cp)
            its = [pcg3(lv, b, 1e-3, cfg)[1] for b in (b1, b2)] + [pcg3(lv, b2, 1e-5, cfg)[1]]
            print(f'alpha {a} omega {om} coarse pairs {cp}: random {its[0]} div {its[1]} div@1e-5 {its[2]}', flush=True)
