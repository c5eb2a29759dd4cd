#!/usr/bin/env bash
# The sweep behind docs/accuracy.md "Measured, not changed: what the Runge-Kutta traces sample"
# (README.md here): trace_sampling.diff applied to main, each PF_TRACE_SAMPLING variant built in
# turn, Martin & Moyce n^2 = 2 at 16 cells and the stability suite's large-step dam break.
set -euo pipefail
cd "$(dirname "$0")/../../.."
D=docs/bench/2026-12-04-llvmpipe-trace-sampling
export LP_NUM_THREADS=2
for v in 0 1 2 3 4; do
  sed -i "s/^#define PF_TRACE_SAMPLING [0-9]/#define PF_TRACE_SAMPLING $v/" shaders/sim/advect_rk.comp
  ninja -C build pflip pf_validation pf_stability_tests > /dev/null
  for run in "rk2 1" "rk2_offset 1" "rk2_offset 2" "rk2_offset 4"; do
    set -- $run
    build/samples/pf_validation --cells 16 --preset balanced --case martin_moyce_2 --advection $1 --cfl $2 \
      --json $D/v${v}_$1_cfl$2.json > $D/v${v}_$1_cfl$2.txt 2>&1
  done
  build/tests/pf_stability_tests --gtest_filter='Presets/LargeSteps.DamBreakAtHalfSecondFramesWithEnoughSubsteps/fast' \
    > $D/v${v}_large_steps_fast.txt 2>&1 || true
done
# The fast preset at CFL 3.5 (src/api/pf_api.cpp edited for the run) and the traces' rotation test.
sed -i 's/            p.cfl = 3.0f;/            p.cfl = 3.5f;/' src/api/pf_api.cpp
for v in 0 1 3; do
  sed -i "s/^#define PF_TRACE_SAMPLING [0-9]/#define PF_TRACE_SAMPLING $v/" shaders/sim/advect_rk.comp
  ninja -C build pflip pf_stability_tests pf_internal_tests > /dev/null
  build/tests/pf_stability_tests --gtest_filter='Presets/LargeSteps.DamBreakAtHalfSecondFramesWithEnoughSubsteps/fast' \
    > $D/v${v}_large_steps_fast_cfl3.5.txt 2>&1 || true
  build/tests/pf_internal_tests --gtest_filter='AdvectionSchemes.*' > $D/v${v}_rotation.txt 2>&1 || true
done
sed -i 's/            p.cfl = 3.5f;/            p.cfl = 3.0f;/' src/api/pf_api.cpp
sed -i "s/^#define PF_TRACE_SAMPLING [0-9]/#define PF_TRACE_SAMPLING 0/" shaders/sim/advect_rk.comp
