#!/usr/bin/env bash
# Copies what a run on the GPU machine needs into build-dev/ (stripped, under the 64 MiB the
# device tool carries): the benchmark tools, the test binaries and libpflip.
set -euo pipefail
cd "$(dirname "$0")/.."
rm -rf build-dev && mkdir -p build-dev
# The binaries load libpflip by its SONAME (cmake/version.cmake: libpflip.so.0.<minor> before 1.0).
soname=$(readelf -d build/libpflip.so | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
cp -L "build/libpflip.so" "build-dev/$soname"
for t in samples/pf_bench samples/pf_headless samples/pf_accuracy samples/pf_validation tests/pf_internal_tests tests/pf_engine_tests \
         tests/pf_stability_tests; do
  [ -f "build/$t" ] && cp "build/$t" build-dev/
done
strip --strip-debug build-dev/*
du -sh build-dev
