#!/usr/bin/env bash
# Installs cortex's build dependencies from Debian 12 packages and builds it (Release)
# into build/. Safe to run again. Uses sudo when not run as root.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config
          libeigen3-dev libtomlplusplus-dev libcli11-dev libfmt-dev libspdlog-dev
          libhdf5-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev
          librandom123-dev libsuitesparse-dev python3-numpy python3-h5py python3-matplotlib
          python3-paraview xvfb xauth ffmpeg openmpi-bin libopenmpi-dev)
missing=()
for p in "${packages[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
