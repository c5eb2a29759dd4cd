#!/usr/bin/env bash
# Builds pflip and runs the whole test suite (GoogleTest on Mesa llvmpipe through EGL
# surfaceless when there is no GPU, plus glslangValidator on every shader permutation).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)" "$@"
