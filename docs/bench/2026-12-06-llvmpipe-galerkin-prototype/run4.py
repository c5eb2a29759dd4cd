import numpy as np, sys
sys.path.insert(0, __import__('os').path.dirname(__file__) or '.')
from mg import *
from run import types_from_particles, div_rhs
d = np.load(sys.argv[1]); dims = (128, 64, 64); dx = 1/64
types, cnt = types_from_particles(d['x'], dims, dx)
rng = np.random.default_rng(1)
cfg = dict(omega=0.6, coarse_pairs=4)
def trunc(A, cc, keepfn, comp):
    C = A.tocoo(); dd = cc[C.col] - cc[C.row]
    keep = keepfn(np.abs(dd))
    dropped = np.zeros(A.shape[0]); np.add.at(dropped, C.row[~keep], C.data[~keep])
    K = sp.csr_matrix((C.data[keep], (C.row[keep], C.col[keep])), shape=A.shape)
    return (K + (sp.diags(dropped) if comp else 0)).tocsr()
for name, fn in (('full', None), ('27', lambda a: a.max(1) <= 1), ('33', lambda a: (a.max(1) <= 1) | (a.sum(1) <= 2) & (a.max(1)==2) & (a.sum(1)==2)), ('57 (|o|_1<=3)', lambda a: a.sum(1) <= 3), ('81(|o|_1<=4)', lambda a: a.sum(1) <= 4)):
  for comp in ((False,) if fn is None else (False, True)):
    lv = build_hybrid(types, 'ua', alpha=1.5); lv[0].alpha = 1.0
    if fn is not None:
        A1 = trunc(lv[1].A, lv[1].coords, fn, comp)
        lv[1].A = A1; lv[1].dinv = 1 / A1.diagonal()
        # rebuild deeper levels from the truncated A1
        for l in range(1, len(lv) - 1):
            lv[l+1].A = (lv[l].P.T @ lv[l].A @ lv[l].P).tocsr(); lv[l+1].dinv = 1/lv[l+1].A.diagonal()
    b1 = np.random.default_rng(1).standard_normal(lv[0].A.shape[0]); b2 = div_rhs(d['x'], d['v'], dims, dx, lv[0].coords)
    its = [pcg3(lv, b, 1e-3, cfg)[1] for b in (b1, b2)]
    print(f'{name} comp={comp}: nnz/row {lv[1].A.nnz/lv[1].A.shape[0]:.1f} random {its[0]} div {its[1]}', flush=True)
