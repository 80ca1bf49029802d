#!/usr/bin/env bash
# Installs every Debian 12 package bezierpde needs, and nothing that is already there, then the
# viewer's npm packages (three.js and esbuild, pinned by viewer/package-lock.json) when missing.
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
  python3 python3-jsonschema  # tests/schema: the JSON Schemas of docs/schema/
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libocct-data-exchange-dev
                         # OpenCASCADE 7.6: STEP export (io/step_export.cpp)
  libtbb-dev             # OpenCASCADE's CMake targets link /usr/lib/x86_64-linux-gnu/libtbb.so and
                         # libtbbmalloc.so, which only libtbb-dev provides (its -dev packages do not depend on it)
  chromium               # the browser test of view.html (headless)
  zlib1g-dev             # the browser test decodes Chromium's PNG screenshot
  libsuitesparse-dev     # CHOLMOD: sparse Cholesky of the blend system
  clang libclang-rt-14-dev  # libFuzzer + ASan/UBSan runtimes for the fuzz targets (fuzz/, scripts/fuzz.sh)
  python3-dev pybind11-dev python3-pybind11  # the Python module bezierpde (build/python)
  python3-numpy python3-pytest               # its arrays and its tests
  python3-distributed python3-pandas         # bezierpde.sweep on Dask; its table as a DataFrame
  python3-matplotlib                         # the example READMEs' figures (bezierpde.figures, scripts/figures.sh)
  evolver-nox            # Surface Evolver, for scripts/evolver_compare.py only (docs/cmc_evolver.md; no test runs it)
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
# view.html: three.js and esbuild from the npm registry (viewer/). Debian's npm, unless an npm
# (e.g. one that came with another Node.js) is already on the PATH.
if ! command -v npm >/dev/null 2>&1; then missing+=(npm); fi

if ((${#missing[@]} == 0)); then
  echo "install_deps: all packages present"
else
  echo "install_deps: installing ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

viewer="$(dirname "$0")/../viewer"
if [ ! -f "$viewer/node_modules/three/package.json" ] || [ ! -x "$viewer/node_modules/.bin/esbuild" ]; then
  echo "install_deps: npm ci in viewer/ (three.js, esbuild)"
  (cd "$viewer" && npm ci --no-audit --no-fund)
fi
