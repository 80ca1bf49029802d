#!/usr/bin/env bash
# Configure and build bezierpde into ./build (Release) after installing what is missing.
# Usage: scripts/build.sh [cmake --build targets...]
# Builds for this machine (-DBPDE_NATIVE=ON: -march=native, docs/performance.md) unless
# BPDE_NATIVE=OFF is set in the environment; packagers configure without it (CMake's default is
# OFF, portable code).
# Builds the bpde_* libraries as shared libraries (-DBUILD_SHARED_LIBS=ON: bpde, the tests, the
# examples and the Python module link build/libbpde_*.so) unless BPDE_SHARED_LIBS=OFF is set;
# scripts/test.sh runs this script, so both configure build/ the same way (native and shared by
# default, the same environment switches) and neither rebuilds the other's tree. CMake's
# own default (a plain `cmake -S . -B build`) is static archives (README, "Library use").
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
JOBS=${BPDE_JOBS:-$(nproc)}
# The Python module's interpreter (python/CMakeLists.txt, README "Python"): Python_EXECUTABLE from
# the environment when set; else the python3 on PATH when it imports numpy; else the system's
# /usr/bin/python3, which install_deps.sh gave numpy (a pyenv or venv python3 without numpy has no
# way to get it here: no PyPI), said in one line. CMake itself, configured by hand, fails instead.
PY_ARGS=()
if [ -n "${Python_EXECUTABLE:-}" ]; then
  PY_ARGS=(-DPython_EXECUTABLE="$Python_EXECUTABLE")
elif ! python3 -c 'import numpy' >/dev/null 2>&1 && /usr/bin/python3 -c 'import numpy' >/dev/null 2>&1; then
  echo "build.sh: $(command -v python3 || echo python3) cannot import numpy; the Python module is built for /usr/bin/python3 (run it with /usr/bin/python3, or set Python_EXECUTABLE)" >&2
  PY_ARGS=(-DPython_EXECUTABLE=/usr/bin/python3)
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DBPDE_NATIVE=${BPDE_NATIVE:-ON} -DBUILD_SHARED_LIBS=${BPDE_SHARED_LIBS:-ON} "${PY_ARGS[@]}" ${BPDE_CMAKE_ARGS:-} >/dev/null
if [ $# -gt 0 ]; then
  cmake --build build -j "$JOBS" --target "$@"
else
  cmake --build build -j "$JOBS"
fi
