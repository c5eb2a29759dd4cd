#!/usr/bin/env bash
# Sourced first by every command on the GPU machine (../shared/device/README.md): installs the
# carried GL/EGL dispatch libraries and points EGL at NVIDIA's driver.
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[ -f build-dev/runtime-libs.tar.gz ] && tar -C build-dev -xzf build-dev/runtime-libs.tar.gz  # scripts/pack_device.sh
export LD_LIBRARY_PATH="$PWD/build-dev${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
