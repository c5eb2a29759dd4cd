#!/usr/bin/env bash
# The thin tank's standing wave (Waves.ThinTankOneCell, every preset; the scratch defaults are the
# balanced preset) over lattice seeds 1-8 (XSEED; the test's own is 17) in three configurations:
# Euler CFL 1 at 1e-3 (the balanced preset today), leapfrog CFL 8 at 1e-3 and at 1e-2.
source scripts/device_env.sh >/dev/null 2>&1
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
cd build-dev/scratch
export LD_LIBRARY_PATH="$PWD:$LD_LIBRARY_PATH"
mkdir -p $OUT/w
for cfg in "euler_1e-3|XADV=0 XCFL=1 XTOL=1e-3" "lf_1e-3|XADV=3 XCFL=8 XTOL=1e-3" "lf_1e-2|XADV=3 XCFL=8 XTOL=1e-2"; do
  tag=${cfg%%|*}; envs=${cfg#*|}
  for seed in 1 2 3 4 5 6 7 8 17; do
    env $envs XSEED=$seed ./pf_engine_tests --gtest_filter=Waves.ThinTankOneCell > $OUT/w/${tag}_$seed.txt 2>&1 &
  done
  wait
  for seed in 1 2 3 4 5 6 7 8 17; do
    echo "$tag seed $seed: $(grep '^balanced_1' $OUT/w/${tag}_$seed.txt | sed -E 's/.*\(theory [0-9.]+, ([-+0-9.%]+)\), loss\/period ([0-9.%]+).*energy gain max ([0-9.]+) .*/period \1 loss \2 gain \3/')"
  done
done
cd $OUT && tar czf w.tgz w && rm -rf w
