#!/usr/bin/env bash
# The sweep behind docs/performance.md "Band smoothing" (README.md here): libraries swapped
# through LD_LIBRARY_PATH on one warm machine, two rounds.
source scripts/device_env.sh
R=$OUT/res; mkdir -p $R
B=build-dev/pf_bench
D=docs/bench/2026-12-04-h200-band-smoothing
S="original_24 dam_break_small fountain_pool $D/dam_break_64.json $D/dam_break_96.json dam_break_1m"
run() { local v=$1 n=$2; shift 2; local L=$PWD/build-dev; [ $v = before ] && L=$PWD/build-dev/before
  LD_LIBRARY_PATH=$L:$LD_LIBRARY_PATH timeout 200 $B "$@" --json $R/${v}_$n.json > $R/${v}_$n.txt 2>&1; }
for round in 1 2; do for v in before after; do
  run $v balanced_r$round --warmup 20 --steps 100 --gpu-timing step --preset balanced $S
  run $v fast_r$round --warmup 20 --steps 100 --gpu-timing step --preset fast original_24 dam_break_small fountain_pool dam_break_1m
  run $v one_projection_r$round --warmup 20 --steps 100 --gpu-timing step --preset balanced --max-substeps 1 $S
done; done
for v in before after; do
  run $v balanced_10m_w150 --warmup 150 --steps 40 --gpu-timing step --preset balanced dam_break_10m
  run $v fast_10m_w150 --warmup 150 --steps 40 --gpu-timing step --preset fast dam_break_10m
  run $v kernels_1m --warmup 20 --steps 40 --gpu-timing kernels --preset balanced dam_break_1m
  run $v kernels_original_24 --warmup 20 --steps 100 --gpu-timing kernels --preset balanced --max-substeps 1 original_24
done
timeout 150 build-dev/pf_internal_tests --gtest_filter='*Solver*:*Mirror*:*Visc*:*Reference*:*PassPipeline*' > $R/nvidia_internal_tests.txt 2>&1
timeout 200 build-dev/pf_engine_tests --gtest_filter='*Corner*:*Mirror*:*Ladder*:*Volume*:*Snapshot*:*Preset*:*Waves*' > $R/nvidia_engine_tests.txt 2>&1
tar -C $OUT -czf $OUT/res.tgz res
cd $R && python3 -c "
import json,glob
for f in sorted(glob.glob('*.json')):
    d=json.load(open(f))
    print('%-28s'%f, '  '.join('%s %.3f (%.2f, it %.1f)'%(s['scene'][:14], s['gpu']['total_ms_per_step']['median'], s['substeps_per_step']['mean'] if isinstance(s['substeps_per_step'],dict) else s['substeps_per_step'], s['solver_iterations']['mean'] if isinstance(s['solver_iterations'],dict) else s['solver_iterations']) for s in d['scenes']))
"
grep -h -E '^\[  (PASSED|FAILED)' nvidia_*tests.txt
