#!/usr/bin/env bash
# Builds pflip and runs the headless demo: a dam break rendered to PNGs in out/demo/
# (NVIDIA GPU through EGL when present, Mesa llvmpipe otherwise).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
build/samples/pf_headless --out out/demo "$@"
