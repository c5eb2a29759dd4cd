#!/usr/bin/env bash
# Copies what a run on the GPU machine needs into build-dev/ (stripped, under the 64 MiB the
# device tool carries): the benchmark tools, the test binaries and libpflip, and, compressed, the
# shared libraries the OpenVDB export needs that the GPU machine lacks (scripts/device_env.sh
# unpacks them there).
set -euo pipefail
cd "$(dirname "$0")/.."
rm -rf build-dev && mkdir -p build-dev
# The binaries load libpflip by its SONAME (cmake/version.cmake: libpflip.so.0.<minor> before 1.0).
soname=$(readelf -d build/libpflip.so | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
cp -L "build/libpflip.so" "build-dev/$soname"
for t in samples/pf_bench samples/pf_render_bench samples/pf_surface_bench samples/pf_headless samples/pf_vdb_check samples/pf_load_time \
         samples/pf_accuracy samples/pf_validation tests/pf_internal_tests tests/pf_engine_tests \
         tests/pf_stability_tests; do
  [ -f "build/$t" ] && cp "build/$t" build-dev/
done
strip --strip-debug build-dev/*
# OpenVDB and what it loads (libopenvdb alone is 57 MB, 8 MB compressed), minus what every
# Linux has.
libs=$(ldd build/samples/pf_headless | awk '/=> \// {print $3}' |
       grep -E 'openvdb|Imath|tbb|log4cplus|blosc|boost|snappy|lz4|zstd' || true)
if [ -n "$libs" ]; then
  mkdir -p build-dev/runtime && cp -L $libs build-dev/runtime/
  tar -C build-dev/runtime -czf build-dev/runtime-libs.tar.gz . && rm -rf build-dev/runtime
fi
du -sh build-dev
