# Finds the particles faster than a threshold in pf_headless's PLY frames (x y z vx vy vz floats):
# python3 fast_particles.py PLY_DIR [M_PER_S]; per frame the count, the fastest speed, the
# particles within 0.1 m (one cell) of the first fast one, and up to six fast ones (x y z | v).
import sys, glob, array, math, os
thr = float(sys.argv[2]) if len(sys.argv) > 2 else 12.0
for path in sorted(glob.glob(os.path.join(sys.argv[1], 'frame_*.ply'))):
    data = open(path, 'rb').read()
    end = data.index(b'end_header\n') + len(b'end_header\n')
    a = array.array('f'); a.frombytes(data[end:])
    n = len(a) // 6
    fast = []
    vmax = 0.0
    for i in range(n):
        vx, vy, vz = a[6*i+3], a[6*i+4], a[6*i+5]
        s = vx*vx + vy*vy + vz*vz
        if s > vmax: vmax = s
        if s > thr*thr: fast.append(i)
    if fast:
        desc = ['(%.2f %.2f %.2f | %.1f %.1f %.1f)' % tuple(a[6*i:6*i+6]) for i in fast[:6]]
        i0 = fast[0]; x0, y0, z0 = a[6*i0], a[6*i0+1], a[6*i0+2]
        nb = sum(1 for j in range(n) if abs(a[6*j]-x0) < 0.1 and abs(a[6*j+1]-y0) < 0.1 and abs(a[6*j+2]-z0) < 0.1)
        print(os.path.basename(path), n, 'vmax %.1f' % math.sqrt(vmax), 'fast', len(fast), 'neighbours(0.1m) of first', nb, ' '.join(desc))
