#!/usr/bin/env bash
# The pressure-solver sweep recorded in docs/accuracy.md: every solver on the dam breaks at a
# relative-residual tolerance of 1e-4, with and without separation, plus the original's 40
# Jacobi sweeps. Usage: scripts/bench_solvers.sh OUTDIR [BIN_DIR]  (on the GPU machine, after
# `source scripts/device_env.sh`; BIN_DIR defaults to build-dev).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: bench_solvers.sh OUTDIR [BIN_DIR]}
bin=${2:-build-dev}
mkdir -p "$out"
export PF_SCENES_DIR="$PWD/samples/scenes"
run() {  # name, then pf_bench arguments
  local name=$1; shift
  "$bin/pf_bench" --warmup 20 --steps 60 --json "$out/$name.json" "$@" > "$out/$name.log" 2>&1 || echo "FAILED: $name"
  grep -E "solver:|wall .* ms/step" "$out/$name.log" | sed "s/^/$name: /"
}
if [ "${QUICK:-0}" = 1 ]; then  # the main points only
  run dam_break_1m_jacobi40 dam_break_1m --solver jacobi --pressure-iterations 40
  for sep in 0 1; do
    run dam_break_1m_mgpcg_sep$sep dam_break_1m --solver mgpcg --tolerance 1e-4 --pressure-iterations 40 --separation $sep
    run dam_break_10m_mgpcg_sep$sep dam_break_10m --solver mgpcg --tolerance 1e-4 --pressure-iterations 40 --separation $sep --steps 30
  done
  run dam_break_1m_pcg_sep0 dam_break_1m --solver pcg --tolerance 1e-4 --pressure-iterations 400 --separation 0
  exit 0
fi
if [ "${P2G:-0}" = 1 ]; then  # the particle-to-grid schemes on the benchmark scenes
  for scheme in fixed float gather; do
    run original_24_p2g_$scheme original_24 --p2g $scheme
    run dam_break_1m_p2g_$scheme dam_break_1m --p2g $scheme
    run dam_break_10m_p2g_$scheme dam_break_10m --p2g $scheme --steps 30
  done
  exit 0
fi
if [ "${PRESETS:-0}" = 1 ]; then  # the presets on the benchmark scenes (150 frames of the 10m one)
  for q in fast balanced accurate; do
    run dam_break_1m_$q dam_break_1m --preset $q
    run dam_break_10m_$q dam_break_10m --preset $q --warmup 0 --steps 150
  done
  exit 0
fi
for scene in dam_break_1m; do
  run "${scene}_jacobi40" "$scene" --solver jacobi --pressure-iterations 40
  for sep in 1 0; do
    run "${scene}_jacobi_tol_sep$sep" "$scene" --solver jacobi --tolerance 1e-4 --pressure-iterations 2000 --separation $sep
    run "${scene}_rbgs_sep$sep" "$scene" --solver rbgs --tolerance 1e-4 --pressure-iterations 1000 --separation $sep
    run "${scene}_pcg_sep$sep" "$scene" --solver pcg --tolerance 1e-4 --pressure-iterations 400 --separation $sep
    run "${scene}_mgpcg_sep$sep" "$scene" --solver mgpcg --tolerance 1e-4 --pressure-iterations 40 --separation $sep
  done
done
run dam_break_10m_jacobi40 dam_break_10m --solver jacobi --pressure-iterations 40 --steps 30
run dam_break_10m_mgpcg_sep0 dam_break_10m --solver mgpcg --tolerance 1e-4 --pressure-iterations 40 --separation 0 --steps 30
run dam_break_10m_mgpcg_sep1 dam_break_10m --solver mgpcg --tolerance 1e-4 --pressure-iterations 40 --separation 1 --steps 30
