"""MGPCG iteration counts: McAdams geometric coarsening (as pflip's shaders) against Galerkin
coarse operators (unsmoothed aggregation 2x2x2; trilinear P^T A P). Prototype, CPU, float64."""
import numpy as np, scipy.sparse as sp, sys, time

FLUID, AIR, SOLID = 0, 1, 2
OFFS = [(-1,0,0),(1,0,0),(0,-1,0),(0,1,0),(0,0,-1),(0,0,1)]

def lin(d, c):  # c: (n,3) -> index, x fastest
    return c[:,0] + d[0]*(c[:,1] + d[1]*c[:,2])

def poisson(types, ghost=None):
    """7-point operator on FLUID cells: diag = in-domain non-SOLID neighbours (+ghost term), -1 to FLUID."""
    d = types.shape[::-1]  # types indexed [z,y,x]
    fl = np.argwhere(types.T == FLUID)  # (x,y,z)
    n = len(fl)
    idx = -np.ones(types.size, np.int64); idx[lin(d, fl)] = np.arange(n)
    diag = np.zeros(n); rows=[]; cols=[]
    tflat = types.T.reshape(-1, order='F')  # index lin
    for o in OFFS:
        q = fl + np.array(o)
        inside = np.all((q >= 0) & (q < np.array(d)), axis=1)
        qi = np.where(inside, lin(d, np.clip(q, 0, np.array(d)-1)), 0)
        t = np.where(inside, tflat[qi], SOLID)
        diag += (t != SOLID)
        m = t == FLUID
        rows.append(np.arange(n)[m]); cols.append(idx[qi[m]])
    if ghost is not None: diag += ghost
    r = np.concatenate(rows); c = np.concatenate(cols)
    A = sp.csr_matrix((np.concatenate([diag, -np.ones(len(r))]), (np.concatenate([np.arange(n), r]), np.concatenate([np.arange(n), c]))), shape=(n, n))
    return A, fl, idx

def coarsen_types(types):
    nz, ny, nx = types.shape
    cz, cy, cx = (nz+1)//2, (ny+1)//2, (nx+1)//2
    pad = np.full((2*cz, 2*cy, 2*cx), -1); pad[:nz,:ny,:nx] = types
    b = pad.reshape(cz,2,cy,2,cx,2).transpose(0,2,4,1,3,5).reshape(cz,cy,cx,8)
    air = (b == AIR).any(-1); fluid = (b == FLUID).any(-1)
    return np.where(air, AIR, np.where(fluid, FLUID, SOLID))

def trilinear_P(fl_f, idx_c, dc):
    """rows: fine FLUID cells; cols: coarse cells (by idx_c, -1 = not active): 3/4 parent, 1/4 other, clamped."""
    rows=[]; cols=[]; vals=[]
    parent = fl_f >> 1
    other = np.clip(parent + 2*(fl_f & 1) - 1, 0, np.array(dc)-1)
    for n in range(8):
        pick = np.array([(n>>0)&1, (n>>1)&1, (n>>2)&1])
        c = parent + pick*(other - parent)
        w = np.prod(0.75 - 0.5*pick)
        ci = idx_c[lin(dc, c)]
        m = ci >= 0
        rows.append(np.arange(len(fl_f))[m]); cols.append(ci[m]); vals.append(np.full(m.sum(), w))
    ncols = idx_c.max() + 1
    return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(len(fl_f), ncols))

class Level:
    pass

def colours(coords, k):
    if k == 2: key = coords.sum(1) & 1
    else: key = (coords[:,0] & 1) + 2*(coords[:,1] & 1) + 4*(coords[:,2] & 1)
    return [np.nonzero(key == c)[0] for c in range(k)]

def build_geometric(types, coarse_cells=1024, ghost=None):
    levels = []
    A, fl, idx = poisson(types, ghost)
    while True:
        L = Level(); L.A = A; L.coords = fl; L.dims = types.shape[::-1]; L.col = colours(fl, 2); L.dinv = 1/A.diagonal()
        levels.append(L)
        if types.size <= coarse_cells: break
        ct = coarsen_types(types)
        Ac, flc, idxc = poisson(ct)
        P = trilinear_P(fl, idxc, ct.shape[::-1])
        L.P = P; L.R = 0.5 * P.T.tocsr(); L.alpha = 1.0
        types, A, fl = ct, Ac, flc
    return levels

