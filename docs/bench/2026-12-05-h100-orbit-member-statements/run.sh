#!/usr/bin/env bash
# Run on the GPU machine from the repository root with `build-dev` carried: main's library of
# ec5137b (build-dev/), the same with the orbit members in statements (build-dev/mainfix/) and the
# fused-CG branch with that change (build-dev/fused/); pf_bench of ec5137b for all three.
source scripts/device_env.sh
ROOT=$PWD; R=/tmp/res5; mkdir -p $R
B=build-dev/pf_bench
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader > $R/gpu.txt
lib() { case $1 in main) echo $ROOT/build-dev;; mainfix) echo $ROOT/build-dev/mainfix;; fused) echo $ROOT/build-dev/fused;; esac; }
for round in 1 2; do
  for l in main mainfix fused; do
    LD_LIBRARY_PATH=$(lib $l):$LD_LIBRARY_PATH timeout 120 $B --warmup 20 --steps 100 --gpu-timing step --preset balanced --max-substeps 1 dam_break_1m original_24 --json $R/${l}_one_r$round.json > $R/${l}_one_r$round.txt 2>&1
    LD_LIBRARY_PATH=$(lib $l):$LD_LIBRARY_PATH timeout 120 $B --warmup 20 --steps 100 --gpu-timing step --preset fast dam_break_1m original_24 --json $R/${l}_fast_r$round.json > $R/${l}_fast_r$round.txt 2>&1
    LD_LIBRARY_PATH=$(lib $l):$LD_LIBRARY_PATH timeout 120 $B --warmup 20 --steps 100 --gpu-timing step --preset balanced dam_break_1m original_24 --json $R/${l}_bal_r$round.json > $R/${l}_bal_r$round.txt 2>&1
  done
done
for l in main mainfix fused; do
  LD_LIBRARY_PATH=$(lib $l):$LD_LIBRARY_PATH timeout 120 $B --warmup 20 --steps 40 --gpu-timing kernels --preset balanced --max-substeps 1 dam_break_1m --json $R/${l}_kernels.json > $R/${l}_kernels.txt 2>&1
done
cd $R && python3 -c "
import json,glob
for f in sorted(glob.glob('*_r?.json')):
    d=json.load(open(f))
    for s in d['scenes']: print('%-22s %-14s it %6.2f disp %6.1f ms %.3f'%(f, s['scene'], s['solver_iterations']['mean'], s['dispatch_floor']['total']['dispatches_per_step'], s['gpu']['total_ms_per_step']['median']))
"
grep -iE "zstats|smooth" $R/*_kernels.txt | head -30
tar -C /tmp -czf $OUT/res5.tgz res5
