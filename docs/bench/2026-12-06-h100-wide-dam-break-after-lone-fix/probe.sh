#!/usr/bin/env bash
# The wide dam break's speeds under both presets: the five fastest particles every 10 frames and
# how many particles share each one's cell (lone_probe.cpp, a scratch tool), main's library.
source scripts/device_env.sh
scene=docs/bench/2026-12-06-h100-large-world-scenes/dam_break_10m_wide.json
for preset in fast balanced; do
  limit=150; [ $preset = balanced ] && limit=200
  PROBE_PRESET=$preset PROBE_FROM=10 PROBE_EVERY=10 LD_LIBRARY_PATH=$PWD/build-dev/main:$LD_LIBRARY_PATH \
    timeout $limit build-dev/lone_probe $scene 190 save 0 x > $OUT/probe_$preset.txt 2> $OUT/probe_${preset}_log.txt
  echo "== $preset"; cut -c1-330 $OUT/probe_$preset.txt
done
