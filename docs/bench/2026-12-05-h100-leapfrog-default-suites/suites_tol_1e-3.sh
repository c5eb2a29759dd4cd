#!/usr/bin/env bash
# Scratch default at 1e-3 (leapfrog, projection CFL 8; accurate keeps Euler CFL 1): the tests that
# failed at 1e-2, the wave and volume tests, the stability suite's fast mode; the default's frame.
source scripts/device_env.sh >/dev/null 2>&1
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
mkdir -p /tmp/wt/tests && ln -sfn "$PWD/tests/golden" /tmp/wt/tests/golden && ln -sfn "$PWD/samples" /tmp/wt/samples
cd build-dev/scratch
export LD_LIBRARY_PATH="$PWD:$LD_LIBRARY_PATH"
mkdir -p $OUT/s2
sharded() {  # binary filter tag [env]
  local bin=$1 filter=$2 tag=$3; shift 3
  for i in 0 1 2 3 4 5 6 7; do
    env "$@" GTEST_TOTAL_SHARDS=8 GTEST_SHARD_INDEX=$i timeout 300 ./$bin --gtest_filter="$filter" > $OUT/s2/${tag}_$i.txt 2>&1 &
  done
  wait
  echo "$tag: $(cat $OUT/s2/${tag}_*.txt | grep -c '^\[       OK \]') ok, failed: $(cat $OUT/s2/${tag}_*.txt | grep '^\[  FAILED  \] [A-Z]' | sed 's/ (.*//; s/, where.*//; s/.*\] //' | sort -u | tr '\n' ' ')"
}
s=$SECONDS
sharded pf_engine_tests 'Waves.*:Volume.*:Emitters.*:Physics.*:Push.*:QualityPresets.*:RenderSurface.*:SurfaceTension.*:VorticityConfinement.*:Viscosity.*:DomainMotion.*:Obstacle*:Whitewater*:Sinks.*:Tunnelling.*:Leapfrog.*' engine
echo "t=$((SECONDS-s))"
sharded pf_stability_tests '*' stab
echo "t=$((SECONDS-s))"
for t in Volume.RestingTank Volume.CorrectionKeepsANoisy LiquidAtRestStaysAtRest DamBreakRoughness SmallDropStays CapillaryWave; do
  grep -h -A14 "RUN.*$t" $OUT/s2/engine_*.txt | grep -E "Failure|actual|^[a-z].*:" | head -4
done
grep -h "loss/period" $OUT/s2/engine_*.txt | cut -c1-140
for sc in original_24 dam_break_1m; do ./pf_bench --gpu-timing step --warmup 20 --steps 100 $sc > $OUT/s2/bench_$sc.txt 2>&1; grep -E "^$sc +[0-9]|solver:" $OUT/s2/bench_$sc.txt; done
cd $OUT && tar czf s2.tgz s2 && rm -rf s2
