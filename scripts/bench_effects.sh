#!/usr/bin/env bash
# The effects' cost sweep recorded in docs/effects.md: a scene's core step, then the same scene
# with each effect on alone and all together (pf_bench --features; the scene's objects are
# added in every run, an effect that is off dispatches nothing). Usage:
#   scripts/bench_effects.sh OUTDIR [BIN_DIR] [SCENE]   (BIN_DIR defaults to build/samples,
#   SCENE to dam_break_1m_effects; on the GPU machine BIN_DIR=build-dev after
#   `source scripts/device_env.sh`). STEPS / WARMUP override the measured and unmeasured steps.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: bench_effects.sh OUTDIR [BIN_DIR] [SCENE]}
bin=${2:-build/samples}
scene=${3:-dam_break_1m_effects}
mkdir -p "$out"
export PF_SCENES_DIR="$PWD/samples/scenes"
for f in none force_fields obstacles emitters sinks domain_motion all; do
  "$bin/pf_bench" --warmup "${WARMUP:-20}" --steps "${STEPS:-60}" --features "$f" --json "$out/${scene}_$f.json" \
    "$scene" > "$out/${scene}_$f.log" 2>&1 || echo "FAILED: $f"
  grep -E "wall .* ms/step|gpu .* ms" "$out/${scene}_$f.log" | head -3 | sed "s/^/$f: /"
done
