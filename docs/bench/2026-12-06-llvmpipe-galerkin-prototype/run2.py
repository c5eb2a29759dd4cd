import numpy as np, sys
sys.path.insert(0, __import__('os').path.dirname(__file__) or '.')
import mg
from mg import *
from run import types_from_particles, div_rhs
d = np.load(sys.argv[1]); dims = (128, 64, 64); dx = 1/64
types, cnt = types_from_particles(d['x'], dims, dx)
rng = np.random.default_rng(1)
def go(name, lv):
    b1 = rng.standard_normal(lv[0].A.shape[0]); b2 = div_rhs(d['x'], d['v'], dims, dx, lv[0].coords)
    mg.vcycle_saved = mg.vcycle
    res = []
    for b in (b1, b2):
        _, it = pcg2(lv, b, 1e-3); res.append(it)
    print(f'{name:40s} random {res[0]} div {res[1]}  sizes {[L.A.shape[0] for L in lv]} nnz/row {[round(L.A.nnz/L.A.shape[0]) for L in lv]}', flush=True)
def pcg2(levels, b, tol, maxit=100):
    A = levels[0].A; x = np.zeros_like(b); r = b.copy(); nb = np.linalg.norm(b)
    z = vcycle2(levels, 0, r); p = z.copy(); rz = r @ z
    for it in range(1, maxit + 1):
        Ap = A @ p; a = rz / (p @ Ap); x += a * p; r -= a * Ap
        if np.linalg.norm(r) <= tol * nb: return x, it
        z = vcycle2(levels, 0, r); rz2 = r @ z; p = z + (rz2 / rz) * p; rz = rz2
    return x, maxit
go('geometric (exact coarsest)', build_geometric(types))
go('tri-galerkin all, 8-colour GS', build_hybrid(types, 'tri'))
for om, ns in ((0.6, 1), (0.6, 2), (0.8, 2)):
    go(f'tri-galerkin all, jacobi w{om} x{ns}', build_hybrid(types, 'tri', smoother='jacobi', omega=om, nsweep=ns))
for a in (1.0, 1.5):
    go(f'L1 tri, deeper UA a{a}, 8-colour GS', build_hybrid(types, 'ua', alpha=a))
    go(f'L1 tri, deeper UA a{a}, jacobi .6x2', build_hybrid(types, 'ua', alpha=a, smoother='jacobi', omega=0.6, nsweep=2))
