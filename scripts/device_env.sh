#!/usr/bin/env bash
# Sourced first by every command on the GPU machine (../shared/device/README.md): installs the
# carried GL/EGL dispatch libraries and points EGL at NVIDIA's driver.
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
export LD_LIBRARY_PATH="$PWD/build-dev${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
