# Compares each pf_validation output v_<config>_<case>.txt of a folder with the balanced
# preset's (v_bal_<case>.txt): every series' RMS (or its mean over perturbed lattices) against
# the bound max(1.1 x balanced, balanced + 0.01), and the projections a frame.
#   python3 validation_summary.py h100_validation > h100_validation/summary.txt
import re,sys,glob,os
d=sys.argv[1]
def parse(f):
    out={}; txt=open(f).read()
    if 'rms mean' in txt:
        part=txt.split('rms mean')[1]
        for l in part.splitlines()[1:]:
            m=re.match(r'\s+(\S+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)',l)
            if m: out[m.group(1)]=float(m.group(2))
            elif out: break
    else:
        for l in txt.splitlines():
            m=re.match(r'\s+(\S+)\s+\S+\(\S+\)\s+\d+\s+([\d.]+)',l)
            if m: out[m.group(1)]=float(m.group(2))
    sub=re.findall(r'([\d.]+) substeps/frame',txt)
    return out, [float(x) for x in sub]
cfgs=sorted({re.match(r'v_(.*?)_(martin|marin)',os.path.basename(f)).group(1) for f in glob.glob(d+'/v_*.txt')})
cases=sorted({re.match(r'v_(?:bal|lf_[^_]+)_(.*)\.txt',os.path.basename(f)).group(1) for f in glob.glob(d+'/v_*.txt')})
for c in cases:
    base,bs=parse(f'{d}/v_bal_{c}.txt')
    print(f'== {c}  (bal substeps {sum(bs)/len(bs):.2f})')
    for cfg in cfgs:
        if cfg=='bal': continue
        f=f'{d}/v_{cfg}_{c}.txt'
        if not os.path.exists(f): continue
        r,ss=parse(f)
        row=[]
        for k,v in base.items():
            b=max(1.1*v, v+0.01); x=r.get(k,float('nan'))
            row.append(f'{k[:14]} {x:.4f}/{b:.4f}{"" if x<=b else " FAIL"}')
        print(f'  {cfg:8s} proj {sum(ss)/len(ss):.2f}: '+' | '.join(row))
