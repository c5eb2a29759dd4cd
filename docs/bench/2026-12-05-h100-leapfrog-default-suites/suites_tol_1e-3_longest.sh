#!/usr/bin/env bash
# Scratch default at 1e-3 (leapfrog, projection CFL 8; accurate keeps Euler CFL 1) with a longest
# projection of XMAXDT s: the whole engine and stability suites (fast mode), 8 shards.
source scripts/device_env.sh >/dev/null 2>&1
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
mkdir -p /tmp/wt/tests && ln -sfn "$PWD/tests/golden" /tmp/wt/tests/golden && ln -sfn "$PWD/samples" /tmp/wt/samples
cd build-dev/scratch
export LD_LIBRARY_PATH="$PWD:$LD_LIBRARY_PATH"
mkdir -p $OUT/s3
sharded() {  # binary filter tag [env]
  local bin=$1 filter=$2 tag=$3; shift 3
  for i in 0 1 2 3 4 5 6 7; do
    env "$@" GTEST_TOTAL_SHARDS=8 GTEST_SHARD_INDEX=$i timeout 300 ./$bin --gtest_filter="$filter" > $OUT/s3/${tag}_$i.txt 2>&1 &
  done
  wait
  echo "$tag: $(cat $OUT/s3/${tag}_*.txt | grep -c '^\[       OK \]') ok, failed: $(cat $OUT/s3/${tag}_*.txt | grep '^\[  FAILED  \] [A-Z]' | sed 's/ (.*//; s/, where.*//; s/.*\] //' | sort -u | tr '\n' ' ')"
}
s=$SECONDS
for x in 0.033333 0.016667; do
  sharded pf_engine_tests '*' engine_$x XMAXDT=$x
  echo "t=$((SECONDS-s))"
  sharded pf_stability_tests '*' stab_$x XMAXDT=$x
  echo "t=$((SECONDS-s))"
done
grep -h "loss/period\|capillary" $OUT/s3/engine_*.txt | cut -c1-140
cd $OUT && tar czf s3.tgz s3 && rm -rf s3
