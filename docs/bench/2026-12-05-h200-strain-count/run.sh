#!/usr/bin/env bash
# The strain count on NVIDIA, lean: its tests, then balanced against leapfrog at a projection CFL of 8.
source scripts/device_env.sh
nvidia-smi --query-gpu=name --format=csv,noheader
cd build-dev
./pf_internal_tests --gtest_brief=1 --gtest_filter='Metrics.*:StepClock.*:UniformLayout*' > $OUT/internal.log 2>&1; echo "internal rc=$? $(grep -E '^\[  PASSED|FAILED' $OUT/internal.log | tr '\n' ' ')"
./pf_engine_tests --gtest_brief=1 --gtest_filter='Leapfrog.*:Snapshots.*:Stats*' > $OUT/engine.log 2>&1; echo "engine rc=$? $(grep -E '^\[  PASSED|FAILED' $OUT/engine.log | tr '\n' ' ')"
b() { tag=$1; shift; timeout 100 ./pf_bench "$@" > $OUT/$tag.txt 2>&1; echo "$tag: $(grep -E 'gpu .* ms/step' $OUT/$tag.txt | sed 's/.*wall/wall/' | tr '\n' ' ')"; }
b bal --gpu-timing step --warmup 20 --steps 60 original_24 dam_break_1m --preset balanced
b lf8 --gpu-timing step --warmup 20 --steps 60 original_24 dam_break_1m --preset balanced --advection leapfrog --cfl 8
b lf8_10m --gpu-timing step --warmup 10 --steps 30 dam_break_10m --preset balanced --advection leapfrog --cfl 8
b lf8_kernels --gpu-timing kernels --warmup 20 --steps 30 dam_break_1m --preset balanced --advection leapfrog --cfl 8
