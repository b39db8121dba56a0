#!/usr/bin/env bash
# Installs what is missing (Debian 12 packages, as root) and builds seaflex into build/.
# Usage: scripts/setup.sh [cmake preset, default "release"]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"

packages=(build-essential cmake ninja-build pkg-config git python3 clang-format
          libeigen3-dev libsuitesparse-dev libyaml-cpp-dev libcli11-dev libfmt-dev
          libgtest-dev libgmock-dev libbenchmark-dev python3-matplotlib libhdf5-dev python3-h5py
          python3-vtk9 clang libclang-rt-14-dev
          pybind11-dev python3-dev python3-numpy python3-pandas python3-distributed python3-pytest
          python3-scipy)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  if [ "$(id -u)" -ne 0 ]; then sudo=sudo; else sudo=; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
