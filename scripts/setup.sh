#!/usr/bin/env bash
# Installs everything pflip needs on a fresh Debian 12 machine: build tools (and clang with its
# libFuzzer runtime), GL/EGL (Mesa llvmpipe runs every test without a GPU), GoogleTest,
# glslang, GLM, stb, nlohmann-json,
# and glad2 (pinned) in a virtual environment at .venv. Safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build pkg-config python3 python3-venv python3-pip
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri mesa-utils
  libgtest-dev glslang-tools libglm-dev libstb-dev nlohmann-json3-dev libcli11-dev
  libglfw3-dev libimgui-dev xvfb xauth ffmpeg
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

if [ ! -x .venv/bin/python ] || ! .venv/bin/python -c 'import glad' 2>/dev/null; then
  python3 -m venv .venv
  .venv/bin/python -m pip install -q --disable-pip-version-check glad2==2.0.8
fi
echo "setup: ok"
