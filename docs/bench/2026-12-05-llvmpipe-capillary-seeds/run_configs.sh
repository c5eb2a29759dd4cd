#!/usr/bin/env bash
# Runs SurfaceTension.CapillaryWaveHasTheTheoreticalFrequency (patched by seed_study.diff) per
# lattice seed and configuration against one library: $1 = the library's folder, $2 = label.
lib=$1; label=$2
one() { env "$@" LD_LIBRARY_PATH=$lib LP_NUM_THREADS=1 ./tests/pf_engine_tests --gtest_filter=SurfaceTension.CapillaryWaveHasTheTheoreticalFrequency 2>&1 | grep -E "^capillary|^period-av" | tr '\n' ' '; echo; }
export -f one; export lib
for cfg in "XAPIC=1" "XAPIC=1 XVC=0" "XFLIP=0.8" "XMC=1"; do
  for s in 1 2 3 4 5 6 7 8; do echo "$cfg XSEED=$s"; done | xargs -P 2 -I{} bash -c 'echo "{} $(one {})"'
done | sed "s|^|$label |"
