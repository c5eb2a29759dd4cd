#!/usr/bin/env bash
# Configures and builds pflip into build/ (Release with debug info, Ninja). Arguments go to the
# configure step, except `--target NAME` (repeatable), which builds only NAME and what it links
# instead of every target.
set -euo pipefail
cd "$(dirname "$0")/.."
configure=() targets=()
while (($#)); do
  case "$1" in
    --target) targets+=(--target "$2"); shift 2 ;;
    *) configure+=("$1"); shift ;;
  esac
done
cmake -S . -B build -G Ninja -DPython3_EXECUTABLE="$PWD/.venv/bin/python" "${configure[@]}" >/dev/null
cmake --build build "${targets[@]}"
