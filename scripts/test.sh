#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds everything (library, bpde, tests,
# benchmarks, examples, the Python module) and runs every test with CTest: the GoogleTest
# programs, the pytest files of python/tests (Python.*) and the package test (Package.consumer:
# install into a temporary prefix, build an outside project from the README's snippets); then it
# builds and runs the fuzz targets briefly.
# The suite runs on the shared-library build of scripts/build.sh (BPDE_SHARED_LIBS=ON, its
# default): Package.consumer then installs the .so files and checks that the consumer and the
# installed bpde load them from the prefix. BPDE_SHARED_LIBS=OFF runs it on static archives.
# With BPDE_SANITIZE=1 it then builds and runs the same suite under AddressSanitizer and
# UndefinedBehaviorSanitizer (the `asan` preset of CMakePresets.json, in ./build-asan; no Python
# module there, docs/robustness.md "Sanitizer pass"). That pass costs more than the normal one, so CI
# leaves it to this switch.
set -euo pipefail
cd "$(dirname "$0")/.."
# The suite runs on build/ configured exactly as scripts/build.sh configures it (native,
# -march=native, unless BPDE_NATIVE=OFF; shared unless BPDE_SHARED_LIBS=OFF), so running one
# after the other rebuilds nothing. It passes on the native and on the portable build: its
# tolerances were measured on both (docs/performance_measurements.md, "Kernels").
bash scripts/build.sh
# Every tier: unit, integration and slow (tests/tiers.cmake). The inner loop while editing is
# `ctest --test-dir build -L unit -j2` (under 2 minutes on 2 cores); `-LE slow` adds the integration tests.
ctest --test-dir build --output-on-failure -j "$(nproc)"
# The libFuzzer targets of the readers (fuzz/, clang, ./build-fuzz): 20000 inputs each, failing on
# any crash or sanitizer report (docs/robustness.md; the long run is `bash scripts/fuzz.sh`).
bash scripts/fuzz.sh 20000
if [ "${BPDE_SANITIZE:-0}" = "1" ]; then
  cmake --preset asan >/dev/null
  cmake --build --preset asan -j "$(nproc)"
  ctest --preset asan -j "$(nproc)"
fi
