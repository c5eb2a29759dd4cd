#!/usr/bin/env bash
# usage: cap.sh "ENV..." seeds...  -> one line per seed
cfg=$1; shift
one() { env $cfg XSEED=$1 LP_NUM_THREADS=1 /tmp/wtb/tests/pf_engine_tests --gtest_filter=SurfaceTension.CapillaryWaveHasTheTheoreticalFrequency 2>&1 | grep -E "^capillary|^period-av|OK \]|FAILED \]" | sed -E 's/capillary wave: a0 [0-9.]+ m, //; s/\(theory [0-9.]+, //; s/\[ +(OK|FAILED) +\].*/\1/' | tr '\n' ' '; echo; }
export -f one; export cfg
for s in "$@"; do echo $s; done | xargs -P 2 -I{} bash -c 'echo "$cfg seed {}: $(one {})"'
