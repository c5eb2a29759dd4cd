import numpy as np, sys, time
sys.path.insert(0, __import__('os').path.dirname(__file__) or '.')
from mg import *

def types_from_particles(x, dims, dx):
    c = np.floor(x / dx).astype(int); c = np.clip(c, 0, np.array(dims) - 1)
    cnt = np.zeros(dims[::-1], np.int32)
    np.add.at(cnt, (c[:,2], c[:,1], c[:,0]), 1)
    return np.where(cnt > 0, FLUID, AIR), cnt

def div_rhs(x, v, dims, dx, fl):
    """Divergence of a crude P2G (linear along each face normal) on FLUID cells."""
    g = x / dx
    div = np.zeros(dims[::-1])
    for a in range(3):
        fd = list(dims); fd[a] += 1
        num = np.zeros(fd[::-1]); den = np.zeros(fd[::-1])
        ci = np.clip(np.floor(g).astype(int), 0, np.array(dims) - 1)
        fa = np.floor(g[:, a]).astype(int); t = g[:, a] - fa
        for k, w in ((0, 1 - t), (1, t)):
            f = ci.copy(); f[:, a] = np.clip(fa + k, 0, dims[a])
            np.add.at(num, (f[:,2], f[:,1], f[:,0]), w * v[:, a]); np.add.at(den, (f[:,2], f[:,1], f[:,0]), w)
        u = np.where(den > 0, num / np.maximum(den, 1e-12), 0)
        # walls: normal velocity 0
        sl = [slice(None)]*3; sl[2-a] = 0; u[tuple(sl)] = 0; sl[2-a] = -1; u[tuple(sl)] = 0
        sl1 = [slice(None)]*3; sl1[2-a] = slice(1, None); sl0 = [slice(None)]*3; sl0[2-a] = slice(0, -1)
        div += u[tuple(sl1)] - u[tuple(sl0)]
    return -div[fl[:,2], fl[:,1], fl[:,0]]

if __name__ == '__main__':
    rng = np.random.default_rng(1)
    if sys.argv[1] == 'synthetic':
        dims = (64, 32, 32); types = np.full(dims[::-1], AIR); types[:24, :24, :24] = FLUID; rhs_div = None
    else:
        d = np.load(sys.argv[1]); dims = (128, 64, 64); dx = 1/64
        types, cnt = types_from_particles(d['x'], dims, dx)
    t0 = time.time()
    variants = [('geometric', lambda: build_geometric(types))]
    for a in [1.0, 1.5, 1.8]:
        variants.append((f'ua{a}', lambda a=a: build_galerkin(types, 'ua', alpha=a)))
    variants = [v for v in variants if not v[0].startswith('ua')]
    for pat in ('full',):
        variants.append((f'tri-galerkin-{pat}', lambda pat=pat: build_galerkin(types, 'tri', pattern=pat)))
    A0 = None
    for name, mk in variants:
        lv = mk()
        if A0 is None:
            A0 = lv[0].A; fl = lv[0].coords
            b_rand = rng.standard_normal(A0.shape[0])
            rhss = [('random', b_rand)]
            if sys.argv[1] != 'synthetic': rhss.append(('div', div_rhs(d['x'], d['v'], dims, dx, fl)))
        out = []
        for rn, b in rhss:
            for tol in (1e-3, 1e-5):
                _, it = pcg(lv, b, tol)
                out.append(f'{rn}@{tol:g}:{it}')
        print(f'{name:20s} levels {len(lv)} fluid {A0.shape[0]} ' + ' '.join(out) + f'  nnz/row coarse1 {lv[1].A.nnz/lv[1].A.shape[0]:.1f}', flush=True)
