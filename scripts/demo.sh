#!/usr/bin/env bash
# Builds the headless demo (pf_headless and what it links, not the tests or the other tools) and
# runs it: a dam break rendered to PNGs in out/demo/ (NVIDIA GPU through EGL when present, Mesa
# llvmpipe otherwise). Arguments go to pf_headless (`build/samples/pf_headless --help`).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh --target pf_headless
build/samples/pf_headless --out out/demo "$@"
