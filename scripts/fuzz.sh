#!/usr/bin/env bash
# The libFuzzer targets of fuzz/ (net, job, blend, boundary-curve and sweep readers; docs/robustness.md).
#   bash scripts/fuzz.sh [RUNS]     (default 1000000 inputs per target; CI runs 20000)
# Builds fuzz/ with clang in ./build-fuzz (ASan + UBSan + libFuzzer, only the reader sources),
# then runs each target for RUNS inputs from its seeds: fuzz/corpus/<target> (every JSON file of
# examples/ and hostile cases) and fuzz/regressions/<target> (inputs that once crashed). New
# inputs go to build-fuzz/corpus/<target>; a crash stops the script with a non-zero status and
# leaves the input as build-fuzz/crash-<target>-*: add it to fuzz/regressions/<target>/ (replayed by
# the ctest test fuzz_regressions_<target>) once fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS="${1:-1000000}"
CXX_FUZZ="${CXX_FUZZ:-clang++}"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S fuzz -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER="$CXX_FUZZ" "${launcher[@]}" >/dev/null
cmake --build build-fuzz -j "$(nproc)"
for t in net job blend curve sweep; do
  mkdir -p "build-fuzz/corpus/$t"
  start=$(date +%s)
  # -max_len: the seeds include 100000-level nestings (200 kB); 2 MB leaves room to grow them.
  # -rss_limit_mb / -timeout: a reader that needs more than 2 GB or 10 s for one input is a finding.
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    "build-fuzz/fuzz_$t" -runs="$RUNS" -max_len=2097152 -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
    -artifact_prefix="build-fuzz/crash-$t-" "build-fuzz/corpus/$t" "fuzz/corpus/$t" "fuzz/regressions/$t" \
    2>"build-fuzz/fuzz_$t.log" || { tail -40 "build-fuzz/fuzz_$t.log"; echo "fuzz: $t FAILED"; exit 1; }
  echo "fuzz: $t: $RUNS inputs, $(($(date +%s) - start)) s, no finding" \
    "($(grep -o 'stat::number_of_executed_units: *[0-9]*' "build-fuzz/fuzz_$t.log" | grep -o '[0-9]*$') executed)"
done
