#!/usr/bin/env bash
# Installs every Debian 12 package bezierpde needs, and nothing that is already there.
# Idempotent: a second run installs nothing. Needs root (or sudo) only when something is missing.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev          # Eigen 3.4
  libceres-dev           # Ceres 2.1
  libnlopt-dev libnlopt-cxx-dev   # NLopt 2.7 (C++ header nlopt.hpp)
  libcgal-dev libgmp-dev libmpfr-dev  # CGAL 5.5
  libgtest-dev libgmock-dev  # GoogleTest
  libbenchmark-dev       # Google Benchmark
  nlohmann-json3-dev     # JSON
  libcli11-dev           # command line
  python3-dev pybind11-dev python3-pybind11  # the Python module bezierpde (build/python)
  python3-numpy python3-pytest               # its arrays and its tests
  python3-distributed python3-pandas         # bezierpde.sweep on Dask; its table as a DataFrame
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install_deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "install_deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
