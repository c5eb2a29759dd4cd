#!/usr/bin/env bash
# The fine level's tile passes against main: one warm machine, libraries swapped per run, two
# rounds interleaved, then a kernel profile of the leapfrog frame with each library.
# Run from the repository root on the GPU machine with build-dev/ (new) and build-dev/main/ (main).
source scripts/device_env.sh
b=build-dev/pf_bench
lf="--preset balanced --advection leapfrog --cfl 8 --tolerance 1e-3"
run() {  # library dir, name, then pf_bench arguments
  local lib=$1 name=$2; shift 2
  LD_LIBRARY_PATH=$PWD/$lib:$LD_LIBRARY_PATH $b --gpu-timing step --warmup 20 --steps 100 "$@" original_24 dam_break_1m > $OUT/$name.txt 2>&1
  echo "$name: $(grep -E '^(original_24|dam_break_1m) ' $OUT/$name.txt | awk '{printf "%s %s (%s)  ", $1, $6, $4}')"
}
LD_LIBRARY_PATH=$PWD/build-dev/main:$LD_LIBRARY_PATH $b --warmup 5 --steps 10 original_24 > /dev/null 2>&1  # the first run stalls
for round in 1 2; do
  for cfg in lf8 balanced fast; do
    case $cfg in lf8) args=$lf;; balanced) args="--preset balanced";; fast) args="--preset fast";; esac
    run build-dev/main main_${cfg}_$round $args
    run build-dev tiles_${cfg}_$round $args
  done
done
for lib in main tiles; do
  d=build-dev; [ $lib = main ] && d=build-dev/main
  LD_LIBRARY_PATH=$PWD/$d:$LD_LIBRARY_PATH $b --gpu-timing kernels --warmup 20 --steps 30 $lf dam_break_1m > $OUT/k_$lib.txt 2>&1
done
grep -A14 "^pass:kernel" $OUT/k_tiles.txt | head -16
