#!/usr/bin/env bash
# NVIDIA suites: engine, internal, stability; then a baseline bench. Results under $OUT.
# (Run from the project root with build-dev/ from scripts/pack_device.sh.)
source scripts/device_env.sh
nvidia-smi --query-gpu=name --format=csv,noheader
cd build-dev
for t in pf_internal_tests pf_engine_tests pf_stability_tests; do
  s=$SECONDS
  ./$t --gtest_brief=1 > $OUT/$t.log 2>&1; rc=$?
  echo "$t rc=$rc $((SECONDS-s)) s: $(grep -E '^\[  PASSED|FAILED|SKIPPED \]' $OUT/$t.log | head -5 | tr '\n' ' ')"
done
./pf_bench --gpu-timing step --warmup 20 --steps 100 original_24 dam_break_1m --preset balanced > $OUT/bench_bal.txt 2>&1
./pf_bench --gpu-timing step --warmup 20 --steps 100 original_24 dam_break_1m --preset balanced --max-substeps 1 > $OUT/bench_one.txt 2>&1
