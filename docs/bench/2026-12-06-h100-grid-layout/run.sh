#!/usr/bin/env bash
# NVIDIA check of the make-room commits (grid addressing through one place): the internal and
# engine suites, and the frame against main at 6dc0a1f (build-dev/after) on the same machine.
source scripts/device_env.sh >/dev/null 2>&1
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
cd build-dev
export PF_SCENES_DIR=$PWD/../samples/scenes
LF="--preset balanced --advection leapfrog --cfl 8 --tolerance 1e-3"
./pf_bench --gpu-timing step --warmup 40 --steps 50 original_24 $LF > /dev/null 2>&1
for r in 1 2; do
  for v in now base; do
    if [ $v = base ]; then L="$PWD/after"; B=after/pf_bench; else L="$PWD"; B=./pf_bench; fi
    for cfg in "lf8:$LF" "balanced:--preset balanced" "fast:--preset fast"; do
      name=${cfg%%:*}; args=${cfg#*:}
      LD_LIBRARY_PATH=$L:$LD_LIBRARY_PATH $B --gpu-timing step --warmup 20 --steps 100 original_24 dam_break_1m $args > $OUT/${v}_${name}_$r.txt 2>&1
      echo "r$r $v $name: $(grep -E '^(original_24|dam_break_1m) +[0-9]' $OUT/${v}_${name}_$r.txt | tr -s ' ' | cut -d' ' -f1,4-6 | tr '\n' '|')"
    done
  done
done
timeout 150 ./pf_internal_tests --gtest_brief=1 > $OUT/internal.log 2>&1; echo "internal rc=$? $(grep -E '^\[  (PASSED|FAILED) ' $OUT/internal.log | tr '\n' ' ')"
timeout 250 ./pf_engine_tests --gtest_brief=1 --gtest_filter='Obstacle*:Viscosity*:SurfaceTension*:Whitewater*:Vorticity*:ForceFields*:DomainMotion*:Emitters*:Sinks*:Render*:Tunnelling*:Memory*:Snapshots*' > $OUT/engine.log 2>&1; echo "engine rc=$? $(grep -E '^\[  (PASSED|FAILED) ' $OUT/engine.log | tr '\n' ' ')"
grep -E '^\[  FAILED  \]' $OUT/internal.log $OUT/engine.log | head -20
