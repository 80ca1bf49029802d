#!/usr/bin/env bash
# Regenerate the PNG figures of the example READMEs: runs examples/<EXAMPLE>/figures.py (every
# example, or the ones named) with the Python module of ./build (bezierpde.figures, matplotlib's
# headless Agg backend), after building the module, the command, the benchmarks and the example
# programs whose tables the figures plot. Each script writes its PNGs, and an SVG beside each,
# beside its README.
# Usage: bash scripts/figures.sh [EXAMPLE ...]      e.g. bash scripts/figures.sh 004-cmc-circle
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -f build/CMakeCache.txt ]; then bash scripts/build.sh bpde; fi
targets=$(ls examples/*/main.cpp | sed -E 's|examples/([^/]*)/main.cpp|example_\1|; s|[^A-Za-z0-9_]|_|g')
cmake --build build -j "${BPDE_JOBS:-$(nproc)}" --target bpde bpde_python bpde_bench $targets
# The interpreter the module was built for (python/CMakeLists.txt), which has numpy and matplotlib.
PY=$(sed -n 's/^Python_EXECUTABLE:FILEPATH=//p' build/CMakeCache.txt)
PY=${PY:-/usr/bin/python3}
if [ $# -gt 0 ]; then examples=("$@"); else examples=($(ls examples/*/figures.py | sed -E 's|examples/([^/]*)/figures.py|\1|')); fi
for e in "${examples[@]}"; do
  e=${e%/}; e=${e#examples/}
  echo "figures: $e"
  PYTHONPATH="$PWD/build/python" BPDE_BUILD_DIR="$PWD/build" BPDE_SOURCE_DIR="$PWD" "$PY" "examples/$e/figures.py"
done
