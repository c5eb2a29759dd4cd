#!/usr/bin/env bash
# dam_break_10m's column in a domain four times larger in x and z, aged (frames 151-190), with
# main at dedc34e (G2P's lone-particle rule), as measured before it at 8a42f22
# (../2026-12-06-h100-large-world-scenes/). build-dev/main/ holds main's library.
source scripts/device_env.sh
scene=docs/bench/2026-12-06-h100-large-world-scenes/dam_break_10m_wide.json
for preset in fast balanced; do
  LD_LIBRARY_PATH=$PWD/build-dev/main:$LD_LIBRARY_PATH build-dev/pf_bench --gpu-timing step --warmup 150 --steps 40 \
    --preset $preset $scene > $OUT/dam_break_10m_wide_$preset.txt 2>&1
  grep -E "wall .*median|solver:|raised flags|^dam_break_10m_wide " $OUT/dam_break_10m_wide_$preset.txt
done
