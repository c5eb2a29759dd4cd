#!/bin/bash
# The capillary wave of tests/engine/test_surface_tension.cpp at several substep counts, Euler (XADV=0)
# and leapfrog (XADV=3), from a scratch build of main with scratch_knobs.diff (XDT caps the substep, s;
# XFR sets flip_ratio; XCFL 8 as in the candidate default; XCORR=1: leapfrog's correction once per 1/60 s).
cd /tmp/wt/build
run() { echo "== $*"; env "$@" LP_NUM_THREADS=0 ./tests/pf_engine_tests --gtest_filter='SurfaceTension.CapillaryWave*' 2>&1 | grep "capillary wave:"; }
for adv in 0 3; do
  run XADV=$adv XCFL=8
  for dt in 0.00065 0.00055 0.00045 0.0003; do run XADV=$adv XCFL=8 XDT=$dt; done
done
run XADV=3 XCFL=8 XCORR=1
run XADV=3 XCFL=8 XVC=0
run XADV=0 XCFL=8 XVC=0
for dt in 0.00072 0.00055 0.00045; do run XADV=0 XCFL=8 XFR=1 XDT=$dt; done
