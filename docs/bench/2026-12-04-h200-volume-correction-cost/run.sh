#!/usr/bin/env bash
# What the volume correction costs a frame (README.md here): the presets with their correction
# and with `--volume-correction 0`, at their projections and at one a frame, two rounds on one
# warm machine.
source scripts/device_env.sh
R=/tmp/res; mkdir -p $R
B=build-dev/pf_bench
run() { local n=$1; shift; timeout 240 $B "$@" --json $R/$n.json > $R/$n.txt 2>&1; }
for round in 1 2; do for vc in 0.5 0; do
  run balanced_vc${vc}_r$round --warmup 20 --steps 100 --gpu-timing step --preset balanced --volume-correction $vc original_24 dam_break_1m
  run fast_vc${vc}_r$round --warmup 20 --steps 100 --gpu-timing step --preset fast --volume-correction $vc original_24 dam_break_1m
  run one_projection_vc${vc}_r$round --warmup 20 --steps 100 --gpu-timing step --preset balanced --max-substeps 1 --volume-correction $vc original_24 dam_break_1m
done; done
for vc in 0.5 0; do
  run kernels_one_projection_vc$vc --warmup 20 --steps 40 --gpu-timing kernels --preset balanced --max-substeps 1 --volume-correction $vc dam_break_1m
  run balanced_10m_w150_vc$vc --warmup 150 --steps 40 --gpu-timing step --preset balanced --volume-correction $vc dam_break_10m
done
tar -C /tmp -czf $OUT/res.tgz res
cd $R && python3 -c "
import json,glob
for f in sorted(glob.glob('*.json')):
    d=json.load(open(f))
    print('%-34s'%f, '  '.join('%s %.3f (%.2f)'%(s['scene'][:14], s['gpu']['total_ms_per_step']['median'], s['substeps_per_step']['mean'] if isinstance(s['substeps_per_step'],dict) else s['substeps_per_step']) for s in d['scenes']))
"
