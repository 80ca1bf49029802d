#!/usr/bin/env bash
# The main job on a built-in default: installs what is missing, builds bpde, runs `bpde demo`.
# Output goes to out/demo (or the directory given as $1).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh bpde
./build/bpde demo --out "${1:-out/demo}"
