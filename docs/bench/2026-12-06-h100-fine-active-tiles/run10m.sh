#!/usr/bin/env bash
# dam_break_10m, frames 151-190, main against the tile passes, two rounds interleaved.
source scripts/device_env.sh
b=build-dev/pf_bench
lf="--preset balanced --advection leapfrog --cfl 8 --tolerance 1e-3"
for round in 1 2; do
  for cfg in lf8 balanced; do
    case $cfg in lf8) args=$lf;; balanced) args="--preset balanced";; esac
    for lib in main tiles; do
      d=build-dev; [ $lib = main ] && d=build-dev/main
      LD_LIBRARY_PATH=$PWD/$d:$LD_LIBRARY_PATH $b --gpu-timing step --warmup 150 --steps 40 $args dam_break_10m > $OUT/10m_${lib}_${cfg}_$round.txt 2>&1
      echo "${lib}_${cfg}_$round: $(grep -E '^dam_break_10m ' $OUT/10m_${lib}_${cfg}_$round.txt | head -1 | awk '{printf "%s ms (%s projections)", $6, $4}')"
    done
  done
done
