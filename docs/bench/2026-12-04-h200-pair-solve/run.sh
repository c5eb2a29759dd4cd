#!/usr/bin/env bash
# The pair solve (README.md here): the library before (build-dev/base/, main at f4e87da: the
# correction's solve alongside the projection's) and after (build-dev/: both in the same passes),
# swapped per run on one warm machine, two rounds; then per-kernel timing of the one-projection
# frame, the 10M scene, and the pair tests on NVIDIA's GL.
source scripts/device_env.sh
R=/tmp/res; mkdir -p $R
B=build-dev/pf_bench
part=${1:-all}  # rounds | rest | all: two calls fit the device's 10-minute limit
run() {
  local lib=$1 n=$2; shift 2
  local path=$PWD/build-dev; [ "$lib" = before ] && path=$PWD/build-dev/base
  LD_LIBRARY_PATH=$path:$LD_LIBRARY_PATH timeout 300 $B "$@" --json $R/${lib}_$n.json > $R/${lib}_$n.txt 2>&1
}
[ $part != rest ] && for round in 1 2; do for lib in before after; do
  run $lib one_projection_r$round --warmup 20 --steps 100 --gpu-timing step --preset balanced --max-substeps 1 original_24 dam_break_1m
  run $lib fast_r$round --warmup 20 --steps 100 --gpu-timing step --preset fast original_24 dam_break_1m
  run $lib balanced_r$round --warmup 20 --steps 100 --gpu-timing step --preset balanced original_24 dam_break_1m
done; done
[ $part != rounds ] && for lib in before after; do
  run $lib kernels_one_projection --warmup 20 --steps 40 --gpu-timing kernels --preset balanced --max-substeps 1 dam_break_1m
  run $lib balanced_10m_w150 --warmup 150 --steps 40 --gpu-timing step --preset balanced dam_break_10m
done
[ $part != rounds ] && timeout 300 build-dev/pf_internal_tests --gtest_filter='PairSolve.*:VolumeCorrectionPass.*:Mgpcg/*' \
  --gtest_output=json:$R/internal_tests.json > $R/internal_tests.txt 2>&1
tar -C /tmp -czf $OUT/res_$part.tgz res
cd $R && python3 -c "
import json,glob
for f in sorted(glob.glob('*.json')):
    if f.startswith('internal'): continue
    d=json.load(open(f))
    print('%-34s'%f, '  '.join('%s %.3f (%.2f proj, %d disp, %.1f MiB)'%(s['scene'][:14], s['gpu']['total_ms_per_step']['median'], s['substeps_per_step']['mean'], s['dispatch_floor']['total']['dispatches_per_step'], s['gpu_memory']['bytes']/2**20) for s in d['scenes']))
"
tail -5 $R/internal_tests.txt
