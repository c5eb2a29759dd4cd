#!/usr/bin/env bash
# The pf_accuracy knob sweep one configuration per process, each writing its own JSON, so a
# run cut short by the GPU machine's time limit keeps every configuration it finished.
# usage: scripts/sweep_accuracy.sh CELLS OUTDIR SECONDS CONFIG...
#   SECONDS: start no new configuration after this many seconds.
# Merge the files for scripts/plot_accuracy.py with scripts/merge_accuracy.py.
set -uo pipefail
cells=$1 out=$2 budget=$3
shift 3
bin=${PF_ACCURACY:-build-dev/pf_accuracy}
mkdir -p "$out"
start=$SECONDS
for c in "$@"; do
  if (( SECONDS - start > budget )); then
    echo "not run (time): $c" | tee -a "$out/skipped.txt"
    continue
  fi
  "$bin" --cells "$cells" --config "$c" --json "$out/${cells}_$c.json" > "$out/${cells}_$c.log" 2>&1 ||
    echo "failed: $c (rc $?)" | tee -a "$out/failed.txt"
done
