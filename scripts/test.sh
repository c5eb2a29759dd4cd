#!/usr/bin/env bash
# Builds pflip and runs the whole test suite (GoogleTest on Mesa llvmpipe through EGL
# surfaceless when there is no GPU, plus glslangValidator on every shader permutation), then
# the sanitizer stage (ASan + UBSan build in build-asan/) and the scene-loader libFuzzer stage
# (clang, build-fuzz/). Arguments go to the first ctest run only.
#
# `scripts/test.sh --quick` is the contributors' loop: it builds only the library, the internal
# tests and the shader tooling, and runs the tests labelled "core" (every GPU pass against the
# double-precision CPU reference, glslangValidator on every shader permutation, the export
# check), in a few minutes; the full suite above is what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
# ctest runs one test per core, so llvmpipe runs each test's GL work on the test's own thread
# (0: no worker threads, which would wait for each other at every dispatch) instead of one
# thread per core each (docs/notes/2026-12-05-llvmpipe-threads-in-ci.md: what that saves). GPU drivers ignore it.
export LP_NUM_THREADS="${LP_NUM_THREADS:-0}"
stage() {  # runs one stage and says how long it took (CI time is budgeted per stage)
  local start=$SECONDS
  "$@"
  echo "test.sh: stage '$*' took $((SECONDS - start)) s"
}
if [ "${1:-}" = --quick ]; then
  shift
  scripts/build.sh --target pflip --target pf_internal_tests --target pf_shader_dump
  cd build && exec ctest -L core --output-on-failure -j"$(nproc)" "$@"
fi
# Line tables only (-g1; build/ keeps it in its cache until configured again): what a test's
# backtrace needs, and a third less compile time than -g on CI's 2 cores (samples/bench/validation.cpp
# 22.5 s at -O2 -g, 15.4 s at -O2 -g1, 2026-12-01). -O1: the tests' time is the GL driver's, not
# this code's, and a third less compile time again (samples/bench/main.cpp 17.6 s at -O2 -g1,
# 11.9 s at -O1 -g1, 2026-12-05); the floating-point results are the same (no -ffast-math, no FMA).
ci_flags="-O1 -g1 -DNDEBUG"
main_tree() {
  scripts/build.sh -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$ci_flags" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$ci_flags" &&
    (cd build && ctest --output-on-failure -j"$(nproc)" "$@")
}
stage main_tree "$@"
stage scripts/test_sanitizers.sh
stage scripts/test_fuzz.sh
