# Scratch: redoes G2P by hand for the probed particle from lone_probe + probe_dump.diff output
# (probe_NNN_{pre,post}.bin in the current folder); prints each stencil face: weight, u, u_old,
# delta, valid word, theta, and the two cells (kind A/F/S, P2G count, pressure).
import numpy as np, glob, sys
W=8; N=2*W+1
kinds={0:'A',1:'F',2:'S'}
files=sorted(glob.glob('probe_*_post.bin'))
for fpost in files:
    idx=int(fpost.split('_')[1]); fpre='probe_%03d_pre.bin'%(idx-1)
    pre=np.fromfile(fpre,dtype=np.float32); d=open(fpost,'rb').read()
    post=np.frombuffer(d[:32],dtype=np.float32); c0=np.frombuffer(d[32:44],dtype=np.int32)
    rec=np.frombuffer(d[44:],dtype=np.float32).reshape(3,N,N,N,7)  # axis,z,y,x
    p=pre[:3]; v=pre[4:7]; vn=post[4:7]
    g=p/0.1
    print('=== substep',idx//2,'pos',p,'v',v,'-> v_new',vn)
    cell=np.floor(g).astype(int); lc=cell-c0
    def C(c):
        l=c-c0; r=rec[0,l[2],l[1],l[0]]; w=int(r[5]); return "%s%d(p=%.3g)"%(kinds[w&3],int(r[4]),r[6])
    print(' own cell',cell, C(cell))
    for a in range(3):
        off=np.array([0.5,0.5,0.5]); off[a]=0
        s=g-off; b=np.floor(s).astype(int); fr=s-b
        pic=0; dl=0
        for n in range(8):
            dd=np.array([n&1,(n>>1)&1,(n>>2)&1])
            w=np.prod(np.where(dd==1,fr,1-fr))
            f=b+dd; l=f-c0
            r=rec[a,l[2],l[1],l[0]]
            lo=f.copy(); lo[a]-=1
            pic+=w*r[0]; dl+=w*(r[0]-r[1])
            print('  ax%d face %s w=%.3f u=%.3f uold=%.3f d=%.3f valid=%d theta=%.3f cells %s|%s'%(a,f,w,r[0],r[1],r[0]-r[1],r[2],r[3],C(lo),C(f)))
        print('  ax%d pic=%.3f delta=%.3f flip=%.3f new=%.3f'%(a,pic,dl,v[a]+dl,0.05*pic+0.95*(v[a]+dl)))
