#!/usr/bin/env bash
# Regenerate every generated section of the docs (the tables between `<!-- generated: NAME -->`
# and `<!-- end -->` in examples/*/README.md and docs/*.md) from the example programs' output.
# Builds the example programs first. `bash scripts/docs.sh --check` changes nothing and fails when
# a section is stale (the CTest test Docs.GeneratedSectionsMatchTheExamples runs that check).
# `bash scripts/docs.sh --full` also regenerates the heavy sections (names ending in "-full", e.g.
# the area tables of docs/cmc_measurements.md from example_004_cmc_area_tables --full; minutes), which the check
# leaves alone.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -d build ]; then bash scripts/build.sh; fi
targets=$(ls examples/*/main.cpp | sed -E 's|examples/([^/]*)/main.cpp|example_\1|; s|[^A-Za-z0-9_]|_|g')
cmake --build build -j "$(nproc)" --target $targets
python3 scripts/docs.py --build "$PWD/build" "$@"
