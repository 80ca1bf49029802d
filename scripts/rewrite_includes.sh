#!/usr/bin/env bash
# Rewrites the #include lines of the library's own headers to the one include style of bezierpde:
#   #include "core/errors.h"  ->  #include "bezierpde/core/errors.h"
# for the library folders (core tensor triangular energies solvers boundaries io jobs checks), in
# every .h/.cpp/.cc/.md file of the repository (not build trees, not .git, not the outside project
# of tests/package/consumer, whose own core/errors.h must stay its own). app/, tests/, bench/ and
# examples/ are not installed, so their own headers ("app/commands.h", "tests/cli/cli_run.h") keep
# their paths. Idempotent: lines already in the bezierpde/ style are left alone, so it can be run
# again after a merge brings in files written in the old style.
#   bash scripts/rewrite_includes.sh          # rewrite in place, print the files changed
#   bash scripts/rewrite_includes.sh --check  # exit 1 if any file still uses the old style
set -euo pipefail
cd "$(dirname "$0")/.."
FOLDERS='core|tensor|triangular|energies|solvers|boundaries|io|jobs|checks'
PATTERN="^([[:space:]]*#[[:space:]]*include[[:space:]]*\")(${FOLDERS})/"
mapfile -t files < <(git ls-files -co --exclude-standard -- '*.h' '*.cpp' '*.cc' '*.md' | grep -v -e '^build' -e '^tests/package/consumer/' || true)
changed=0
for f in "${files[@]}"; do
  [ -f "$f" ] || continue
  if grep -Eq "$PATTERN" "$f"; then
    changed=$((changed + 1))
    if [ "${1:-}" = "--check" ]; then
      echo "old include style: $f"
    else
      sed -E -i "s@${PATTERN}@\\1bezierpde/\\2/@" "$f"
      echo "rewrote: $f"
    fi
  fi
done
if [ "${1:-}" = "--check" ] && [ "$changed" -gt 0 ]; then exit 1; fi
echo "rewrite_includes: ${changed} file(s) $([ "${1:-}" = "--check" ] && echo "in the old style" || echo "rewritten")"
