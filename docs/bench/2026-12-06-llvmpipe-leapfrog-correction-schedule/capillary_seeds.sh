#!/usr/bin/env bash
# $1 label, rest: env settings; runs seeds 1-8, two at a time
label=$1; shift
one() { env $CFG XSEED=$1 LP_NUM_THREADS=0 /tmp/wt/build/tests/pf_engine_tests --gtest_filter=SurfaceTension.CapillaryWaveHasTheTheoreticalFrequency 2>&1 | grep -E "^capillary|^period-av" | tr '\n' ' '; echo; }
export -f one; export CFG="$*"
for s in 1 2 3 4 5 6 7 8; do echo $s; done | xargs -P 2 -I{} bash -c 'echo "seed {} $(one {})"' | sed "s|^|$label |"
