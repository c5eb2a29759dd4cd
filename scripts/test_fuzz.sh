#!/usr/bin/env bash
# libFuzzer stage: the samples' scene loader fuzzed (clang, -fsanitize=fuzzer,address,undefined)
# from the shipped scenes and tests/fuzz/corpus/scene/ for PF_FUZZ_MAX_TIME seconds (default
# 40, one fuzzing process per core, at most 4) in build-fuzz/. Only that target is built there,
# linking the main tree's build/libpflip.so where it exists (else the library, plain, with clang).
# Skipped, saying so, when clang or its libFuzzer runtime is missing (scripts/setup.sh installs
# both).
#   PF_FUZZ_MAX_TIME=3600 scripts/test_fuzz.sh                  # a longer run by hand
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang++ >/dev/null || ! command -v clang >/dev/null; then
  echo "test_fuzz: SKIPPED: clang is not installed (apt-get install clang libclang-rt-14-dev)"
  exit 0
fi
# The main tree's library when it has one (scripts/test.sh builds it first): the fuzzer calls
# only the C API, so the library need not be compiled again here.
pflip_lib=""
[ -f build/libpflip.so ] && pflip_lib="$PWD/build/libpflip.so"
cmake -S . -B build-fuzz -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
      -DCMAKE_BUILD_TYPE=Release -DPF_FUZZ_MAX_TIME="${PF_FUZZ_MAX_TIME:-40}" -DPF_FUZZ_PFLIP="$pflip_lib" \
      -DPython3_EXECUTABLE="$PWD/.venv/bin/python" >/dev/null
if ! grep -q '^PF_HAS_LIBFUZZER:INTERNAL=1' build-fuzz/CMakeCache.txt; then
  echo "test_fuzz: SKIPPED: clang cannot link -fsanitize=fuzzer (apt-get install libclang-rt-14-dev)"
  exit 0
fi
cmake --build build-fuzz --target pf_scene_fuzz
cd build-fuzz
ctest --output-on-failure -R '^fuzz\.scene$'
