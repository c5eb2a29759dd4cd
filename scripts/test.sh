#!/usr/bin/env bash
# Builds pflip and runs the whole test suite (GoogleTest on Mesa llvmpipe through EGL
# surfaceless when there is no GPU, plus glslangValidator on every shader permutation), then
# the sanitizer stage (ASan + UBSan build in build-asan/) and the scene-loader libFuzzer stage
# (clang, build-fuzz/). Arguments go to the first ctest run only.
set -euo pipefail
cd "$(dirname "$0")/.."
# ctest runs one test per core, so llvmpipe gets one thread per test instead of one per core
# each (the README's Tests section says what that saves). GPU drivers ignore it.
export LP_NUM_THREADS="${LP_NUM_THREADS:-1}"
stage() {  # runs one stage and says how long it took (CI time is budgeted per stage)
  local start=$SECONDS
  "$@"
  echo "test.sh: stage '$*' took $((SECONDS - start)) s"
}
main_tree() { scripts/build.sh && (cd build && ctest --output-on-failure -j"$(nproc)" "$@"); }
stage main_tree "$@"
stage scripts/test_sanitizers.sh
stage scripts/test_fuzz.sh
