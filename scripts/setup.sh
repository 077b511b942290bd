#!/usr/bin/env bash
# Install Granule's build dependencies from Debian 12 packages (as root) and build the release
# preset.  Safe to run repeatedly.  Usage: bash scripts/setup.sh [preset]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
packages=(cmake ninja-build g++ libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev
          libtomlplusplus-dev nlohmann-json3-dev libxxhash-dev libfmt-dev libhdf5-dev hdf5-tools libeigen3-dev libboost-dev
          python3-h5py python3-numpy python3-scipy python3-matplotlib pkg-config libcairo2-dev
          ffmpeg python3-vtk9 libopenmpi-dev openmpi-bin pybind11-dev python3-pybind11 python3-dev python3-gsd
          python3-pytest)
missing=()
for p in "${packages[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if ((${#missing[@]})); then
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get -o DPkg::Lock::Timeout=600 install -y -qq "${missing[@]}" >/dev/null
fi
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset"
