#!/usr/bin/env bash
# Installs everything pflip needs on a fresh Debian 12 machine: build tools (and clang with its
# libFuzzer runtime), GL/EGL (Mesa llvmpipe runs every test without a GPU), GoogleTest,
# glslang, GLM, stb, nlohmann-json, OpenVDB, and, pinned in a virtual environment at .venv,
# glad2 and the Python client's modules. Safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build pkg-config python3 python3-venv python3-pip
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri mesa-utils
  libgtest-dev glslang-tools libglm-dev libstb-dev nlohmann-json3-dev libcli11-dev
  libglfw3-dev libimgui-dev xvfb xauth ffmpeg
  doxygen  # the API reference, built by the docs.doxygen test with warnings as errors
  # the samples' OpenVDB export (.vdb); libopenvdb-dev's FindOpenVDB.cmake needs Boost.Iostreams'
  # headers, which that package does not pull in
  libopenvdb-dev libboost-iostreams-dev
  clang libclang-rt-14-dev  # the libFuzzer stage of scripts/test.sh (scripts/test_fuzz.sh)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# glad2 generates the GL loader at build time; the rest is the Python client's (python/): numpy,
# moderngl (its tests' GL context), pytest, Pillow (examples), setuptools (`pip install ./python`) and
# Panda3D (samples/engines/panda3d: pflip inside an engine it did not write, tested headless).
python_packages=(glad2==2.0.8 numpy==2.4.6 moderngl==5.13.0 glcontext==3.1.0 pytest==9.2.0 pillow==13.0.0
                 panda3d==1.10.16
                 "setuptools>=77")
[ -x .venv/bin/python ] || python3 -m venv .venv
# pip checks the installed versions against the pins and reaches the index only for what is missing.
.venv/bin/python -m pip install -q --disable-pip-version-check "${python_packages[@]}"
echo "setup: ok"
