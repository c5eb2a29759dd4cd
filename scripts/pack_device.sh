#!/usr/bin/env bash
# Copies what a run on the GPU machine needs into build-dev/ (stripped, under the 64 MiB the
# device tool carries): the benchmark tools, the test binaries and libpflip.
set -euo pipefail
cd "$(dirname "$0")/.."
rm -rf build-dev && mkdir -p build-dev
cp build/libpflip.so.0 build-dev/
for t in samples/pf_bench samples/pf_headless samples/pf_accuracy tests/pf_internal_tests tests/pf_engine_tests; do
  [ -f "build/$t" ] && cp "build/$t" build-dev/
done
strip --strip-debug build-dev/*
du -sh build-dev
