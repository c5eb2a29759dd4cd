#!/usr/bin/env bash
# Scratch default (leapfrog, projection CFL 8, MGPCG to 1e-2; accurate keeps Euler CFL 1): the
# engine and stability suites on NVIDIA, fast and long modes, 8 shards each.
source scripts/device_env.sh >/dev/null 2>&1
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
mkdir -p /tmp/wt/tests && ln -sfn "$PWD/tests/golden" /tmp/wt/tests/golden && ln -sfn "$PWD/samples" /tmp/wt/samples
cd build-dev/scratch
export LD_LIBRARY_PATH="$PWD:$LD_LIBRARY_PATH"
mkdir -p $OUT/s
sharded() {  # binary filter tag [env]
  local bin=$1 filter=$2 tag=$3; shift 3
  for i in 0 1 2 3 4 5 6 7; do
    env "$@" GTEST_TOTAL_SHARDS=8 GTEST_SHARD_INDEX=$i timeout 420 ./$bin --gtest_filter="$filter" > $OUT/s/${tag}_$i.txt 2>&1 &
  done
  wait
  echo "$tag: $(cat $OUT/s/${tag}_*.txt | grep -c '^\[       OK \]') ok, failed: $(cat $OUT/s/${tag}_*.txt | grep '^\[  FAILED  \] [A-Z]' | sed 's/ (.*//; s/.*\] //' | sort -u | tr '\n' ' ')"
}
s=$SECONDS
sharded pf_engine_tests '*' engine_fast
echo "t=$((SECONDS-s))"
sharded pf_stability_tests '*' stab_fast
echo "t=$((SECONDS-s))"
sharded pf_engine_tests 'Waves.*:Volume.*' engine_long PF_STABILITY_LONG=1
echo "t=$((SECONDS-s))"
sharded pf_stability_tests '*' stab_long PF_STABILITY_LONG=1
echo "t=$((SECONDS-s))"
grep -h "loss/period" $OUT/s/engine_*.txt | cut -c1-150
./pf_bench --gpu-timing step --warmup 20 --steps 100 original_24 dam_break_1m > $OUT/s/bench_default.txt 2>&1
grep -E '^(original_24|dam_break_1m) +[0-9]' $OUT/s/bench_default.txt
cd $OUT && tar czf s.tgz s && rm -rf s
