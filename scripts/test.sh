#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds everything (library, bpde, tests,
# benchmarks, examples, the Python module) and runs every test with CTest: the GoogleTest
# programs, the pytest files of python/tests (Python.*) and the package test (Package.consumer:
# install into a temporary prefix, build an outside project from the README's snippets).
# With BPDE_SANITIZE=1 it then builds and runs the same suite under AddressSanitizer and
# UndefinedBehaviorSanitizer (the `asan` preset of CMakePresets.json, in ./build-asan). That pass
# doubles the time on a 2-core machine, so CI leaves it to this switch.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
if [ "${BPDE_SANITIZE:-0}" = "1" ]; then
  cmake --preset asan >/dev/null
  cmake --build --preset asan -j "$(nproc)"
  ctest --preset asan -j "$(nproc)"
fi
