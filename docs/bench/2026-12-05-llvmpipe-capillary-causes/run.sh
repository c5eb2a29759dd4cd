#!/bin/bash
# usage: run.sh LABEL "ENV=.. ENV=.."  (lattice seeds 1..8 in turn; appends to results.txt in the build folder)
cd "${BUILD:-build}"
label=$1; envs=$2
for s in 1 2 3 4 5 6 7 8; do
  out=$(env $envs XSEED=$s LP_NUM_THREADS=1 nice -n 19 ./tests/pf_engine_tests --gtest_filter=SurfaceTension.CapillaryWaveHasTheTheoreticalFrequency 2>&1)
  pg=$(echo "$out" | grep "period-averaged gain")
  cw=$(echo "$out" | grep "capillary wave:")
  res=$(echo "$out" | grep -E "^\[  (PASSED|FAILED)" | head -1)
  echo "$label $envs XSEED=$s $pg $cw ${res:0:12}" | tee -a results.txt
done