def drop(Ac, cc, pattern):
    if pattern == 'full': return Ac
    C = Ac.tocoo()
    dd = np.abs(cc[C.row] - cc[C.col])
    keep = (dd.max(1) <= 1) if pattern == '27' else (dd.sum(1) <= 1)
    dropped = np.zeros(Ac.shape[0]); np.add.at(dropped, C.row[~keep], C.data[~keep])
    K = sp.csr_matrix((C.data[keep], (C.row[keep], C.col[keep])), shape=Ac.shape)
    return (K + sp.diags(dropped)).tocsr()

def build_galerkin(types, kind, coarse_cells=1024, alpha=1.0, ghost=None, pattern='full'):
    levels = []
    A, fl, idx = poisson(types, ghost)
    dims = types.shape[::-1]
    ncol = 2
    while True:
        L = Level(); L.A = A; L.coords = fl; L.dims = dims; L.col = colours(fl, ncol); L.dinv = 1/A.diagonal()
        levels.append(L)
        if np.prod(dims) <= coarse_cells: break
        dc = tuple((np.array(dims)+1)//2)
        if kind == 'ua':
            parent = fl >> 1
            key = lin(dc, parent)
            uniq, inv = np.unique(key, return_inverse=True)
            P = sp.csr_matrix((np.ones(len(fl)), (np.arange(len(fl)), inv)), shape=(len(fl), len(uniq)))
            cc = np.stack([uniq % dc[0], (uniq // dc[0]) % dc[1], uniq // (dc[0]*dc[1])], 1)
            newcol = 2
        else:  # trilinear Galerkin: coarse cells any fluid child (types rule FLUID or AIR w/ fluid)
            parent = fl >> 1
            uniq = np.unique(lin(dc, parent))
            idxc = -np.ones(int(np.prod(dc)), np.int64); idxc[uniq] = np.arange(len(uniq))
            P = trilinear_P(fl, idxc, dc)
            cc = np.stack([uniq % dc[0], (uniq // dc[0]) % dc[1], uniq // (dc[0]*dc[1])], 1)
            newcol = 8
        Ac = drop((P.T @ A @ P).tocsr(), cc, pattern)
        if kind != 'ua': newcol = 2 if pattern == '7' else 8
        L.P = P; L.R = P.T.tocsr(); L.alpha = alpha
        A, fl, dims, ncol = Ac, cc, dc, newcol
    return levels

def sweep(L, x, b, c):
    ids = L.col[c]
    # x_c = (b_c - (A x)_c + D_c x_c) / D_c
    Ax = L.A[ids] @ x
    x[ids] += (b[ids] - Ax) * L.dinv[ids]

def vcycle(levels, l, r, coarse_sweeps=8):
    L = levels[l]; nc = len(L.col)
    x = np.zeros_like(r)
    if l + 1 == len(levels):
        sweep(L, x, r, 0)
        for _ in range(coarse_sweeps):
            for c in list(range(1, nc)) + [0] if nc == 2 else list(range(nc))[::-1] + list(range(nc)):
                sweep(L, x, r, c)
        if nc != 2:  # symmetric: fwd then bwd repeated
            pass
        return x
    order = list(range(nc))
    for c in order: sweep(L, x, r, c)
    res = r - L.A @ x
    ec = vcycle(levels, l + 1, L.R @ res, coarse_sweeps)
    x += L.alpha * (L.P @ ec)
    for c in order[::-1]: sweep(L, x, r, c)
    return x

def pcg(levels, b, tol=1e-3, maxit=200, x0=None):
    A = levels[0].A
    x = np.zeros_like(b) if x0 is None else x0.copy()
    r = b - A @ x; nb = np.linalg.norm(b)
    if np.linalg.norm(r) <= tol * nb: return x, 0
    z = vcycle(levels, 0, r); p = z.copy(); rz = r @ z
    for it in range(1, maxit + 1):
        Ap = A @ p; a = rz / (p @ Ap)
        x += a * p; r -= a * Ap
        if np.linalg.norm(r) <= tol * nb: return x, it
        z = vcycle(levels, 0, r); rz2 = r @ z; p = z + (rz2 / rz) * p; rz = rz2
    return x, maxit

def build_hybrid(types, deep='ua', alpha=1.0, coarse_cells=1024, smoother='gs', omega=0.7, nsweep=1):
    """Level 1 trilinear Galerkin (fine smoother RBGS), deeper levels by `deep`: 'ua' aggregation Galerkin, 'tri'."""
    levels = []
    A, fl, idx = poisson(types)
    dims = types.shape[::-1]; ncol = 2; l = 0
    while True:
        L = Level(); L.A = A; L.coords = fl; L.dims = dims; L.col = colours(fl, ncol); L.dinv = 1/A.diagonal()
        L.smoother = 'gs' if l == 0 else smoother; L.omega = omega; L.nsweep = 1 if l == 0 else nsweep
        levels.append(L)
        if np.prod(dims) <= coarse_cells: break
        dc = tuple((np.array(dims)+1)//2)
        parent = fl >> 1
        uniq = np.unique(lin(dc, parent))
        cc = np.stack([uniq % dc[0], (uniq // dc[0]) % dc[1], uniq // (dc[0]*dc[1])], 1)
        if l == 0 or deep == 'tri':
            idxc = -np.ones(int(np.prod(dc)), np.int64); idxc[uniq] = np.arange(len(uniq))
            P = trilinear_P(fl, idxc, dc); a = 1.0
        else:
            inv = np.searchsorted(uniq, lin(dc, parent))
            P = sp.csr_matrix((np.ones(len(fl)), (np.arange(len(fl)), inv)), shape=(len(fl), len(uniq))); a = alpha
        Ac = (P.T @ A @ P).tocsr()
        L.P = P; L.R = P.T.tocsr(); L.alpha = a
        A, fl, dims, ncol = Ac, cc, dc, 8
        l += 1
    return levels

def smooth(L, x, r, forward):
    if getattr(L, 'smoother', 'gs') == 'jacobi':
        for _ in range(L.nsweep):
            x += L.omega * L.dinv * (r - L.A @ x)
    else:
        order = list(range(len(L.col)))
        for c in (order if forward else order[::-1]): sweep(L, x, r, c)

def vcycle2(levels, l, r, coarse_sweeps=8):
    L = levels[l]
    x = np.zeros_like(r)
    if l + 1 == len(levels):
        import scipy.sparse.linalg as sla
        return sla.spsolve(L.A.tocsc(), r) if L.A.shape[0] < 3000 else vcycle(levels, l, r)
    smooth(L, x, r, True)
    res = r - L.A @ x
    ec = vcycle2(levels, l + 1, L.R @ res, coarse_sweeps)
    x += L.alpha * (L.P @ ec)
    smooth(L, x, r, False)
    return x

def coarsest_gs(L, r, pairs):
    x = np.zeros_like(r)
    cols = colours(L.coords, 8)
    L.col = cols
    for _ in range(pairs):
        for c in range(8): sweep(L, x, r, c)
        for c in reversed(range(8)): sweep(L, x, r, c)
    return x

def vcycle3(levels, l, r, cfg):
    L = levels[l]
    if l + 1 == len(levels):
        return coarsest_gs(L, r, cfg['coarse_pairs'])
    if l == 0:
        x = np.zeros_like(r); sweep(L, x, r, 0); sweep(L, x, r, 1)
    else:
        x = cfg['omega'] * L.dinv * r
    res = r - L.A @ x
    ec = vcycle3(levels, l + 1, L.R @ res, cfg)
    x += L.alpha * (L.P @ ec)
    if l == 0:
        sweep(L, x, r, 1); sweep(L, x, r, 0)
    else:
        x += cfg['omega'] * L.dinv * (r - L.A @ x)
    return x

def pcg3(levels, b, tol, cfg, maxit=100):
    A = levels[0].A; x = np.zeros_like(b); r = b.copy(); nb = np.linalg.norm(b)
    z = vcycle3(levels, 0, r, cfg); p = z.copy(); rz = r @ z
    for it in range(1, maxit + 1):
        Ap = A @ p; a = rz / (p @ Ap); x += a * p; r -= a * Ap
        if np.linalg.norm(r) <= tol * nb: return x, it
        z = vcycle3(levels, 0, r, cfg); rz2 = r @ z; p = z + (rz2 / rz) * p; rz = rz2
    return x, maxit
