#!/usr/bin/env bash
# The candidate default (leapfrog, projection CFL 8, MGPCG to 1e-3, balanced otherwise) against
# the balanced preset: GPU ms a frame and the per-kernel profile with its dispatch count.
source scripts/device_env.sh >/dev/null 2>&1
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
cd build-dev
export LD_LIBRARY_PATH="$PWD/old:$LD_LIBRARY_PATH"  # the library at 45a68d7 (main's step at 1/60 s frames)
mkdir -p $OUT/k
LF="--preset balanced --advection leapfrog --cfl 8 --tolerance 1e-3"
./pf_bench --gpu-timing step --warmup 40 --steps 50 original_24 $LF > /dev/null 2>&1
./pf_bench --gpu-timing step --warmup 20 --steps 100 original_24 dam_break_1m $LF > $OUT/k/step_lf_1e-3.txt 2>&1
grep -E '^(original_24|dam_break_1m) +[0-9]|solver:' $OUT/k/step_lf_1e-3.txt
./pf_bench --gpu-timing kernels --warmup 20 --steps 60 dam_break_1m $LF > $OUT/k/kernels_lf_1e-3.txt 2>&1
grep -E 'dam_break_1m +total|dam_break_1m +pressure_solve' $OUT/k/kernels_lf_1e-3.txt
cd $OUT && tar czf k.tgz k && rm -rf k
